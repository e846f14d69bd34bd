#!/usr/bin/env bash
# Cross-compiles OpenTOP for Windows 10/11 (x86_64) with the shared MinGW-w64 Qt toolchain
# (../shared/toolchains/README.md: Qt 6.4.2 + libmodbus 3.1.6 unpacked at /opt/qt6-mingw),
# stages the three programs with everything they load into one folder that runs as it is, and
# packs that folder as an installer (NSIS) and a portable zip:
#
#   scripts/build-windows.sh            configure, build (Release), stage and package
#   scripts/build-windows.sh stage      stage again from the last build
#   scripts/build-windows.sh package    stage and package again from the last build
#
#   build-win/                          the build folder (its own; never build/)
#   build-win/stage/OpenTOP-<version>-win64/
#       opentop.exe opentop-cli.exe opentop-sim.exe
#       Qt6*.dll libmodbus-5.dll and the MinGW runtime (libstdc++, libgcc_s_seh, libwinpthread,
#       libssp), each found by following the programs' imports, none more
#       platforms/ styles/ sqldrivers/ imageformats/ iconengines/   the Qt plugins loaded at
#       run time (windows; offscreen for opentop-cli's certificate PDF; SQLite)
#       translations/qtbase_<lang>.qm   Qt's own words for every language OpenTOP speaks
#                                       (OpenTOP's own messages are inside the programs)
#   build-win/OpenTOP-<version>-win64-setup.exe   packaging/windows/opentop.nsi: per machine,
#       Start-menu entries for OpenTOP and a command prompt with opentop-cli on its PATH, an
#       uninstaller that removes exactly what was installed; /S for a silent install
#   build-win/OpenTOP-<version>-win64.zip          the staged folder, to run without installing
#
# Run under Wine (headless): see docs in ../shared/toolchains/README.md, e.g.
#   WINEDEBUG=-all wine build-win/stage/OpenTOP-*-win64/opentop-cli.exe --version
#
# Environment:
#   OPENTOP_QT_MINGW=/opt/qt6-mingw     where the toolchain is unpacked
#   OPENTOP_WIN_BUILD=<repo>/build-win  the build folder
#   OPENTOP_JOBS=2                      parallel compile jobs (every compile runs under nice 19)
#   OPENTOP_WERROR=ON                   warnings are errors, as in the Linux build
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
qt="${OPENTOP_QT_MINGW:-/opt/qt6-mingw}"
build="${OPENTOP_WIN_BUILD:-$repo/build-win}"
jobs="${OPENTOP_JOBS:-2}"
werror="${OPENTOP_WERROR:-ON}"
triplet=x86_64-w64-mingw32
programs=(opentop opentop-cli opentop-sim)

die() {
    echo "build-windows: $*" >&2
    exit 1
}

check_toolchain() {
    [[ -f "$qt/lib/cmake/Qt6/qt.toolchain.cmake" ]] ||
        die "no Qt for MinGW at $qt: unpack it with
    tar -C /opt -xf ../shared/toolchains/qt6.4.2-mingw-w64-x86_64.tar.zst
(../shared/toolchains/README.md lists the Debian packages it needs beside it)"
    command -v "$triplet-g++-posix" >/dev/null ||
        die "no $triplet-g++-posix: apt-get install g++-mingw-w64-x86-64-posix"
    command -v "$triplet-objdump" >/dev/null ||
        die "no $triplet-objdump: apt-get install binutils-mingw-w64-x86-64"
    [[ -x /usr/lib/qt6/libexec/moc ]] ||
        die "no host moc: apt-get install qt6-base-dev-tools qt6-base-dev (Debian's Qt 6.4.2)"
}

configure_and_build() {
    # Release at -O2, the optimisation of the Linux build (CMake's -O3 only adds time, and
    # false warnings from GCC 12). No tests here: they run under Wine in a later phase.
    nice -n 19 cmake -S "$repo" -B "$build" -G Ninja \
        -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_CXX_FLAGS_RELEASE="-O2 -DNDEBUG" \
        -DCMAKE_TOOLCHAIN_FILE="$qt/lib/cmake/Qt6/qt.toolchain.cmake" \
        -DOPENTOP_BUILD_TESTS=OFF \
        -DOPENTOP_WERROR="$werror"
    # The Linux builds' compiler cache is theirs: these objects do not go into it.
    CCACHE_DISABLE=1 nice -n 19 cmake --build "$build" --parallel "$jobs" --target "${programs[@]}"
}

# The DLLs a PE file imports, by name as the import table spells them.
imports_of() {
    "$triplet-objdump" -p "$1" | sed -n 's/^\s*DLL Name: //p'
}

# Where a DLL that is not part of Windows comes from: Qt's, the compiler's runtime (libstdc++,
# libgcc_s, libssp) or MinGW's (libwinpthread); empty for a system DLL.
find_dll() {
    local name="$1" dir gcc_dir
    gcc_dir="$(dirname "$("$triplet-g++-posix" -print-libgcc-file-name)")"
    for dir in "$qt/bin" "$gcc_dir" "/usr/$triplet/lib"; do
        if [[ -f "$dir/$name" ]]; then
            echo "$dir/$name"
            return
        fi
    done
}

version() {
    local v
    v="$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$build/CMakeCache.txt" 2>/dev/null)"
    [[ -n "$v" ]] || die "no configured build in $build: run without arguments first"
    echo "$v"
}

