; The Windows installer, made by scripts/build-windows.sh from its staged folder:
;   makensis -DVERSION=0.1.0 -DSTAGE=<staged folder> -DFILES=<files.nsh> -DUNFILES=<unfiles.nsh>
;            -DICON=<opentop.ico> -DOUTFILE=<OpenTOP-0.1.0-win64-setup.exe> opentop.nsi
; Installs for every user of the machine (Program Files, administrator), with Start-menu entries
; for OpenTOP and for a command prompt that has opentop-cli on its PATH. The uninstaller removes
; exactly the files the installer wrote (FILES and UNFILES list them), then the folders if they
; are empty, the shortcuts and the registry entries. /S installs and uninstalls silently.
; A 64-bit installer for a 64-bit program: it runs where there is no 32-bit Windows layer
; either (Wine without wine32).
Target amd64-unicode
!include "MUI2.nsh"
!include "x64.nsh"

!define APP "OpenTOP"
!define UNINSTALL_KEY "Software\Microsoft\Windows\CurrentVersion\Uninstall\${APP}"

Name "${APP} ${VERSION}"
OutFile "${OUTFILE}"
InstallDir "$PROGRAMFILES64\${APP}"
InstallDirRegKey HKLM "${UNINSTALL_KEY}" "InstallLocation"
RequestExecutionLevel admin
SetCompressor /SOLID lzma
BrandingText "${APP} ${VERSION}"
VIProductVersion "${VERSION}.0"
VIAddVersionKey "ProductName" "${APP}"
VIAddVersionKey "ProductVersion" "${VERSION}"
VIAddVersionKey "FileVersion" "${VERSION}"
VIAddVersionKey "FileDescription" "${APP} ${VERSION} setup"
VIAddVersionKey "CompanyName" "OpenTOP developers"
VIAddVersionKey "LegalCopyright" "OpenTOP developers"

!define MUI_ICON "${ICON}"
!define MUI_UNICON "${ICON}"
!define MUI_FINISHPAGE_RUN "$INSTDIR\opentop.exe"
!insertmacro MUI_PAGE_DIRECTORY
!insertmacro MUI_PAGE_INSTFILES
!insertmacro MUI_PAGE_FINISH
!insertmacro MUI_UNPAGE_CONFIRM
!insertmacro MUI_UNPAGE_INSTFILES
!insertmacro MUI_LANGUAGE "English"

Function .onInit
    ${IfNot} ${RunningX64}
        MessageBox MB_ICONSTOP|MB_OK "${APP} needs a 64-bit Windows." /SD IDOK
        Abort
    ${EndIf}
    SetRegView 64
FunctionEnd

Function un.onInit
    SetRegView 64
FunctionEnd

Section "${APP}"
    SetShellVarContext all
    !include "${FILES}"
    WriteUninstaller "$INSTDIR\uninstall.exe"

    CreateDirectory "$SMPROGRAMS\${APP}"
    CreateShortcut "$SMPROGRAMS\${APP}\${APP}.lnk" "$INSTDIR\opentop.exe" "" \
        "$INSTDIR\opentop.exe" 0
    ; A console in the user's folder where opentop-cli (and opentop-sim) are found by name.
    CreateShortcut "$SMPROGRAMS\${APP}\${APP} command prompt.lnk" "$SYSDIR\cmd.exe" \
        '/k set "PATH=$INSTDIR;%PATH%" && cd /d "%USERPROFILE%" && opentop-cli --version' \
        "$INSTDIR\opentop-cli.exe" 0

    WriteRegStr HKLM "${UNINSTALL_KEY}" "DisplayName" "${APP}"
    WriteRegStr HKLM "${UNINSTALL_KEY}" "DisplayVersion" "${VERSION}"
    WriteRegStr HKLM "${UNINSTALL_KEY}" "Publisher" "OpenTOP developers"
    WriteRegStr HKLM "${UNINSTALL_KEY}" "DisplayIcon" "$INSTDIR\opentop.exe"
    WriteRegStr HKLM "${UNINSTALL_KEY}" "InstallLocation" "$INSTDIR"
    WriteRegStr HKLM "${UNINSTALL_KEY}" "UninstallString" '"$INSTDIR\uninstall.exe"'
    WriteRegStr HKLM "${UNINSTALL_KEY}" "QuietUninstallString" '"$INSTDIR\uninstall.exe" /S'
    WriteRegDWORD HKLM "${UNINSTALL_KEY}" "NoModify" 1
    WriteRegDWORD HKLM "${UNINSTALL_KEY}" "NoRepair" 1
    WriteRegDWORD HKLM "${UNINSTALL_KEY}" "EstimatedSize" ${SIZE_KB}
SectionEnd

Section "Uninstall"
    SetShellVarContext all
    Delete "$SMPROGRAMS\${APP}\${APP}.lnk"
    Delete "$SMPROGRAMS\${APP}\${APP} command prompt.lnk"
    RMDir "$SMPROGRAMS\${APP}"
    !include "${UNFILES}"
    Delete "$INSTDIR\uninstall.exe"
    RMDir "$INSTDIR" ; only when empty: files someone put there stay
    DeleteRegKey HKLM "${UNINSTALL_KEY}"
SectionEnd