stage() {
    local version dest
    version="$(version)"
    dest="$build/stage/OpenTOP-$version-win64"
    rm -rf "$dest"
    mkdir -p "$dest"
    local p
    for p in "${programs[@]}"; do
        [[ -f "$build/app/$p.exe" ]] || die "$build/app/$p.exe is missing: build first"
        cp "$build/app/$p.exe" "$dest/"
    done
    # Plugins Qt loads by name at run time (no import names them): the window platform, the
    # offscreen one (opentop-cli lays out a certificate's text without a display), the native
    # style, SQLite for the results database, the image formats and the SVG icon engine the
    # window's icons use.
    local plugin
    for plugin in platforms/qwindows.dll platforms/qoffscreen.dll \
        styles/qwindowsvistastyle.dll sqldrivers/qsqlite.dll \
        imageformats/qico.dll imageformats/qsvg.dll imageformats/qjpeg.dll imageformats/qgif.dll \
        iconengines/qsvgicon.dll; do
        [[ -f "$qt/plugins/$plugin" ]] || die "the toolchain has no $plugin"
        mkdir -p "$dest/$(dirname "$plugin")"
        cp "$qt/plugins/$plugin" "$dest/$plugin"
    done
    # Every DLL the programs and plugins import, followed to the end; Windows' own stay out.
    local -a queue=("$dest"/*.exe "$dest"/*/*.dll)
    local -A seen=()
    local file dll from
    while ((${#queue[@]})); do
        file="${queue[0]}"
        queue=("${queue[@]:1}")
        while read -r dll; do
            [[ -n "$dll" && -z "${seen[${dll,,}]:-}" ]] || continue
            seen[${dll,,}]=1
            from="$(find_dll "$dll")"
            [[ -n "$from" ]] || continue # a system DLL
            cp "$from" "$dest/"
            queue+=("$dest/$dll")
        done < <(imports_of "$file")
    done
    # Without symbols, as the Debian package strips its programs (the toolchain's DLLs come
    # unstripped: libstdc++ alone is 23 MB with them, 2 MB without).
    find "$dest" \( -name '*.exe' -o -name '*.dll' \) -exec "$triplet-strip" --strip-unneeded {} +
    # Qt's own messages (standard buttons, dialogs) for each language OpenTOP is translated to.
    local ts lang
    mkdir -p "$dest/translations"
    for ts in "$repo"/translations/opentop_*.ts; do
        lang="$(basename "$ts" .ts)"
        lang="${lang#opentop_}"
        if [[ -f "/usr/share/qt6/translations/qtbase_$lang.qm" ]]; then
            cp "/usr/share/qt6/translations/qtbase_$lang.qm" "$dest/translations/"
        else
            echo "build-windows: no qtbase_$lang.qm (apt-get install qt6-translations-l10n)" >&2
        fi
    done
    echo "staged: $dest ($(du -sh "$dest" | cut -f1), $(find "$dest" -type f | wc -l) files)"
}

# NSIS lines for the staged files: installing them (File, folder by folder) and removing exactly
# them again (Delete, then RMDir of each folder, deepest first, which only removes empty ones).
nsis_file_lists() {
    local src="$1" files="$2" unfiles="$3" dir rel win file
    : >"$files"
    : >"$unfiles"
    while read -r dir; do # ".", "./platforms", ...
        rel="${dir#.}"
        rel="${rel#/}"                       # "", "platforms"
        win="${rel:+\\${rel//\//\\}}"        # "", "\platforms"
        echo "SetOutPath \"\$INSTDIR$win\"" >>"$files"
        while read -r file; do
            echo "File \"$src${rel:+/$rel}/$file\"" >>"$files"
            echo "Delete \"\$INSTDIR$win\\$file\"" >>"$unfiles"
        done < <(find "$src/$rel" -maxdepth 1 -type f -printf '%f\n' | LC_ALL=C sort)
    done < <(cd "$src" && find . -type d | LC_ALL=C sort)
    while read -r dir; do # deepest first
        rel="${dir#./}"
        echo "RMDir \"\$INSTDIR\\${rel//\//\\}\"" >>"$unfiles"
    done < <(cd "$src" && find . -mindepth 1 -type d | LC_ALL=C sort -r)
    echo "SetOutPath \"\$INSTDIR\"" >>"$files" # the shortcuts' working folder
}

package() {
    local version name src out
    version="$(version)"
    name="OpenTOP-$version-win64"
    src="$build/stage/$name"
    [[ -d "$src" ]] || die "nothing staged in $src"
    command -v makensis >/dev/null || die "no makensis: apt-get install nsis"
    command -v zip >/dev/null || die "no zip: apt-get install zip"
    nsis_file_lists "$src" "$build/stage/files.nsh" "$build/stage/unfiles.nsh"
    out="$build/$name-setup.exe"
    nice -n 19 makensis -V2 -INPUTCHARSET UTF8 \
        -DVERSION="$version" -DSTAGE="$src" -DICON="$build/app/opentop.ico" \
        -DFILES="$build/stage/files.nsh" -DUNFILES="$build/stage/unfiles.nsh" \
        -DSIZE_KB="$(du -sk "$src" | cut -f1)" -DOUTFILE="$out" \
        "$repo/packaging/windows/opentop.nsi"
    echo "installer: $out ($(du -h "$out" | cut -f1))"
    out="$build/$name.zip"
    rm -f "$out"
    (cd "$build/stage" && find "$name" -print | LC_ALL=C sort | nice -n 19 zip -q -X -9 "$out" -@)
    echo "zip: $out ($(du -h "$out" | cut -f1))"
}

check_toolchain
case "${1:-all}" in
all)
    start=$SECONDS
    configure_and_build
    echo "build-windows: built in $((SECONDS - start)) s"
    stage
    package
    ;;
stage) stage ;;
package)
    stage
    package
    ;;
*) die "usage: $0 [stage|package]" ;;
esac
