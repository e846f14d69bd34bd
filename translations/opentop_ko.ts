<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ko">
<context>
    <name>Freshness</name>
    <message>
        <location filename="../model/session/Freshness.cpp" line="29"/>
        <location filename="../model/session/Freshness.cpp" line="31"/>
        <source>%1 s old</source>
        <translation>%1초 전</translation>
    </message>
    <message>
        <location filename="../model/session/Freshness.cpp" line="33"/>
        <source>%1 min old</source>
        <translation>%1분 전</translation>
    </message>
    <message>
        <location filename="../model/session/Freshness.cpp" line="34"/>
        <source>%1 h old</source>
        <translation>%1시간 전</translation>
    </message>
    <message>
        <location filename="../model/session/Freshness.cpp" line="40"/>
        <source>never read</source>
        <translation>읽은 적 없음</translation>
    </message>
    <message>
        <location filename="../model/session/Freshness.cpp" line="41"/>
        <source>last answer %1 (%2)</source>
        <translation>마지막 응답 %1 (%2)</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/main.cpp" line="60"/>
        <source>Commissioning tool for RS-485 Modbus-RTU motor drives.</source>
        <translation>RS-485 Modbus-RTU 모터 드라이버용 커미셔닝 도구.</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="64"/>
        <source>Language of the program: %1 (default: the language menu&apos;s choice, else the system&apos;s).</source>
        <translation>프로그램 언어: %1 (기본값: 언어 메뉴에서 고른 언어, 없으면 시스템 언어).</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="79"/>
        <source>Open the bus overview and the trends of every drive.</source>
        <translation>버스 개요와 모든 드라이버의 트렌드를 엽니다.</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="80"/>
        <source>Monitoring poll interval in milliseconds.</source>
        <translation>모니터링 폴링 주기(밀리초).</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="83"/>
        <source>Quit after this many seconds and print the monitoring statistics (for measurements).</source>
        <translation>지정한 초가 지나면 종료하고 모니터링 통계를 출력합니다(측정용).</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="87"/>
        <source>Print the monitoring totals every this many seconds (for measurements).</source>
        <translation>지정한 초마다 모니터링 합계를 출력합니다(측정용).</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="97"/>
        <source>--poll-ms needs a number of milliseconds</source>
        <translation>--poll-ms에는 밀리초 값이 필요합니다</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="102"/>
        <source>--quit-after needs a number of seconds</source>
        <translation>--quit-after에는 초 값이 필요합니다</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="107"/>
        <source>--stats-every needs a number of seconds</source>
        <translation>--stats-every에는 초 값이 필요합니다</translation>
    </message>
    <message>
        <location filename="../app/gui/StartupProbe.cpp" line="23"/>
        <source>Print how long the start took once the window shows the bus&apos;s drives, then quit (for measurements).</source>
        <translation>창에 버스의 드라이버가 표시되면 시작에 걸린 시간을 출력하고 종료합니다(측정용).</translation>
    </message>
</context>
<context>
    <name>opentop</name>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="71"/>
        <source>not read</source>
        <translation>읽지 않음</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="91"/>
        <source>No alarm is active.</source>
        <translation>발생 중인 알람이 없습니다.</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="93"/>
        <source>Alarm active: %1 %2.</source>
        <translation>알람 발생 중: %1 %2.</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="96"/>
        <source>An alarm is active.</source>
        <translation>알람이 발생 중입니다.</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="99"/>
        <source>This drive is set to clear alarms by a power restart only (%1): Alarm-Reset clears none of them.</source>
        <translation>이 드라이버는 전원 재투입으로만 알람이 해제되도록 설정되어 있습니다(%1): Alarm-Reset으로는 어떤 알람도 해제되지 않습니다.</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="106"/>
        <source>%1: could not be read: %2</source>
        <translation>%1: 읽을 수 없습니다: %2</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="110"/>
        <source>%1: no records.</source>
        <translation>%1: 기록 없음.</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="113"/>
        <source>%1: %2 of %3 records, newest first</source>
        <translation>%1: 기록 %3개 중 %2개, 최신순</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="118"/>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="118"/>
        <source>Code</source>
        <translation>코드</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="118"/>
        <source>Panel</source>
        <translation>패널</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="118"/>
        <source>Name</source>
        <translation>이름</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="118"/>
        <source>Cleared by</source>
        <translation>해제 방법</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="125"/>
        <source>unknown code</source>
        <translation>알 수 없는 코드</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="132"/>
        <source>Cause: %1</source>
        <translation>원인: %1</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="134"/>
        <source>Remedy: %1</source>
        <translation>조치: %1</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="136"/>
        <source>To clear: %1</source>
        <translation>해제 방법: %1</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="142"/>
        <source>Communication error register (%1): could not be read.</source>
        <translation>통신 오류 레지스터(%1): 읽을 수 없습니다.</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="146"/>
        <source>Communication error register (%1): none (0).</source>
        <translation>통신 오류 레지스터(%1): 없음(0).</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="149"/>
        <source>Communication error register (%1): %2, not a known code.</source>
        <translation>통신 오류 레지스터(%1): %2, 알 수 없는 코드.</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="153"/>
        <source>Communication error register (%1): %2 %3
  Cause: %4
  Remedy: %5</source>
        <translation>통신 오류 레지스터(%1): %2 %3
  원인: %4
  조치: %5</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="27"/>
        <source>Machine-readable JSON on standard output.</source>
        <translation>기계 판독용 JSON을 표준 출력으로 출력합니다.</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="28"/>
        <source>Print every frame sent and received on standard error.</source>
        <translation>송수신하는 모든 프레임을 표준 오류로 출력합니다.</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="30"/>
        <source>Drive variant where the drive does not report it: VARIANT, or ID=VARIANT,... (e.g. dbu400, 150=dbu400).</source>
        <translation>드라이버가 기종을 알려주지 않을 때 사용할 기종: VARIANT 또는 ID=VARIANT,... (예: dbu400, 150=dbu400).</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="32"/>
        <source>VARIANT</source>
        <translation>VARIANT</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="34"/>
        <source>The drives on the bus, e.g. 1,3,5-7 (default: OPENTOP_BUS_DRIVES, else the drives the last scan of this connection found): before a write or command, their communication group is read to name every drive it also reaches.</source>
        <translation>버스에 있는 드라이버, 예: 1,3,5-7 (기본값: OPENTOP_BUS_DRIVES, 없으면 이 연결의 마지막 스캔에서 찾은 드라이버): 쓰기나 명령 전에 통신 그룹을 읽어 함께 도달하는 모든 드라이버를 밝힙니다.</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="37"/>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="39"/>
        <source>Write or command a drive that can be a communication group parent although the drives on the bus are not known (no --bus-drives and no scan of this connection): drives in its group execute it too, unnamed.</source>
        <translation>버스의 드라이버를 모르는 상태에서도(--bus-drives 없음, 이 연결의 스캔 없음) 통신 그룹 부모일 수 있는 드라이버에 쓰거나 명령합니다: 그룹의 드라이버도 이름이 밝혀지지 않은 채 실행합니다.</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="43"/>
        <source>Show this help, or a command&apos;s help after the command.</source>
        <translation>이 도움말을 표시합니다. 명령 뒤에 쓰면 그 명령의 도움말을 표시합니다.</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="44"/>
        <source>Show the version.</source>
        <translation>버전을 표시합니다.</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="48"/>
        <source>Language of the human output: en, zh_TW, zh_CN, ko, ja (default: the system&apos;s). --json output is the same in every language.</source>
        <translation>사람이 읽는 출력의 언어: en, zh_TW, zh_CN, ko, ja (기본값: 시스템 언어). --json 출력은 모든 언어에서 같습니다.</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="50"/>
        <source>CODE</source>
        <translation>CODE</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="28"/>
        <source>stopped</source>
        <translation>정지됨</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="30"/>
        <source>STILL RUNNING</source>
        <translation>아직 운전 중</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="32"/>
        <source>no answer</source>
        <translation>응답 없음</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="38"/>
        <source>top level</source>
        <translation>최상위</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="41"/>
        <source>&quot;schema&quot; must be 1</source>
        <translation>&quot;schema&quot;는 1이어야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="52"/>
        <source>&quot;family&quot; must be a lower-case id</source>
        <translation>&quot;family&quot;는 소문자 ID여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="60"/>
        <source>serial.parity must be N, E or O</source>
        <translation>serial.parity는 N, E, O 중 하나여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="64"/>
        <source>serial: baud must be 1200–115200 and stopBits 1 or 2</source>
        <translation>serial: baud는 1200–115200, stopBits는 1 또는 2여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="76"/>
        <source>serial.formats: &quot;%1&quot; is not a format such as 8N1 or 8E1</source>
        <translation>serial.formats: &quot;%1&quot;은(는) 8N1, 8E1 같은 형식이 아닙니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="80"/>
        <source>serial.formats must hold the default format %1</source>
        <translation>serial.formats에 기본 형식 %1이(가) 있어야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="84"/>
        <source>serial.powerOnDelayMs must be 0–60000</source>
        <translation>serial.powerOnDelayMs는 0–60000이어야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="97"/>
        <source>limits: maxReadRegisters 1–125, maxWriteRegisters 1–123</source>
        <translation>limits: maxReadRegisters는 1–125, maxWriteRegisters는 1–123</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="99"/>
        <source>limits: slaves must lie in 1–247</source>
        <translation>limits: slaves는 1–247 범위여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="114"/>
        <source>variants[%1] needs id, model and label</source>
        <translation>variants[%1]에는 id, model, label이 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="116"/>
        <source>variants[%1]: id &quot;%2&quot; repeated</source>
        <translation>variants[%1]: id &quot;%2&quot;가 중복됩니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="127"/>
        <source>groups[%1] needs a unique id and a label</source>
        <translation>groups[%1]에는 고유한 id와 label이 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="138"/>
        <source>readBlocks[%1] needs function 3 or 4 and first ≤ last</source>
        <translation>readBlocks[%1]에는 function 3 또는 4와 first ≤ last가 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="182"/>
        <source>%1 has no name</source>
        <translation>%1에 이름이 없습니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="184"/>
        <source>%1: reset must be one of %2</source>
        <translation>%1: reset은 %2 중 하나여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="187"/>
        <source>%1: code %2 repeated</source>
        <translation>%1: 코드 %2가 중복됩니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="203"/>
        <source>%1: unknown parameter &quot;%2&quot;</source>
        <translation>%1: 알 수 없는 파라미터 &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="231"/>
        <source>%1 must be a parameter name, a list of names or an object</source>
        <translation>%1은(는) 파라미터 이름, 이름 목록 또는 객체여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="240"/>
        <source>%1: &quot;%2&quot; has no bit field &quot;%3&quot;</source>
        <translation>%1: &quot;%2&quot;에 비트 필드 &quot;%3&quot;이(가) 없습니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="246"/>
        <source>%1: %2 is not a value &quot;%3&quot; can be written with</source>
        <translation>%1: %2은(는) &quot;%3&quot;에 쓸 수 있는 값이 아닙니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="264"/>
        <source>decelerationKnobs need the &quot;selected&quot; role</source>
        <translation>decelerationKnobs에는 &quot;selected&quot; 역할이 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="280"/>
        <source>%1 needs &quot;selected&quot; and &quot;maxSeconds&quot;</source>
        <translation>%1에는 &quot;selected&quot;와 &quot;maxSeconds&quot;가 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="283"/>
        <source>%1: &quot;selected&quot; %2 is not a value of the &quot;selected&quot; role, or repeated</source>
        <translation>%1: &quot;selected&quot; %2은(는) &quot;selected&quot; 역할의 값이 아니거나 중복됩니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="288"/>
        <source>%1: &quot;maxSeconds&quot; must be more than 0 and at most 600</source>
        <translation>%1: &quot;maxSeconds&quot;는 0보다 크고 600 이하여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="320"/>
        <source>%1: &quot;light&quot; must be one of %2, each once</source>
        <translation>%1: &quot;light&quot;는 %2 중 하나여야 하며 각각 한 번만 쓸 수 있습니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="323"/>
        <source>%1: &quot;colour&quot; must be #rrggbb</source>
        <translation>%1: &quot;colour&quot;는 #rrggbb 형식이어야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="325"/>
        <source>%1: &quot;label&quot; and &quot;meaning&quot; must not be empty</source>
        <translation>%1: &quot;label&quot;과 &quot;meaning&quot;은 비어 있으면 안 됩니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="57"/>
        <source> and %1 more</source>
        <translation> 외 %1개</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="28"/>
        <source>not reached</source>
        <translation>도달하지 않음</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="35"/>
        <source>error: %1</source>
        <translation>오류: %1</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="36"/>
        <source>nothing was written</source>
        <translation>아무것도 쓰지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="60"/>
        <source>NOT RECORDED (%1)</source>
        <translation>기록 안 됨 (%1)</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="62"/>
        <source>%1 (kept on this station)</source>
        <translation>%1 (이 스테이션에 보관)</translation>
    </message>
</context>
<context>
    <name>opentop::AboutDialog</name>
    <message>
        <location filename="../ui/help/AboutDialog.cpp" line="20"/>
        <source>About OpenTOP</source>
        <translation>OpenTOP 정보</translation>
    </message>
    <message>
        <location filename="../ui/help/AboutDialog.cpp" line="22"/>
        <source>&lt;h2&gt;OpenTOP %1&lt;/h2&gt;&lt;p&gt;Commissioning tool for RS-485 Modbus-RTU motor drives: TROY DBU brushless drives and a DC motor PID controller.&lt;/p&gt;&lt;p&gt;Copyright © the OpenTOP developers.&lt;br&gt;Licence: GNU General Public License, version 3 or any later version (GPL-3.0-or-later). This program comes with ABSOLUTELY NO WARRANTY; it is free software, and you are welcome to redistribute it under the terms of that licence.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Built with&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;Qt %2 (run time; built with %3): GNU Lesser General Public License, version 3 (LGPL-3.0-only); Qt Charts: GNU General Public License, version 3 (GPL-3.0-only)&lt;/li&gt;&lt;li&gt;libmodbus %4: GNU Lesser General Public License, version 2.1 or later (LGPL-2.1-or-later)&lt;/li&gt;&lt;li&gt;GoogleTest (tests only): BSD 3-Clause licence&lt;/li&gt;&lt;/ul&gt;</source>
        <translation>&lt;h2&gt;OpenTOP %1&lt;/h2&gt;&lt;p&gt;RS-485 Modbus-RTU 모터 드라이버용 커미셔닝 도구: TROY DBU 브러시리스 드라이버와 DC 모터 PID 컨트롤러.&lt;/p&gt;&lt;p&gt;Copyright © the OpenTOP developers.&lt;br&gt;라이선스: GNU General Public License 버전 3 또는 이후 버전(GPL-3.0-or-later). 이 프로그램은 어떠한 보증도 제공하지 않습니다. 자유 소프트웨어이며, 이 라이선스의 조건에 따라 자유롭게 재배포할 수 있습니다.&lt;/p&gt;&lt;p&gt;&lt;b&gt;사용한 구성 요소&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;Qt %2 (실행 시; 빌드 시 %3): GNU Lesser General Public License 버전 3(LGPL-3.0-only); Qt Charts: GNU General Public License 버전 3(GPL-3.0-only)&lt;/li&gt;&lt;li&gt;libmodbus %4: GNU Lesser General Public License 버전 2.1 또는 이후 버전(LGPL-2.1-or-later)&lt;/li&gt;&lt;li&gt;GoogleTest (테스트 전용): BSD 3-Clause 라이선스&lt;/li&gt;&lt;/ul&gt;</translation>
    </message>
    <message>
        <location filename="../ui/help/AboutDialog.cpp" line="45"/>
        <source>About &amp;Qt</source>
        <translation>Qt 정보(&amp;Q)</translation>
    </message>
</context>
<context>
    <name>opentop::AccessCheck</name>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="27"/>
        <source>%1 (%2) may not %3: it needs the %4 role or higher</source>
        <translation>%1(%2)은(는) %3 권한이 없습니다: %4 이상의 역할이 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="39"/>
        <location filename="../model/access/AccessCheck.cpp" line="49"/>
        <location filename="../model/access/AccessCheck.cpp" line="122"/>
        <source>the users cannot be read from the results database: %1</source>
        <translation>결과 데이터베이스에서 사용자를 읽을 수 없습니다: %1</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="54"/>
        <source>wrong user name or password</source>
        <translation>사용자 이름 또는 비밀번호가 틀렸습니다</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="56"/>
        <source>user &quot;%1&quot;: wrong user name or password</source>
        <translation>사용자 &quot;%1&quot;: 사용자 이름 또는 비밀번호가 틀렸습니다</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="60"/>
        <source>user %1 is disabled</source>
        <translation>사용자 %1은(는) 비활성화되어 있습니다</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="98"/>
        <source>logged in as %1</source>
        <translation>%1(으)로 로그인</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="123"/>
        <source>user %1 is not an active user</source>
        <translation>사용자 %1은(는) 활성 사용자가 아닙니다</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="136"/>
        <source>recipe %1 rev. %2, checksum %3</source>
        <translation>레시피 %1 rev. %2, 체크섬 %3</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="142"/>
        <source>this station has no users yet: an approval names its approver, so add users first (opentop-cli eol user add)</source>
        <translation>이 스테이션에는 아직 사용자가 없습니다: 승인에는 승인자가 기록되므로 먼저 사용자를 추가하십시오(opentop-cli eol user add)</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="151"/>
        <source>the approval was not recorded: %1</source>
        <translation>승인이 기록되지 않았습니다: %1</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="155"/>
        <source>%1; approval %2</source>
        <translation>%1; 승인 %2</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="184"/>
        <source>the first user must be an administrator (--role administrator): they add everyone else</source>
        <translation>첫 사용자는 관리자여야 합니다(--role administrator): 나머지 사용자는 관리자가 추가합니다</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="189"/>
        <source>add user %1</source>
        <translation>사용자 %1 추가</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="196"/>
        <source>user %1 exists already</source>
        <translation>사용자 %1이(가) 이미 있습니다</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="202"/>
        <source>user %1 (%2) added as %3</source>
        <translation>사용자 %1(%2)을(를) %3(으)로 추가했습니다</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="214"/>
        <source>enable user %1</source>
        <translation>사용자 %1 활성화</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="214"/>
        <source>disable user %1</source>
        <translation>사용자 %1 비활성화</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="216"/>
        <location filename="../model/access/AccessCheck.cpp" line="256"/>
        <source>there are no users yet</source>
        <translation>아직 사용자가 없습니다</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="223"/>
        <location filename="../model/access/AccessCheck.cpp" line="262"/>
        <source>no user %1</source>
        <translation>사용자 %1이(가) 없습니다</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="228"/>
        <source>%1 is the last active administrator: add another first</source>
        <translation>%1은(는) 마지막 활성 관리자입니다: 먼저 다른 관리자를 추가하십시오</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="254"/>
        <source>set the password of %1</source>
        <translation>%1의 비밀번호 설정</translation>
    </message>
</context>
<context>
    <name>opentop::AccessPolicy</name>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="76"/>
        <source>operator</source>
        <translation>작업자</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="78"/>
        <source>technician</source>
        <translation>기술자</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="80"/>
        <source>engineer</source>
        <translation>엔지니어</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="84"/>
        <source>administrator</source>
        <translation>관리자</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="96"/>
        <source>test units</source>
        <translation>제품 검사</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="98"/>
        <source>reset an alarm and retry</source>
        <translation>알람 리셋 후 재시도</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="100"/>
        <source>override a retest limit</source>
        <translation>재검사 한도 해제</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="102"/>
        <source>leave production mode</source>
        <translation>생산 모드 종료</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="104"/>
        <source>open or edit a recipe</source>
        <translation>레시피 열기 또는 편집</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="106"/>
        <source>approve a recipe</source>
        <translation>레시피 승인</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="110"/>
        <source>manage users</source>
        <translation>사용자 관리</translation>
    </message>
</context>
<context>
    <name>opentop::AddressSwitches</name>
    <message>
        <location filename="../model/profile/AddressSwitches.cpp" line="66"/>
        <source>address.names: every switch needs a name</source>
        <translation>address.names: 모든 스위치에 이름이 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/AddressSwitches.cpp" line="74"/>
        <source>address.switches must be &quot;hex-rotary&quot; or &quot;binary-dip&quot;</source>
        <translation>address.switches는 &quot;hex-rotary&quot; 또는 &quot;binary-dip&quot;이어야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/AddressSwitches.cpp" line="78"/>
        <source>address.names: 1–%1 switches for this notation</source>
        <translation>address.names: 이 표기법에는 스위치 1–%1개</translation>
    </message>
    <message>
        <location filename="../model/profile/AddressSwitches.cpp" line="81"/>
        <source>address: the switches (%1) cannot set machine number %2</source>
        <translation>address: 스위치(%1)로는 국번 %2을(를) 설정할 수 없습니다</translation>
    </message>
</context>
<context>
    <name>opentop::AlarmBanner</name>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="16"/>
        <source>Show</source>
        <translation>보기</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="17"/>
        <source>Dismiss</source>
        <translation>닫기</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="24"/>
        <source>Open the drive&apos;s alarm history</source>
        <translation>드라이버의 알람 이력을 엽니다</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="25"/>
        <source>Hide this alarm until it is cleared; a new alarm shows again</source>
        <translation>해제될 때까지 이 알람을 숨깁니다. 새 알람은 다시 표시됩니다</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="85"/>
        <source>Machine %1: %2 %3 — %4</source>
        <translation>국번 %1: %2 %3 — %4</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="89"/>
        <source>Machine %1: %2 %3</source>
        <translation>국번 %1: %2 %3</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="91"/>
        <source>Machine %1: alarm %2h (not in the alarm table)</source>
        <translation>국번 %1: 알람 %2h (알람 표에 없음)</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="95"/>
        <source>Machine %1: an alarm is active</source>
        <translation>국번 %1: 알람 발생 중</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/alarms/AlarmBanner.cpp" line="98"/>
        <source>(%n more drive(s) with an alarm)</source>
        <translation>
            <numerusform>(알람이 발생한 드라이버 %n대 더 있음)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::AlarmExport</name>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="50"/>
        <source>Machine</source>
        <translation>국번</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="50"/>
        <source>Model</source>
        <translation>모델</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="50"/>
        <source>Kind</source>
        <translation>종류</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="50"/>
        <source>Record</source>
        <translation>기록</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="50"/>
        <source>Code</source>
        <translation>코드</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="50"/>
        <source>Machine name</source>
        <translation>기계 이름</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="51"/>
        <source>Panel code</source>
        <translation>패널 코드</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="51"/>
        <source>Name</source>
        <translation>이름</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="51"/>
        <source>Cleared by</source>
        <translation>해제 방법</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="51"/>
        <source>Cause</source>
        <translation>원인</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="51"/>
        <source>Remedy</source>
        <translation>조치</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="54"/>
        <source>alarm</source>
        <translation>알람</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="55"/>
        <source>warning</source>
        <translation>경고</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="63"/>
        <source>unknown code</source>
        <translation>알 수 없는 코드</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="109"/>
        <source>machine %1: %2</source>
        <translation>국번 %1: %2</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/alarms/AlarmExport.cpp" line="132"/>
        <source>%n record(s) of %1 drive(s) written to %2.</source>
        <translation>
            <numerusform>드라이버 %1대의 기록 %n건을 %2에 저장했습니다.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="137"/>
        <source>Not everything could be read: %1</source>
        <translation>일부를 읽지 못했습니다: %1</translation>
    </message>
</context>
<context>
    <name>opentop::AlarmHistory</name>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="68"/>
        <source>%1: erases the %2</source>
        <translation>%1: %2 삭제</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="107"/>
        <source>%1 drives have no alarm reset command</source>
        <translation>%1 드라이버에는 알람 리셋 명령이 없습니다</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="182"/>
        <source>The alarm</source>
        <translation>알람</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="184"/>
        <source>%1 is cleared.</source>
        <translation>%1이(가) 해제되었습니다.</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="185"/>
        <source>No alarm was active; nothing to clear.</source>
        <translation>발생 중인 알람이 없어 해제할 것이 없습니다.</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="188"/>
        <source>%1 is still active: only a power cycle clears it. %2</source>
        <translation>%1이(가) 아직 발생 중입니다: 전원 재투입으로만 해제됩니다. %2</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="193"/>
        <source>%1 is still active: the drive is set to clear alarms by a power restart only (%2). Remove the cause, turn the power off, wait 5 s and turn it on again; or change that setting to allow the reset command.</source>
        <translation>%1이(가) 아직 발생 중입니다: 이 드라이버는 전원 재투입으로만 알람이 해제되도록 설정되어 있습니다(%2). 원인을 제거하고 전원을 끈 뒤 5 s 기다렸다가 다시 켜십시오. 또는 리셋 명령을 허용하도록 그 설정을 변경하십시오.</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="199"/>
        <source>%1 is still active: its cause is still present%2. Remove the cause and turn off the start signal, then reset again.</source>
        <translation>%1이(가) 아직 발생 중입니다: 원인이 아직 남아 있습니다%2. 원인을 제거하고 기동 신호를 끈 뒤 다시 리셋하십시오.</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="205"/>
        <source>The reset was accepted; whether an alarm is still active could not be read.</source>
        <translation>리셋은 수락되었지만, 알람이 아직 발생 중인지 읽을 수 없습니다.</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="207"/>
        <source>The reset failed: %1</source>
        <translation>리셋 실패: %1</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="210"/>
        <source>(The drive refused the reset: %1)</source>
        <translation>(드라이버가 리셋을 거부했습니다: %1)</translation>
    </message>
</context>
<context>
    <name>opentop::AlarmRecords</name>
    <message>
        <location filename="../model/alarms/AlarmRecords.cpp" line="90"/>
        <location filename="../model/alarms/AlarmRecords.cpp" line="101"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>opentop::AlarmRecordsView</name>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="50"/>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="50"/>
        <source>Code</source>
        <translation>코드</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="50"/>
        <source>Panel</source>
        <translation>패널</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="50"/>
        <source>Name</source>
        <translation>이름</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="50"/>
        <source>Cleared by</source>
        <translation>해제 방법</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="67"/>
        <source>Cause and remedy</source>
        <translation>원인 및 조치</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="68"/>
        <source>Communication error register</source>
        <translation>통신 오류 레지스터</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="75"/>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="115"/>
        <source>Select a record to see its cause and remedy.</source>
        <translation>원인과 조치를 보려면 기록을 선택하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="76"/>
        <source>Not read yet.</source>
        <translation>아직 읽지 않음.</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="126"/>
        <source>This drive has no communication error register.</source>
        <translation>이 드라이버에는 통신 오류 레지스터가 없습니다.</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="128"/>
        <source>%1: could not be read.</source>
        <translation>%1: 읽을 수 없습니다.</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="130"/>
        <source>%1: no error (0).</source>
        <translation>%1: 오류 없음(0).</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="133"/>
        <source>%1: %2, not a known code.</source>
        <translation>%1: %2, 알 수 없는 코드.</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="135"/>
        <source>%1: %2 %3
Cause: %4
Remedy: %5</source>
        <translation>%1: %2 %3
원인: %4
조치: %5</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="147"/>
        <source>No alarm records</source>
        <translation>알람 기록 없음</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="147"/>
        <source>No warning records</source>
        <translation>경고 기록 없음</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="153"/>
        <source>%1: could not be read: %2</source>
        <translation>%1: 읽을 수 없습니다: %2</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="156"/>
        <source>%1: %2 of %3 records, newest first</source>
        <translation>%1: 기록 %3개 중 %2개, 최신순</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="167"/>
        <source>unknown code</source>
        <translation>알 수 없는 코드</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="196"/>
        <source>Record %1: code %2 is not in the %3 table.</source>
        <translation>기록 %1: 코드 %2이(가) %3 표에 없습니다.</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="201"/>
        <source>%1 %2 (record %3)</source>
        <translation>%1 %2 (기록 %3)</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="203"/>
        <source>Cause: %1</source>
        <translation>원인: %1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="205"/>
        <source>Remedy: %1</source>
        <translation>조치: %1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="207"/>
        <source>To clear: %1</source>
        <translation>해제 방법: %1</translation>
    </message>
</context>
<context>
    <name>opentop::AlarmsCommand</name>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="165"/>
        <source>Show alarm and warning histories with causes and remedies; reset, erase</source>
        <translation>알람·경고 이력을 원인과 조치와 함께 표시합니다. 리셋, 삭제</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="172"/>
        <source>Send the alarm reset command, then tell whether the alarm is cleared or needs a power cycle (needs --yes; exit 4 when it stays active).</source>
        <translation>알람 리셋 명령을 보낸 뒤, 알람이 해제되었는지 전원 재투입이 필요한지 알려줍니다(--yes 필요; 알람이 계속 발생 중이면 종료 코드 4).</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="174"/>
        <source>Erase the alarm and warning records (needs --yes).</source>
        <translation>알람·경고 기록을 삭제합니다(--yes 필요).</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="175"/>
        <source>Confirm --reset and --clear-records.</source>
        <translation>--reset과 --clear-records를 확인합니다.</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="186"/>
        <source>error: usage: %1 (one machine number)</source>
        <translation>오류: 사용법: %1 (국번 하나)</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="194"/>
        <source>error: %1</source>
        <translation>오류: %1</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="200"/>
        <source>error: machine number %1 (%2) keeps no alarm or warning records</source>
        <translation>오류: 국번 %1(%2)은(는) 알람·경고 기록을 보관하지 않습니다</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="207"/>
        <source>error: %1 drives have no %2 command</source>
        <translation>오류: %1 드라이버에는 %2 명령이 없습니다</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="209"/>
        <source>alarm reset</source>
        <translation>알람 리셋</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="209"/>
        <source>record erase</source>
        <translation>기록 삭제</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="220"/>
        <source>These change machine number %1; add --yes to send them:</source>
        <translation>다음은 국번 %1의 설정을 변경합니다. 보내려면 --yes를 추가하십시오:</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="224"/>
        <source>— clears the active alarm if its cause is gone and it is not one that only a power cycle clears</source>
        <translation>— 원인이 제거되었고 전원 재투입으로만 해제되는 알람이 아니면 발생 중인 알람을 해제합니다</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="249"/>
        <source>Machine number %1 (%2)</source>
        <translation>국번 %1 (%2)</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="277"/>
        <source>Alarm reset: %1</source>
        <translation>알람 리셋: %1</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="300"/>
        <source>Erased: %1 (%2 records); %3</source>
        <translation>삭제됨: %1 (기록 %2건); %3</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="303"/>
        <source>read back empty.</source>
        <translation>다시 읽기 결과 비어 있음.</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="304"/>
        <source>NOT empty when read back.</source>
        <translation>다시 읽기 결과 비어 있지 않음.</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="307"/>
        <source>Erasing failed: %1</source>
        <translation>삭제 실패: %1</translation>
    </message>
</context>
<context>
    <name>opentop::AlarmsPage</name>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="35"/>
        <source>&amp;Re-read</source>
        <translation>다시 읽기(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="36"/>
        <source>Reset &amp;alarm…</source>
        <translation>알람 리셋(&amp;A)…</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="37"/>
        <source>&amp;Clear records…</source>
        <translation>기록 삭제(&amp;C)…</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="41"/>
        <source>Alarms and warnings of machine %1 (%2)</source>
        <translation>국번 %1의 알람과 경고 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="67"/>
        <source>Send the alarm reset command; tells whether the alarm is cleared or only a power cycle clears it</source>
        <translation>알람 리셋 명령을 보냅니다. 알람이 해제되었는지, 전원 재투입으로만 해제되는지 알려줍니다</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="69"/>
        <source>Erase the alarm and warning records kept by the drive</source>
        <translation>드라이버에 보관된 알람·경고 기록을 삭제합니다</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="75"/>
        <source>This drive keeps no alarm or warning records.</source>
        <translation>이 드라이버는 알람·경고 기록을 보관하지 않습니다.</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="105"/>
        <source>Alarm state: %1</source>
        <translation>알람 상태: %1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="187"/>
        <source>Reading the records…</source>
        <translation>기록을 읽는 중…</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="203"/>
        <source>No alarm is active.</source>
        <translation>발생 중인 알람이 없습니다.</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="205"/>
        <source>Alarm active: %1 %2.</source>
        <translation>알람 발생 중: %1 %2.</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="207"/>
        <source>An alarm is active.</source>
        <translation>알람이 발생 중입니다.</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="210"/>
        <source>This drive is set to clear alarms by a power restart only (%1): Alarm-Reset clears none of them.</source>
        <translation>이 드라이버는 전원 재투입으로만 알람이 해제되도록 설정되어 있습니다(%1): Alarm-Reset으로는 어떤 알람도 해제되지 않습니다.</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="214"/>
        <source>Could not be read: %1</source>
        <translation>읽을 수 없습니다: %1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="252"/>
        <source>Writes: %1</source>
        <translation>쓰기: %1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="253"/>
        <source>This clears the active alarm if its cause is gone. Some alarms are cleared only by a power cycle; the result tells.</source>
        <translation>원인이 제거되었으면 발생 중인 알람을 해제합니다. 일부 알람은 전원 재투입으로만 해제되며, 결과에 표시됩니다.</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="256"/>
        <source>This drive is set to clear alarms by a power restart only (%1).</source>
        <translation>이 드라이버는 전원 재투입으로만 알람이 해제되도록 설정되어 있습니다(%1).</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="258"/>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="260"/>
        <source>Reset alarm</source>
        <translation>알람 리셋</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="259"/>
        <source>Send the alarm reset command to machine %1?</source>
        <translation>국번 %1에 알람 리셋 명령을 보내시겠습니까?</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="267"/>
        <source>Sending the alarm reset…</source>
        <translation>알람 리셋을 보내는 중…</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="273"/>
        <source>Alarm reset: %1</source>
        <translation>알람 리셋: %1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="276"/>
        <source>Turn the drive&apos;s power off, wait 5 s and turn it on again.</source>
        <translation>드라이버 전원을 끄고 5 s 기다린 뒤 다시 켜십시오.</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="287"/>
        <source>%1 (%2 records)</source>
        <translation>%1 (기록 %2건)</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="289"/>
        <source>the alarm and warning records</source>
        <translation>알람·경고 기록</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="291"/>
        <source>Clear records</source>
        <translation>기록 삭제</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="292"/>
        <source>Erase %1 of machine %2?</source>
        <translation>국번 %2의 %1을(를) 삭제하시겠습니까?</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="292"/>
        <source> and </source>
        <translation> 및 </translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="293"/>
        <source>The records cannot be restored. Writes: %1</source>
        <translation>삭제한 기록은 복원할 수 없습니다. 쓰기: %1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="295"/>
        <source>Erase</source>
        <translation>삭제</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="302"/>
        <source>Erasing the records…</source>
        <translation>기록을 삭제하는 중…</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="310"/>
        <source>Erased: %1 (%2 records); %3</source>
        <translation>삭제됨: %1 (기록 %2건); %3</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="313"/>
        <source>read back empty.</source>
        <translation>다시 읽기 결과 비어 있음.</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="314"/>
        <source>NOT empty when read back.</source>
        <translation>다시 읽기 결과 비어 있지 않음.</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="316"/>
        <source>Erasing failed: %1</source>
        <translation>삭제 실패: %1</translation>
    </message>
</context>
<context>
    <name>opentop::AutotunePanel</name>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="24"/>
        <source>Autotune…</source>
        <translation>오토튜닝…</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="28"/>
        <source>Accept</source>
        <translation>수락</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="29"/>
        <source>Reject</source>
        <translation>거부</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="30"/>
        <source>Store in the drive</source>
        <translation>드라이버에 저장</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="48"/>
        <source>Writes the proposed gains to the drive (temporary until stored) and offers a step test to compare with the prediction</source>
        <translation>제안된 게인을 드라이버에 쓰고(저장하기 전까지는 임시), 예측과 비교할 스텝 시험을 제안합니다</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="50"/>
        <source>Writes back the gains the drive had before</source>
        <translation>드라이버의 이전 게인을 다시 씁니다</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="51"/>
        <source>Stores the gains in the drive so that they survive a power cycle; asks first unless the step after Accept passed the check</source>
        <translation>전원 재투입 후에도 유지되도록 게인을 드라이버에 저장합니다. 수락 후 스텝이 확인을 통과하지 못했으면 먼저 묻습니다</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="57"/>
        <source>Operating speed:</source>
        <translation>운전 속도:</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="58"/>
        <source>Relay amplitude:</source>
        <translation>릴레이 진폭:</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="59"/>
        <source>%</source>
        <translation>%</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="60"/>
        <source>Rule:</source>
        <translation>튜닝 규칙:</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="64"/>
        <source>Present</source>
        <translation>현재</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="65"/>
        <source>Proposed</source>
        <translation>제안</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="66"/>
        <source>P</source>
        <translation>P</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="66"/>
        <source>I</source>
        <translation>I</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="66"/>
        <source>D</source>
        <translation>D</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="66"/>
        <source>D period</source>
        <translation>D 주기</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="113"/>
        <source>Enter an operating speed above 0 %1.</source>
        <translation>0 %1보다 큰 운전 속도를 입력하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="117"/>
        <source>Enter a relay amplitude of 1–50 %.</source>
        <translation>릴레이 진폭을 1–50 %로 입력하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="130"/>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="183"/>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="145"/>
        <source>No autotune result yet.</source>
        <translation>아직 오토튜닝 결과가 없습니다.</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="153"/>
        <source>Autotune failed: %1</source>
        <translation>오토튜닝 실패: %1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="155"/>
        <source>What to change: %1</source>
        <translation>바꿀 점: %1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="165"/>
        <source>Relay: Ku %1 %/%2, Tu %3 ms measured, %4 readings per period (one every %5 ms)</source>
        <translation>릴레이: Ku %1 %/%2, 측정된 Tu %3 ms, 주기당 읽기 %4회(%5 ms마다)</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="175"/>
        <source>The drive&apos;s own loop (model): Ku %1 %/%2, Tu %3 ms</source>
        <translation>드라이버 자체 루프(모델): Ku %1 %/%2, Tu %3 ms</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="180"/>
        <source>Proposal: the rule&apos;s P × %1, Ti × %2; predicted overshoot %3 %, settling %4</source>
        <translation>제안: 규칙의 P × %1, Ti × %2; 예측 오버슈트 %3 %, 정정 %4</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="184"/>
        <source>not within the record</source>
        <translation>기록 시간 안에 없음</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="208"/>
        <source>Check after Accept: passed.</source>
        <translation>수락 후 확인: 통과.</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="209"/>
        <source>Check after Accept: FAILED. Reject writes back the gains the drive had.</source>
        <translation>수락 후 확인: 실패. 거부하면 드라이버의 이전 게인을 다시 씁니다.</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="171"/>
        <source>Model: K %1 %2/%, τ %3 ms, dead time %4 ms</source>
        <translation>모델: K %1 %2/%, τ %3 ms, 무효 시간 %4 ms</translation>
    </message>
</context>
<context>
    <name>opentop::BackupCommand</name>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="37"/>
        <source>Save every setting of drives to a backup file (written only when all were read)</source>
        <translation>드라이버의 모든 설정을 백업 파일로 저장합니다(모두 읽은 경우에만 저장)</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="43"/>
        <source>The backup file to write (replaced atomically).</source>
        <translation>저장할 백업 파일(원자적으로 교체).</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="44"/>
        <source>FILE</source>
        <translation>FILE</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="46"/>
        <source>Every drive the connection knows (a simulated bus), or every drive a scan finds.</source>
        <translation>연결이 알고 있는 모든 드라이버(시뮬레이션 버스) 또는 스캔으로 찾은 모든 드라이버.</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="54"/>
        <source>error: name the machine numbers, or give --all: backup ID... -o FILE</source>
        <translation>오류: 국번을 지정하거나 --all을 주십시오: backup ID... -o FILE</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="63"/>
        <location filename="../cli/BackupCommand.cpp" line="245"/>
        <location filename="../cli/BackupCommand.cpp" line="251"/>
        <source>error: %1</source>
        <translation>오류: %1</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="72"/>
        <source>scanning the bus for drives…</source>
        <translation>버스에서 드라이버를 스캔하는 중…</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="87"/>
        <source>warning: machine number %1 answered, but its identification failed: it is not backed up; name it to try again (backup %1 -o FILE).</source>
        <translation>경고: 국번 %1이(가) 응답했지만 식별에 실패했습니다: 백업하지 않았습니다. 이 국번을 지정해 다시 시도하십시오(backup %1 -o FILE).</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="108"/>
        <source>error: the port %1 was lost while reading %2 (%3)</source>
        <translation>오류: %2을(를) 읽는 중 포트 %1이(가) 끊어졌습니다(%3)</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="112"/>
        <location filename="../cli/BackupCommand.cpp" line="247"/>
        <source>nothing written to %1</source>
        <translation>%1에 아무것도 저장하지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="120"/>
        <source>error: give the file to write: backup ID... -o FILE</source>
        <translation>오류: 저장할 파일을 지정하십시오: backup ID... -o FILE</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="124"/>
        <source>error: %1; nothing read</source>
        <translation>오류: %1; 아무것도 읽지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="136"/>
        <source>interrupted: nothing written</source>
        <translation>중단됨: 아무것도 저장하지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="140"/>
        <source>error: no drive answers on %1; nothing written</source>
        <translation>오류: %1에서 응답하는 드라이버가 없습니다. 아무것도 저장하지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="166"/>
        <source>machine number %1</source>
        <translation>국번 %1</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="226"/>
        <source>interrupted while reading machine number %1: nothing written</source>
        <translation>국번 %1을(를) 읽는 중 중단됨: 아무것도 저장하지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="188"/>
        <source>%1: %2 settings read in %3 requests, %4 ms</source>
        <translation>%1: 설정 %2개를 요청 %3회로 읽음, %4 ms</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="196"/>
        <source>%1: reading failed, %2 of %3 settings read (%4 requests, %5 ms)</source>
        <translation>%1: 읽기 실패, 설정 %3개 중 %2개 읽음(요청 %4회, %5 ms)</translation>
    </message>
</context>
<context>
    <name>opentop::BackupDialog</name>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="29"/>
        <source>&amp;Cancel</source>
        <translation>취소(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="30"/>
        <source>&amp;Save the drives read</source>
        <translation>읽은 드라이버 저장(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="31"/>
        <source>C&amp;lose</source>
        <translation>닫기(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="44"/>
        <source>Back up drives</source>
        <translation>드라이버 백업</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="46"/>
        <source>Machine number</source>
        <translation>국번</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="46"/>
        <source>Model</source>
        <translation>모델</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="46"/>
        <source>Progress</source>
        <translation>진행</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="46"/>
        <source>Result</source>
        <translation>결과</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="54"/>
        <source>Save only the drives that were read; the others are left out</source>
        <translation>읽은 드라이버만 저장합니다. 나머지는 제외됩니다</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="56"/>
        <source>Stop after the drive being read</source>
        <translation>지금 읽고 있는 드라이버까지 읽고 멈춥니다</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="84"/>
        <source>Nothing was read: %1.</source>
        <translation>아무것도 읽지 않았습니다: %1.</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="107"/>
        <source>Waiting</source>
        <translation>대기 중</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="111"/>
        <source>%v of %m drives</source>
        <translation>드라이버 %m대 중 %v대</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/BackupDialog.cpp" line="112"/>
        <source>Reading the settings of %n drive(s)…</source>
        <translation>
            <numerusform>드라이버 %n대의 설정을 읽는 중…</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="123"/>
        <source>Stopping after the drive being read…</source>
        <translation>지금 읽고 있는 드라이버까지 읽고 멈추는 중…</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="161"/>
        <source>Not read (cancelled)</source>
        <translation>읽지 않음(취소됨)</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="37"/>
        <source>drive %1: not identified, nothing read</source>
        <translation>드라이버 %1: 식별되지 않아 아무것도 읽지 않았습니다</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="166"/>
        <source>Not identified</source>
        <translation>식별 안 됨</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="139"/>
        <source>Reading…</source>
        <translation>읽는 중…</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/BackupDialog.cpp" line="153"/>
        <source>%n setting(s) read in %1 ms</source>
        <translation>
            <numerusform>설정 %n개 읽음, %1 ms</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="167"/>
        <source>Value not allowed</source>
        <translation>허용되지 않는 값</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="168"/>
        <source>Read failed</source>
        <translation>읽기 실패</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="184"/>
        <source>Not read: drive(s) %1. Nothing has been saved yet.</source>
        <translation>읽지 못한 드라이버: %1. 아직 아무것도 저장하지 않았습니다.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/BackupDialog.cpp" line="190"/>
        <source>Save the %n drive(s) that were read?</source>
        <translation>
            <numerusform>읽은 드라이버 %n대를 저장하시겠습니까?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/BackupDialog.cpp" line="214"/>
        <source>Saved %n drive(s) to %1.</source>
        <translation>
            <numerusform>드라이버 %n대를 %1에 저장했습니다.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="220"/>
        <source>Left out (not read): drive(s) %1.</source>
        <translation>제외됨(읽지 못함): 드라이버 %1.</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="224"/>
        <source>Could not save %1: %2</source>
        <translation>%1을(를) 저장할 수 없습니다: %2</translation>
    </message>
</context>
<context>
    <name>opentop::BackupFile</name>
    <message>
        <location filename="../model/files/BackupFile.cpp" line="309"/>
        <source>%1 is larger than %2 MB, the most a backup file may hold (a backup of 247 drives is far smaller); not a backup file</source>
        <translation>%1이(가) 백업 파일의 최대 크기 %2 MB보다 큽니다(드라이버 247대의 백업도 훨씬 작음). 백업 파일이 아닙니다</translation>
    </message>
</context>
<context>
    <name>opentop::BackupFileParser</name>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="49"/>
        <source>not a JSON file: %1 at byte %2</source>
        <translation>JSON 파일이 아닙니다: 바이트 %2에서 %1</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="53"/>
        <source>not an OpenTOP backup file: the JSON is not an object</source>
        <translation>OpenTOP 백업 파일이 아닙니다: JSON이 객체가 아닙니다</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="63"/>
        <source>&quot;created&quot; is not an ISO 8601 date and time</source>
        <translation>&quot;created&quot;가 ISO 8601 날짜·시간이 아닙니다</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="75"/>
        <source>the file holds no drives (&quot;devices&quot; must be a non-empty list)</source>
        <translation>파일에 드라이버가 없습니다(&quot;devices&quot;는 비어 있지 않은 목록이어야 합니다)</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="82"/>
        <source>%1: not a drive</source>
        <translation>%1: 드라이버가 아닙니다</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="84"/>
        <source>machine number %1 appears twice</source>
        <translation>국번 %1이(가) 두 번 나옵니다</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="98"/>
        <source>not an OpenTOP backup file (&quot;format&quot; is &quot;%1&quot;, not &quot;%2&quot;)</source>
        <translation>OpenTOP 백업 파일이 아닙니다(&quot;format&quot;이 &quot;%2&quot;이(가) 아니라 &quot;%1&quot;입니다)</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="100"/>
        <source>not an OpenTOP backup file (no &quot;format&quot;: &quot;%1&quot;)</source>
        <translation>OpenTOP 백업 파일이 아닙니다(&quot;format&quot;: &quot;%1&quot; 없음)</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="105"/>
        <source>&quot;formatVersion&quot; must be a whole number from 1</source>
        <translation>&quot;formatVersion&quot;은 1 이상의 정수여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="107"/>
        <source>written by a newer OpenTOP (format version %1); this version reads format version %2</source>
        <translation>더 새로운 OpenTOP에서 저장한 파일입니다(형식 버전 %1). 이 버전은 형식 버전 %2을(를) 읽습니다</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="113"/>
        <source>the file has no checksum (&quot;checksum&quot;: &quot;sha256:…&quot;); it was not written by OpenTOP or was changed afterwards</source>
        <translation>파일에 체크섬이 없습니다(&quot;checksum&quot;: &quot;sha256:…&quot;). OpenTOP에서 저장한 파일이 아니거나 저장 후 변경되었습니다</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="118"/>
        <source>the file was changed after it was written (checksum mismatch)</source>
        <translation>파일이 저장된 후 변경되었습니다(체크섬 불일치)</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="128"/>
        <source>%1: &quot;slave&quot; must be a machine number 1–247</source>
        <translation>%1: &quot;slave&quot;는 국번 1–247이어야 합니다</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="129"/>
        <source>%1 (machine number %2)</source>
        <translation>%1 (국번 %2)</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="133"/>
        <source>%1: unknown family &quot;%2&quot;; known: %3</source>
        <translation>%1: 알 수 없는 제품군 &quot;%2&quot;; 알려진 제품군: %3</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="138"/>
        <source>%1: &quot;variant&quot; must be text or null</source>
        <translation>%1: &quot;variant&quot;는 텍스트 또는 null이어야 합니다</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="143"/>
        <source>%1: unknown variant &quot;%2&quot; of family %3; known: %4</source>
        <translation>%1: 제품군 %3의 알 수 없는 기종 &quot;%2&quot;; 알려진 기종: %4</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="145"/>
        <source>none</source>
        <translation>없음</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="153"/>
        <source>%1: &quot;machineName&quot; must be text</source>
        <translation>%1: &quot;machineName&quot;은(는) 텍스트여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="155"/>
        <source>%1: &quot;machineName&quot;: %2</source>
        <translation>%1: &quot;machineName&quot;: %2</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="160"/>
        <source>%1: &quot;parameters&quot; must be a list</source>
        <translation>%1: &quot;parameters&quot;는 목록이어야 합니다</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="180"/>
        <source>%1: no &quot;name&quot;</source>
        <translation>%1: &quot;name&quot; 없음</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="183"/>
        <source>%1 %2: &quot;registers&quot; must be a list</source>
        <translation>%1 %2: &quot;registers&quot;는 목록이어야 합니다</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="187"/>
        <source>%1 %2: registers must be numbers 0–65535</source>
        <translation>%1 %2: 레지스터 값은 0–65535의 숫자여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="193"/>
        <source>%1 %2: address &quot;%3&quot;, but the %4 profile has it at %5</source>
        <translation>%1 %2: 주소가 &quot;%3&quot;이지만 %4 프로파일에서는 %5입니다</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="218"/>
        <source>%1: %2: &quot;value&quot; %3 does not match its registers (%4)</source>
        <translation>%1: %2: &quot;value&quot; %3이(가) 레지스터 값(%4)과 일치하지 않습니다</translation>
    </message>
</context>
<context>
    <name>opentop::BackupValidator</name>
    <message>
        <location filename="../model/files/BackupValidator.cpp" line="16"/>
        <source>unknown parameter &quot;%1&quot;: the %2 profile has no such setting</source>
        <translation>알 수 없는 파라미터 &quot;%1&quot;: %2 프로파일에 그런 설정이 없습니다</translation>
    </message>
    <message>
        <location filename="../model/files/BackupValidator.cpp" line="21"/>
        <source>&quot;%1&quot; is not a setting that backups hold</source>
        <translation>&quot;%1&quot;은(는) 백업에 포함되는 설정이 아닙니다</translation>
    </message>
    <message>
        <location filename="../model/files/BackupValidator.cpp" line="25"/>
        <source>&quot;%1&quot; appears twice</source>
        <translation>&quot;%1&quot;이(가) 두 번 나옵니다</translation>
    </message>
    <message>
        <location filename="../model/files/BackupValidator.cpp" line="28"/>
        <source>%1: %2 registers, but the parameter has %3</source>
        <translation>%1: 레지스터 %2개이지만 파라미터는 %3개입니다</translation>
    </message>
    <message>
        <location filename="../model/files/BackupValidator.cpp" line="53"/>
        <source>%1: its allowed values depend on %2, which the file does not hold</source>
        <translation>%1: 허용 값이 %2에 따라 달라지지만 파일에 그 값이 없습니다</translation>
    </message>
</context>
<context>
    <name>opentop::BackupViewer</name>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="24"/>
        <source>Backup file</source>
        <translation>백업 파일</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="35"/>
        <source>Parameter</source>
        <translation>파라미터</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="35"/>
        <source>Label</source>
        <translation>표시 이름</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="35"/>
        <source>Value</source>
        <translation>값</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="35"/>
        <source>Registers</source>
        <translation>레지스터</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="39"/>
        <source>&amp;Open…</source>
        <translation>열기(&amp;O)…</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="40"/>
        <source>Open another backup file</source>
        <translation>다른 백업 파일을 엽니다</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="41"/>
        <source>C&amp;lose</source>
        <translation>닫기(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="62"/>
        <source>%1: no such file</source>
        <translation>%1: 파일이 없습니다</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="68"/>
        <source>the file could not be read</source>
        <translation>파일을 읽을 수 없습니다</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="69"/>
        <source>Backup file %1</source>
        <translation>백업 파일 %1</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="77"/>
        <source>Open backup file</source>
        <translation>백업 파일 열기</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="78"/>
        <source>OpenTOP backups (*.json);;All files (*)</source>
        <translation>OpenTOP 백업 (*.json);;모든 파일 (*)</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="100"/>
        <source>File: %1</source>
        <translation>파일: %1</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="101"/>
        <source>Refused: %1</source>
        <translation>거부됨: %1</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="116"/>
        <source>, %1 bit/s, parity %2, %3 stop bit(s)</source>
        <translation>, %1 bit/s, 패리티 %2, 스톱 비트 %3</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="118"/>
        <source>File: %1
Written by %2 on %3 (UTC)
Read from: %4
Drives: %5</source>
        <translation>파일: %1
저장: %2, %3 (UTC)
읽은 곳: %4
드라이버: %5</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="127"/>
        <source>%1 %2, firmware %3</source>
        <translation>%1 %2, 펌웨어 %3</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="130"/>
        <source>(variant unknown)</source>
        <translation>(기종 알 수 없음)</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/BackupViewer.cpp" line="133"/>
        <source>%n setting(s)</source>
        <translation>
            <numerusform>설정 %n개</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::BarHideButton</name>
    <message>
        <location filename="../ui/widgets/BarHideButton.cpp" line="9"/>
        <source>Hide this bar</source>
        <translation>이 표시줄을 숨깁니다</translation>
    </message>
    <message>
        <location filename="../ui/widgets/BarHideButton.cpp" line="10"/>
        <source>Hide</source>
        <translation>숨기기</translation>
    </message>
</context>
<context>
    <name>opentop::BusDocks</name>
    <message>
        <location filename="../ui/main/BusDocks.cpp" line="28"/>
        <source>Traffic log</source>
        <translation>통신 로그</translation>
    </message>
    <message>
        <location filename="../ui/main/BusDocks.cpp" line="35"/>
        <source>Bus overview</source>
        <translation>버스 개요</translation>
    </message>
    <message>
        <location filename="../ui/main/BusDocks.cpp" line="36"/>
        <source>Trends</source>
        <translation>트렌드</translation>
    </message>
    <message>
        <location filename="../ui/main/BusDocks.cpp" line="37"/>
        <source>Communication groups</source>
        <translation>통신 그룹</translation>
    </message>
    <message>
        <location filename="../ui/main/BusDocks.cpp" line="40"/>
        <location filename="../ui/main/BusDocks.cpp" line="110"/>
        <source>Not connected</source>
        <translation>연결 안 됨</translation>
    </message>
</context>
<context>
    <name>opentop::BusDriveList</name>
    <message>
        <location filename="../cli/BusDriveList.cpp" line="11"/>
        <source>%1 s ago</source>
        <translation>%1초 전</translation>
    </message>
    <message>
        <location filename="../cli/BusDriveList.cpp" line="13"/>
        <source>%1 min ago</source>
        <translation>%1분 전</translation>
    </message>
    <message>
        <location filename="../cli/BusDriveList.cpp" line="15"/>
        <source>%1 h ago</source>
        <translation>%1시간 전</translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/BusDriveList.cpp" line="16"/>
        <source>%n day(s) ago</source>
        <translation>
            <numerusform>%n일 전</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../cli/BusDriveList.cpp" line="27"/>
        <source>the simulated bus&apos;s drives</source>
        <translation>시뮬레이션 버스의 드라이버</translation>
    </message>
    <message>
        <location filename="../cli/BusDriveList.cpp" line="30"/>
        <source>the drives last seen on %1</source>
        <translation>%1에서 마지막으로 본 드라이버</translation>
    </message>
    <message>
        <location filename="../cli/BusDriveList.cpp" line="31"/>
        <source>the drives the last scan of %1 found (%2, %3)</source>
        <translation>%1의 마지막 스캔에서 찾은 드라이버(%2, %3)</translation>
    </message>
    <message>
        <location filename="../cli/BusDriveList.cpp" line="38"/>
        <source>no list of the drives on the bus</source>
        <translation>버스의 드라이버 목록 없음</translation>
    </message>
</context>
<context>
    <name>opentop::BusGroups</name>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="109"/>
        <source>machine number %1 is the parent of communication group %1: what is sent to it is also executed by %2 (children do not reply)</source>
        <translation>국번 %1은(는) 통신 그룹 %1의 부모입니다: 이 국번으로 보내는 내용은 %2에서도 실행됩니다(자식은 응답하지 않음)</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="127"/>
        <location filename="../model/bus/BusGroups.cpp" line="136"/>
        <source>%1 and %2</source>
        <translation>%1 및 %2</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="145"/>
        <source>This also reaches machine number %1 (the child of communication group %2; it executes it without replying).</source>
        <translation>이 내용은 국번 %1에도 전달됩니다(통신 그룹 %2의 자식; 응답 없이 실행함).</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="149"/>
        <source>This also reaches machine numbers %1 (the children of communication group %2; they execute it without replying).</source>
        <translation>이 내용은 국번 %1에도 전달됩니다(통신 그룹 %2의 자식; 응답 없이 실행함).</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="159"/>
        <source>child of %1</source>
        <translation>%1의 자식</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="162"/>
        <source>parent of %1</source>
        <translation>%1의 부모</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="170"/>
        <source>machine number %1 is a child of %2 and itself a parent: a child must not be a group parent</source>
        <translation>국번 %1은(는) %2의 자식이면서 부모입니다: 자식은 그룹 부모가 될 수 없습니다</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="175"/>
        <source>machine number %1 is in communication group %2, but no drive %2 is known: frames to %2 reach %1 although nothing answers</source>
        <translation>국번 %1은(는) 통신 그룹 %2에 속해 있지만 드라이버 %2이(가) 알려져 있지 않습니다: 아무도 응답하지 않아도 %2(으)로 보낸 프레임이 %1에 전달됩니다</translation>
    </message>
</context>
<context>
    <name>opentop::BusLeaving</name>
    <message>
        <location filename="../ui/main/BusLeaving.cpp" line="68"/>
        <location filename="../ui/main/BusLeaving.cpp" line="88"/>
        <source>quit</source>
        <translation>종료</translation>
    </message>
    <message>
        <location filename="../ui/main/BusLeaving.cpp" line="77"/>
        <source>Unwritten changes</source>
        <translation>쓰지 않은 변경 사항</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/main/BusLeaving.cpp" line="78"/>
        <source>%n edit(s) have not been written to the drives. Quit and discard them?</source>
        <translation>
            <numerusform>드라이버에 쓰지 않은 편집이 %n개 있습니다. 버리고 종료하시겠습니까?</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::BusListMenu</name>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="30"/>
        <source>&amp;Name this machine…</source>
        <translation>이 기계에 이름 지정(&amp;N)…</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="36"/>
        <source>&amp;Identify again</source>
        <translation>다시 식별(&amp;I)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="47"/>
        <source>&amp;Remove from list</source>
        <translation>목록에서 제거(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="62"/>
        <source>Name of %1 (up to %2 characters; empty removes the name):</source>
        <translation>%1의 이름(최대 %2자, 비우면 이름 삭제):</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="69"/>
        <source>Name this machine</source>
        <translation>이 기계에 이름 지정</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="76"/>
        <source>Machine number %1 has no name now.</source>
        <translation>국번 %1은(는) 이제 이름이 없습니다.</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="77"/>
        <source>Machine number %1 is now named %2.</source>
        <translation>국번 %1의 이름이 이제 %2입니다.</translation>
    </message>
</context>
<context>
    <name>opentop::BusListModel</name>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="76"/>
        <source>Machine number: the drive&apos;s address on the bus (1–247)</source>
        <translation>국번: 버스에서 드라이브의 주소 (1–247)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="78"/>
        <source>The drive&apos;s MONITOR LED: red alarm, green ready, orange CW, sky blue CCW, purple external interrupt, blue memory or communication error, grey no answer</source>
        <translation>드라이버의 MONITOR LED: 빨강 알람, 초록 준비, 주황 CW, 하늘색 CCW, 보라 외부 인터럽트, 파랑 메모리 또는 통신 오류, 회색 응답 없음</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="85"/>
        <source>LED</source>
        <translation>LED</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="87"/>
        <source>No.</source>
        <translation>국번</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="91"/>
        <source>Family</source>
        <translation>제품군</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="93"/>
        <source>Model</source>
        <translation>모델</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="95"/>
        <source>Firmware</source>
        <translation>펌웨어</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="97"/>
        <source>State</source>
        <translation>상태</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="99"/>
        <source>Control priority</source>
        <translation>제어 우선순위</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="73"/>
        <source>How each drive&apos;s machine number is set on its switches:
%1</source>
        <translation>각 드라이버의 국번을 스위치로 설정하는 방법:
%1</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="89"/>
        <source>Switches</source>
        <translation>스위치</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="101"/>
        <source>Name</source>
        <translation>이름</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="113"/>
        <source>Two drives may share machine number %1 (%2): check the address switches of every drive on the line, give each drive its own number and restart its power; a bad termination or a swapped A/B pair also corrupts replies.</source>
        <translation>두 드라이버가 국번 %1(%2)을(를) 함께 쓰고 있을 수 있습니다: 라인의 모든 드라이버의 주소 스위치를 확인하고, 드라이버마다 다른 국번을 지정한 뒤 전원을 다시 켜십시오. 종단 저항 불량이나 A/B 반대 결선도 응답을 손상시킵니다.</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="134"/>
        <source>%1 at %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="135"/>
        <location filename="../ui/bus/BusListModel.cpp" line="136"/>
        <location filename="../ui/bus/BusListModel.cpp" line="140"/>
        <location filename="../ui/bus/BusListModel.cpp" line="142"/>
        <location filename="../ui/bus/BusListModel.cpp" line="148"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="139"/>
        <source>%1 — variant unknown</source>
        <translation>%1 — 기종 알 수 없음</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="142"/>
        <source>V%1</source>
        <translation>V%1</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="171"/>
        <source>Status light %1: %2 (%3)</source>
        <translation>상태등 %1: %2 (%3)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="175"/>
        <source>The drive&apos;s manual: %1</source>
        <translation>드라이버 매뉴얼: %1</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="178"/>
        <source>Status light grey: not live — %1</source>
        <translation>상태등 회색: 실시간 아님 — %1</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="186"/>
        <source>No name yet: Name… in the context menu (F2) names this machine</source>
        <translation>아직 이름이 없습니다: 컨텍스트 메뉴의 이름 지정…(F2)으로 이 기계에 이름을 붙입니다</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="187"/>
        <source>%1: the name given to this machine (F2 changes it)</source>
        <translation>%1: 이 기계에 붙인 이름(F2로 변경)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="190"/>
        <source>Requests to this drive go out at %1, its own line format, not the port&apos;s: the line is switched to it and back between transactions. Change it with Line format… in the context menu.</source>
        <translation>이 드라이브로 가는 요청은 포트의 형식이 아니라 드라이브 자체의 통신 형식 %1(으)로 나갑니다. 라인은 트랜잭션 사이에 그 형식으로 전환되었다가 다시 돌아옵니다. 컨텍스트 메뉴의 「통신 형식…」에서 변경하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="197"/>
        <source>The drive does not report its variant. Choose it from the context menu (Variant) so that values are checked against the right limits.</source>
        <translation>드라이버가 기종을 알려주지 않습니다. 올바른 한계값으로 값을 검사하도록 컨텍스트 메뉴(기종)에서 선택하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="206"/>
        <source>The drive takes run commands from its I/O terminals; test runs over the bus need communication priority.</source>
        <translation>드라이버가 I/O 단자로 운전 명령을 받고 있습니다. 버스를 통한 시운전에는 통신 우선이 필요합니다.</translation>
    </message>
</context>
<context>
    <name>opentop::BusMemory</name>
    <message>
        <location filename="../model/bus/BusMemory.cpp" line="79"/>
        <source>the simulated bus</source>
        <translation>시뮬레이션 버스</translation>
    </message>
</context>
<context>
    <name>opentop::BusOverview</name>
    <message>
        <location filename="../ui/bus/BusOverview.cpp" line="37"/>
        <source>Double-click a drive to open its pages.</source>
        <translation>드라이버를 더블클릭하면 해당 페이지가 열립니다.</translation>
    </message>
</context>
<context>
    <name>opentop::BusOverviewModel</name>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="133"/>
        <source>Drive</source>
        <translation>드라이버</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="135"/>
        <source>State</source>
        <translation>상태</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="137"/>
        <source>Speed</source>
        <translation>속도</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="139"/>
        <source>Display</source>
        <translation>표시</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="141"/>
        <source>Target</source>
        <translation>목표</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="143"/>
        <source>Load</source>
        <translation>부하</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="145"/>
        <source>Alarm</source>
        <translation>알람</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="147"/>
        <source>Last answer</source>
        <translation>마지막 응답</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="174"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="164"/>
        <source>connection lost; %1</source>
        <translation>연결 끊김; %1</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="166"/>
        <source>no answer: %1; %2</source>
        <translation>응답 없음: %1; %2</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="203"/>
        <source>none</source>
        <translation>없음</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="206"/>
        <source>active</source>
        <translation>발생 중</translation>
    </message>
</context>
<context>
    <name>opentop::BusPanel</name>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="35"/>
        <source>&amp;Scan</source>
        <translation>스캔(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="38"/>
        <source>A&amp;dd drive…</source>
        <translation>드라이버 추가(&amp;D)…</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="40"/>
        <source>Ca&amp;ncel</source>
        <translation>취소(&amp;N)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="50"/>
        <source>Ask every machine number of the range who answers</source>
        <translation>범위 안의 모든 국번에 응답 여부를 묻습니다</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="52"/>
        <source>&amp;from</source>
        <translation>시작(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="54"/>
        <source>&amp;to</source>
        <translation>끝(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="77"/>
        <source>Identify one machine number and add it to the list</source>
        <translation>국번 하나를 식별하여 목록에 추가합니다</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="82"/>
        <location filename="../ui/bus/BusPanel.cpp" line="221"/>
        <source>%v of %m</source>
        <translation>%m 중 %v</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="83"/>
        <source>Scan progress</source>
        <translation>스캔 진행</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="85"/>
        <source>Stop the scan after the request on the wire</source>
        <translation>전송 중인 요청이 끝나면 스캔을 멈춥니다</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="95"/>
        <source>Rescan at %1</source>
        <translation>%1(으)로 다시 스캔</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="135"/>
        <source>Drives on the bus</source>
        <translation>버스의 드라이버</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="151"/>
        <source>Name this machine…</source>
        <translation>이 기계에 이름 지정…</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="207"/>
        <source>%v of %m (machine number %1)</source>
        <translation>%m 중 %v (국번 %1)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="211"/>
        <source>Machine number %1 answered, identification failed: retrying (%2 of %3)… Polling waits until the scan is over.</source>
        <translation>국번 %1이(가) 응답했지만 식별에 실패했습니다: 재시도 중(%3회 중 %2회째)… 폴링은 스캔이 끝날 때까지 기다립니다.</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="223"/>
        <source>Scanning machine numbers %1–%2 on %3, %4 ms each… Polling waits until the scan is over.</source>
        <translation>%3에서 국번 %1–%2 스캔 중, 국번당 %4 ms… 폴링은 스캔이 끝날 때까지 기다립니다.</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="295"/>
        <source>If one is on this bus, add it with Add drive and its line format.</source>
        <translation>버스에 이런 드라이브가 있으면 「드라이브 추가」로 통신 형식과 함께 추가하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="300"/>
        <source>Machine number %1 answered, but its identification failed, also when asked again: add it by hand with Add drive…, or check its line settings and scan again.</source>
        <translation>국번 %1이(가) 응답했지만 다시 물어도 식별에 실패했습니다: [드라이버 추가…]로 직접 추가하거나, 통신 설정을 확인한 뒤 다시 스캔하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="243"/>
        <source>Cancelling after the request on the wire…</source>
        <translation>전송 중인 요청이 끝나면 취소합니다…</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="59"/>
        <source>Machine numbers 1–247, as set on each drive&apos;s switches:
%1</source>
        <translation>국번 1–247, 각 드라이버의 스위치 설정:
%1</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="261"/>
        <source>Did not answer the last scan.</source>
        <translation>마지막 스캔에서 응답하지 않았습니다.</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="267"/>
        <source>The scan stopped at machine number %1: %2</source>
        <translation>국번 %1에서 스캔이 멈췄습니다: %2</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/bus/BusPanel.cpp" line="272"/>
        <source>Scan cancelled after machine numbers %1–%2 (%3 of %4): %n drive(s) found.</source>
        <translation>
            <numerusform>국번 %1–%2 스캔 후 취소됨(%4 중 %3): 드라이버 %n대 발견.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/bus/BusPanel.cpp" line="280"/>
        <source>%n drive(s) found on machine numbers %1–%2 in %3 s.</source>
        <translation>
            <numerusform>국번 %1–%2에서 드라이버 %n대 발견(%3 s).</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="321"/>
        <source>Asking machine number %1…</source>
        <translation>국번 %1에 묻는 중…</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="326"/>
        <source>Machine number %1: %2 added.</source>
        <translation>국번 %1: %2 추가됨.</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="328"/>
        <source>Machine number %1: %2 %3</source>
        <translation>국번 %1: %2 %3</translation>
    </message>
    <message>
        <location filename="../ui/bus/VariantMenu.cpp" line="26"/>
        <source>&amp;Variant</source>
        <translation>기종(&amp;V)</translation>
    </message>
</context>
<context>
    <name>opentop::BusRecallBar</name>
    <message>
        <location filename="../ui/bus/BusRecallBar.cpp" line="21"/>
        <source>&amp;Scan the bus</source>
        <translation>버스 스캔(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusRecallBar.cpp" line="44"/>
        <source>Last time on %1: %2.</source>
        <translation>지난번 %1: %2.</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusRecallBar.cpp" line="46"/>
        <source>&amp;Restore the drive last seen</source>
        <translation>지난번 드라이버 복원(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusRecallBar.cpp" line="47"/>
        <source>&amp;Restore the %1 drives last seen</source>
        <translation>지난번 드라이버 %1대 복원(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusRecallBar.cpp" line="48"/>
        <source>Identify the drives at these machine numbers again, with the variants set last time</source>
        <translation>지난번에 설정한 기종으로 이 국번들의 드라이버를 다시 식별합니다</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusRecallBar.cpp" line="62"/>
        <source>No drive is known on %1 yet. Scan the bus to find the drives.</source>
        <translation>%1에서 아직 알려진 드라이버가 없습니다. 버스를 스캔하여 드라이버를 찾으십시오.</translation>
    </message>
</context>
<context>
    <name>opentop::BusRestore</name>
    <message>
        <location filename="../model/files/BusRestore.cpp" line="26"/>
        <source>machine number %1 is not a drive on the bus</source>
        <translation>국번 %1은(는) 버스에 있는 드라이버가 아닙니다</translation>
    </message>
    <message>
        <location filename="../model/files/BusRestore.cpp" line="97"/>
        <source>not attempted</source>
        <translation>시도 안 함</translation>
    </message>
</context>
<context>
    <name>opentop::BusScanner</name>
    <message>
        <location filename="../model/bus/BusScanner.cpp" line="152"/>
        <source>garbled replies twice (%1): two drives probably share machine number %2; check their address switches (%3)</source>
        <translation>손상된 응답 2회(%1): 두 드라이버가 국번 %2을(를) 함께 쓰고 있을 가능성이 큽니다. 주소 스위치를 확인하십시오(%3)</translation>
    </message>
    <message>
        <location filename="../model/bus/BusScanner.cpp" line="158"/>
        <source>answers, but none of the device profiles matches (%1)</source>
        <translation>응답은 있지만 일치하는 장치 프로파일이 없습니다(%1)</translation>
    </message>
    <message>
        <location filename="../model/bus/BusScanner.cpp" line="171"/>
        <source>answered, but its identification read got no reply (%1), also when asked %2 more times: add it by hand, or scan with a longer wait</source>
        <translation>응답은 있지만 식별 읽기에 응답이 없습니다(%1). %2번 더 물어도 마찬가지입니다: 직접 추가하거나 대기 시간을 늘려 다시 스캔하십시오</translation>
    </message>
    <message>
        <location filename="../model/bus/BusScanner.cpp" line="243"/>
        <source>answered late at first (after the %1 ms wait); a longer wait makes scans of this bus reliable</source>
        <translation>처음에 늦게 응답했습니다(%1 ms 대기 후). 대기 시간을 늘리면 이 버스의 스캔이 안정됩니다</translation>
    </message>
</context>
<context>
    <name>opentop::BusSpec</name>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="57"/>
        <source>&quot;%1&quot;: the braces do not pair; a drive&apos;s defects are written in braces after its number, e.g. dbu200@3{firmware=1.4,stall}</source>
        <translation>&quot;%1&quot;: 중괄호 짝이 맞지 않습니다. 드라이버의 결함은 번호 뒤 중괄호 안에 씁니다. 예: dbu200@3{firmware=1.4,stall}</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="62"/>
        <source>empty device list; write TYPE@ID[,TYPE@ID...], e.g. dbu200@1,dcpid@7 (types: %1)</source>
        <translation>장치 목록이 비어 있습니다. TYPE@ID[,TYPE@ID...] 형식으로 쓰십시오. 예: dbu200@1,dcpid@7 (유형: %1)</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="70"/>
        <source>&quot;%1&quot;: the defects in braces end the item, e.g. dbu200@3{stall}</source>
        <translation>&quot;%1&quot;: 중괄호 안의 결함은 항목 끝에 씁니다. 예: dbu200@3{stall}</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="78"/>
        <source>&quot;%1&quot;: write TYPE@ID or TYPE@FIRST-LAST, e.g. dbu200@1</source>
        <translation>&quot;%1&quot;: TYPE@ID 또는 TYPE@FIRST-LAST 형식으로 쓰십시오. 예: dbu200@1</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="83"/>
        <source>&quot;%1&quot;: unknown device type &quot;%2&quot;; known types: %3</source>
        <translation>&quot;%1&quot;: 알 수 없는 장치 유형 &quot;%2&quot;; 알려진 유형: %3</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="90"/>
        <source>&quot;%1&quot;: the machine number must be a number or a range such as 1-16</source>
        <translation>&quot;%1&quot;: 국번은 숫자 또는 1-16 같은 범위여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="94"/>
        <source>&quot;%1&quot;: machine number %2 is outside %3–%4 for %5</source>
        <translation>&quot;%1&quot;: 국번 %2이(가) %5의 범위 %3–%4을(를) 벗어납니다</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="101"/>
        <source>machine number %1 is given twice</source>
        <translation>국번 %1이(가) 두 번 지정되었습니다</translation>
    </message>
</context>
<context>
    <name>opentop::CertificateHtml</name>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="48"/>
        <source>PASS</source>
        <translation>합격</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="50"/>
        <location filename="../model/eol/CertificateHtml.cpp" line="144"/>
        <source>FAIL</source>
        <translation>불합격</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="52"/>
        <source>ABORTED</source>
        <translation>중지됨</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="54"/>
        <source>STATION ERROR</source>
        <translation>스테이션 오류</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="56"/>
        <source>INTERRUPTED</source>
        <translation>중단됨</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="58"/>
        <source>NOT FINISHED</source>
        <translation>미완료</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="71"/>
        <source>none</source>
        <translation>없음</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="78"/>
        <source>End-of-line test certificate</source>
        <translation>출하 검사 성적서</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="81"/>
        <source>Serial number</source>
        <translation>시리얼 번호</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="82"/>
        <location filename="../model/eol/CertificateHtml.cpp" line="148"/>
        <source>Recipe</source>
        <translation>레시피</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="82"/>
        <source>%1, revision %2</source>
        <translation>%1, 개정 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="83"/>
        <source>Recipe checksum</source>
        <translation>레시피 체크섬</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="84"/>
        <source>Recipe approved by</source>
        <translation>레시피 승인자</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="85"/>
        <source>not approved (station without users)</source>
        <translation>승인 없음(사용자가 없는 스테이션)</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="86"/>
        <source>%1 (approval %2)</source>
        <translation>%1(승인 %2)</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="87"/>
        <source>Station</source>
        <translation>스테이션</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="88"/>
        <source>Operator</source>
        <translation>작업자</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="89"/>
        <location filename="../model/eol/CertificateHtml.cpp" line="148"/>
        <source>Attempt</source>
        <translation>검사 회차</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="90"/>
        <source>%1 (tests of this serial under this recipe)</source>
        <translation>%1회차 (이 레시피에서 이 시리얼의 검사 차수)</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="91"/>
        <source>not counted (recorded before attempts were)</source>
        <translation>집계 안 됨 (검사 회차를 기록하기 전의 기록)</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="92"/>
        <location filename="../model/eol/CertificateHtml.cpp" line="148"/>
        <source>Started</source>
        <translation>시작</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="93"/>
        <source>Ended</source>
        <translation>종료</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="94"/>
        <source>Record</source>
        <translation>기록</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="103"/>
        <source>First failure:</source>
        <translation>첫 불합격 항목:</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/eol/CertificateHtml.cpp" line="121"/>
        <source>This serial failed %n earlier test(s); they are listed below.</source>
        <translation>
            <numerusform>이 시리얼은 이전 검사에서 %n회 불합격했습니다. 아래에 그 목록이 있습니다.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="124"/>
        <source>Drives</source>
        <translation>드라이버</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="125"/>
        <source>Machine number</source>
        <translation>국번</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="125"/>
        <source>Model</source>
        <translation>모델</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="125"/>
        <source>Variant</source>
        <translation>기종</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="125"/>
        <source>Firmware</source>
        <translation>펌웨어</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="125"/>
        <source>How known</source>
        <translation>확인 방법</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="130"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="133"/>
        <source>Settings</source>
        <translation>설정</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="133"/>
        <location filename="../model/eol/CertificateHtml.cpp" line="141"/>
        <source>Drive</source>
        <translation>드라이버</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="133"/>
        <source>Setting</source>
        <translation>설정</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="133"/>
        <location filename="../model/eol/CertificateHtml.cpp" line="141"/>
        <source>Value</source>
        <translation>값</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="133"/>
        <source>Written</source>
        <translation>쓰기</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="134"/>
        <source>Read back</source>
        <translation>다시 읽은 값</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="134"/>
        <source>Verified</source>
        <translation>검증</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="137"/>
        <source>written</source>
        <translation>쓰기 완료</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="137"/>
        <source>already set</source>
        <translation>이미 설정됨</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="138"/>
        <source>yes</source>
        <translation>예</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="138"/>
        <source>NO</source>
        <translation>아니요</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="140"/>
        <source>Measurements</source>
        <translation>측정</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="141"/>
        <source>Step</source>
        <translation>단계</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="141"/>
        <source>Quantity</source>
        <translation>측정 항목</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="141"/>
        <source>Limits</source>
        <translation>한계값</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="141"/>
        <location filename="../model/eol/CertificateHtml.cpp" line="148"/>
        <source>Verdict</source>
        <translation>판정</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="144"/>
        <source>pass</source>
        <translation>합격</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="147"/>
        <source>Earlier tests of this serial</source>
        <translation>이 시리얼의 이전 검사</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="148"/>
        <source>Reason</source>
        <translation>원인</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="150"/>
        <source>%1 rev. %2</source>
        <translation>%1 개정 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="151"/>
        <source>–</source>
        <translation>–</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="161"/>
        <source>Bus traffic around the failure</source>
        <translation>불합격 전후의 버스 통신</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="176"/>
        <source>read from the drive</source>
        <translation>드라이버에서 읽음</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="178"/>
        <source>proven by the variant probe</source>
        <translation>기종 확인으로 입증됨</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="180"/>
        <source>confirmed by a person</source>
        <translation>사람이 확인함</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="182"/>
        <source>ASSUMED, not proven</source>
        <translation>추정, 확인되지 않음</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="186"/>
        <location filename="../model/eol/CertificateHtml.cpp" line="192"/>
        <source>not known</source>
        <translation>알 수 없음</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="194"/>
        <source>%1 (assumed)</source>
        <translation>%1 (추정)</translation>
    </message>
</context>
<context>
    <name>opentop::CertificatePdf</name>
    <message>
        <location filename="../report/CertificatePdf.cpp" line="26"/>
        <source>End-of-line certificate %1</source>
        <translation>출하 검사 성적서 %1</translation>
    </message>
    <message>
        <location filename="../report/CertificatePdf.cpp" line="57"/>
        <source>%1 · %2 · page %3 of %4</source>
        <translation>%1 · %2 · %4쪽 중 %3쪽</translation>
    </message>
</context>
<context>
    <name>opentop::CliApp</name>
    <message>
        <location filename="../cli/CliApp.cpp" line="74"/>
        <source>Usage: %1 [options] COMMAND [arguments]

Commissioning tool for RS-485 Modbus-RTU motor drives.

Commands:
</source>
        <translation>사용법: %1 [옵션] COMMAND [인수]

RS-485 Modbus-RTU 모터 드라이버용 커미셔닝 도구.

명령:
</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="79"/>
        <source>
Connection (every command that talks to drives):
  --port PATH | --tcp HOST:PORT | --sim SPEC
  --family F  --baud N  --parity N|E|O  --stop-bits N  --timeout MS  --retries N
  Defaults follow the family: dbu 19200 8N1, dcpid 9600 8E1; --timeout 200,
  --retries 3 (2 more while the line is noisy: a request needed a retry lately).
  Serial port only: --rs485 off|auto|kernel|rts (who switches the RS-485
  direction; off: the adapter), --rts-polarity high|low, --rts-delay US,
  --low-latency on|off (default on). scan says what the driver accepted.
Output: --json  --trace  --variant VARIANT  --lang CODE
Groups: before a write or command, the communication group of the drives on the
bus is read: --bus-drives LIST (or OPENTOP_BUS_DRIVES), else the drives the last
scan of this connection found (here or in the window); with neither, a write to a
drive that can be a group parent is refused unless --no-group-check

Exit codes: 0 success, 1 communication failure, 2 usage, 3 invalid value or file
(nothing written), 4 verification mismatch or a drive that did not stop,
5 eol run FAIL, 6 eol run station error (no verdict on the unit),
130 interrupted by Ctrl-C, SIGTERM or SIGHUP (what was done is reported).

&quot;%1 help COMMAND&quot; shows a command&apos;s options.
</source>
        <translation>
연결 (드라이버와 통신하는 모든 명령):
  --port PATH | --tcp HOST:PORT | --sim SPEC
  --family F  --baud N  --parity N|E|O  --stop-bits N  --timeout MS  --retries N
  기본값은 제품군에 따름: dbu 19200 8N1, dcpid 9600 8E1; --timeout 200,
  --retries 3 (라인에 노이즈가 있으면(최근 재시도가 필요했던 요청이 있으면) 2회 추가).
  시리얼 포트 전용: --rs485 off|auto|kernel|rts (RS-485 송수신 방향을
  누가 전환하는지; off: 어댑터), --rts-polarity high|low, --rts-delay US,
  --low-latency on|off (기본값 on). scan이 시리얼 드라이버가 받아들인 설정을 표시합니다.
출력: --json  --trace  --variant VARIANT  --lang CODE
그룹: 쓰기나 명령 전에 버스에 있는 드라이버의 통신 그룹을 읽습니다: --bus-drives LIST
(또는 OPENTOP_BUS_DRIVES), 없으면 이 연결의 마지막 스캔에서 찾은 드라이버(여기 또는 창에서);
둘 다 없으면 그룹 부모일 수 있는 드라이버에 대한 쓰기는 --no-group-check 없이는 거부됩니다

종료 코드: 0 성공, 1 통신 실패, 2 사용법 오류, 3 잘못된 값 또는 파일
(아무것도 쓰지 않음), 4 검증 불일치 또는 정지하지 않은 드라이버 있음,
5 eol run 불합격, 6 eol run 스테이션 오류(제품 판정 없음),
130 Ctrl-C, SIGTERM 또는 SIGHUP으로 중단됨(수행한 작업은 보고함).

&quot;%1 help COMMAND&quot;로 명령의 옵션을 볼 수 있습니다.
</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="125"/>
        <source>note: standard output could not be written (closed early, or the disk is full): what the command printed there is lost; the work itself ran to its end and exit status %1 says how it ended</source>
        <translation>참고: 표준 출력에 쓸 수 없습니다(일찍 닫혔거나 디스크가 가득 참). 명령이 그곳에 출력한 내용은 손실되었습니다. 작업 자체는 끝까지 실행되었으며 종료 상태 %1이(가) 결과를 나타냅니다</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="190"/>
        <location filename="../cli/CliApp.cpp" line="245"/>
        <source>Try &quot;%1 --help&quot;.</source>
        <translation>&quot;%1 --help&quot;를 실행해 보십시오.</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="210"/>
        <source>%1: unknown command &quot;%2&quot;; commands: </source>
        <translation>%1: 알 수 없는 명령 &quot;%2&quot;; 명령: </translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="219"/>
        <source>Usage: %1 [options] %2
%3
</source>
        <translation>사용법: %1 [옵션] %2
%3
</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="233"/>
        <source>%1 %2: --%3 is not an option of this command; see &quot;%1 help %2&quot;</source>
        <translation>%1 %2: --%3은(는) 이 명령의 옵션이 아닙니다. &quot;%1 help %2&quot;를 참조하십시오</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="244"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>opentop::CliContext</name>
    <message>
        <location filename="../cli/CliContext.cpp" line="127"/>
        <location filename="../cli/CliContext.cpp" line="141"/>
        <location filename="../cli/CliContext.cpp" line="149"/>
        <source>error: %1</source>
        <translation>오류: %1</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="154"/>
        <source>serial line: %1</source>
        <translation>시리얼 라인: %1</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="177"/>
        <source>%1 &quot;%2&quot;: %3</source>
        <translation>%1 &quot;%2&quot;: %3</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="289"/>
        <source>machine number %1: no connection</source>
        <translation>국번 %1: 연결 없음</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="294"/>
        <source>machine number %1: %2%3</source>
        <translation>국번 %1: %2%3</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="352"/>
        <source>--variant %1: &quot;%2&quot; is not a machine number 1–247</source>
        <translation>--variant %1: &quot;%2&quot;은(는) 국번 1–247이 아닙니다</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="356"/>
        <source>--variant %1: &quot;%2&quot; is not a drive variant; use one of %3</source>
        <translation>--variant %1: &quot;%2&quot;은(는) 드라이버 기종이 아닙니다. 다음 중 하나를 사용하십시오: %3</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="374"/>
        <source>&quot;%1&quot; is not a machine number 1–247 or a range such as 3-8</source>
        <translation>&quot;%1&quot;은(는) 국번 1–247 또는 3-8 같은 범위가 아닙니다</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="384"/>
        <source>no machine number given</source>
        <translation>국번이 지정되지 않았습니다</translation>
    </message>
</context>
<context>
    <name>opentop::CliIdentity</name>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="73"/>
        <source>Who does it (a user of the results database); the password comes from OPENTOP_PASSWORD or is asked on the terminal.</source>
        <translation>수행하는 사람(결과 데이터베이스의 사용자). 비밀번호는 OPENTOP_PASSWORD에서 가져오거나 터미널에서 묻습니다.</translation>
    </message>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="75"/>
        <source>NAME</source>
        <translation>이름</translation>
    </message>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="86"/>
        <source>error: no password: set %1 or run on a terminal</source>
        <translation>오류: 비밀번호가 없습니다: %1을(를) 설정하거나 터미널에서 실행하십시오</translation>
    </message>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="91"/>
        <source>Again: </source>
        <translation>다시 입력: </translation>
    </message>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="93"/>
        <source>error: the passwords differ; nothing was changed</source>
        <translation>오류: 비밀번호가 서로 다릅니다. 아무것도 변경하지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="104"/>
        <source>error: name who does it with --user NAME</source>
        <translation>오류: --user NAME으로 수행하는 사람을 지정하십시오</translation>
    </message>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="108"/>
        <source>Password for %1: </source>
        <translation>%1의 비밀번호: </translation>
    </message>
</context>
<context>
    <name>opentop::CodeEntry</name>
    <message>
        <location filename="../model/profile/CodeTable.cpp" line="10"/>
        <source>Alarm-Reset</source>
        <translation>Alarm-Reset</translation>
    </message>
    <message>
        <location filename="../model/profile/CodeTable.cpp" line="12"/>
        <source>power cycle</source>
        <translation>전원 재투입</translation>
    </message>
    <message>
        <location filename="../model/profile/CodeTable.cpp" line="14"/>
        <source>by itself</source>
        <translation>자동 해제</translation>
    </message>
    <message>
        <location filename="../model/profile/CodeTable.cpp" line="15"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location filename="../model/profile/CodeTable.cpp" line="24"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../model/profile/CodeTable.cpp" line="29"/>
        <source>What to do: %1</source>
        <translation>조치: %1</translation>
    </message>
</context>
<context>
    <name>opentop::CommLossArm</name>
    <message>
        <location filename="../model/eol/CommLossArm.cpp" line="29"/>
        <source>cannot read %1: %2</source>
        <translation>%1을(를) 읽을 수 없습니다: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/CommLossArm.cpp" line="40"/>
        <source>the communication-loss stop cannot be armed (%1 = %2 s): %3; the motor is not started without it</source>
        <translation>통신 두절 정지를 설정할 수 없습니다(%1 = %2 s): %3. 이 기능 없이 모터를 기동하지 않습니다</translation>
    </message>
</context>
<context>
    <name>opentop::CommandReadBack</name>
    <message>
        <location filename="../ui/run/CommandReadBack.cpp" line="43"/>
        <source>Read back after the command at %1:</source>
        <translation>%1 명령 후 다시 읽은 값:</translation>
    </message>
    <message>
        <location filename="../ui/run/CommandReadBack.cpp" line="46"/>
        <source>The motor is running.</source>
        <translation>모터가 운전 중입니다.</translation>
    </message>
    <message>
        <location filename="../ui/run/CommandReadBack.cpp" line="46"/>
        <source>The motor is stopped.</source>
        <translation>모터가 정지해 있습니다.</translation>
    </message>
    <message>
        <location filename="../ui/run/CommandReadBack.cpp" line="48"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../ui/run/CommandReadBack.cpp" line="50"/>
        <source>(not read: %1)</source>
        <translation>(읽지 않음: %1)</translation>
    </message>
    <message>
        <location filename="../ui/run/CommandReadBack.cpp" line="57"/>
        <source>The drives of its communication group, read after the command:</source>
        <translation>명령 후 읽은 통신 그룹의 드라이버:</translation>
    </message>
</context>
<context>
    <name>opentop::CompareCommand</name>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="36"/>
        <source>Show the settings that differ; A, B: a machine number, FILE or FILE:ID (exit 0 whether or not they differ)</source>
        <translation>서로 다른 설정을 표시합니다. A, B: 국번, FILE 또는 FILE:ID (차이 유무와 관계없이 종료 코드 0)</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="43"/>
        <source>Compare A with the profile&apos;s factory defaults; settings the manual gives no default for are listed, never counted as differences.</source>
        <translation>A를 프로파일의 공장 출하값과 비교합니다. 매뉴얼에 기본값이 없는 설정은 목록에 표시하지만 차이로 세지 않습니다.</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="70"/>
        <location filename="../cli/CompareCommand.cpp" line="87"/>
        <location filename="../cli/CompareCommand.cpp" line="146"/>
        <source>error: %1</source>
        <translation>오류: %1</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="64"/>
        <source>interrupted</source>
        <translation>중단됨</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="74"/>
        <source>drive %1</source>
        <translation>드라이버 %1</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="106"/>
        <source>error: %1 holds several drives (%2): name one as %1:ID</source>
        <translation>오류: %1에 드라이버가 여러 대 있습니다(%2): %1:ID 형식으로 하나를 지정하십시오</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="110"/>
        <source>error: %1 holds no drive with machine number %2; it holds %3</source>
        <translation>오류: %1에 국번 %2인 드라이버가 없습니다. 포함된 드라이버: %3</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="126"/>
        <source>error: compare A B, or compare A --defaults (A, B: a machine number, FILE or FILE:ID)</source>
        <translation>오류: compare A B 또는 compare A --defaults (A, B: 국번, FILE 또는 FILE:ID)</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="144"/>
        <source>factory defaults</source>
        <translation>공장 출하값</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="172"/>
        <source>A: %1 (%2)</source>
        <translation>A: %1 (%2)</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="175"/>
        <source>B: %1</source>
        <translation>B: %1</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="180"/>
        <source>parameter</source>
        <translation>파라미터</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="180"/>
        <source>A</source>
        <translation>A</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="180"/>
        <source>B</source>
        <translation>B</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="182"/>
        <location filename="../cli/CompareCommand.cpp" line="183"/>
        <source>(not held)</source>
        <translation>(포함 안 됨)</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="186"/>
        <source> in %1 settings compared</source>
        <translation> (설정 %1개 비교)</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="188"/>
        <source>no differences (%1 settings compared)</source>
        <translation>차이 없음(설정 %1개 비교)</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="195"/>
        <source>note: %1</source>
        <translation>참고: %1</translation>
    </message>
</context>
<context>
    <name>opentop::CompareDialog</name>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="33"/>
        <source>&amp;Differences only</source>
        <translation>차이만 표시(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="37"/>
        <source>Co&amp;mpare</source>
        <translation>비교(&amp;M)</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="39"/>
        <source>Compare settings</source>
        <translation>설정 비교</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="40"/>
        <source>Side A</source>
        <translation>A쪽</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="41"/>
        <source>Side B</source>
        <translation>B쪽</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="57"/>
        <location filename="../ui/files/CompareDialog.cpp" line="227"/>
        <source>Setting</source>
        <translation>설정</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="57"/>
        <location filename="../ui/files/CompareDialog.cpp" line="227"/>
        <source>Parameter</source>
        <translation>파라미터</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="57"/>
        <source>A</source>
        <translation>A</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="57"/>
        <source>B</source>
        <translation>B</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="63"/>
        <source>Filter by setting or parameter name</source>
        <translation>설정 이름 또는 파라미터 이름으로 필터</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="65"/>
        <source>Read the chosen sides and compare them (drives are read fresh)</source>
        <translation>선택한 양쪽을 읽어 비교합니다(드라이버는 새로 읽음)</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="78"/>
        <source>C&amp;lose</source>
        <translation>닫기(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="111"/>
        <source>%1 refused: %2</source>
        <translation>%1 거부됨: %2</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="125"/>
        <source>Reading…</source>
        <translation>읽는 중…</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="150"/>
        <source>side A</source>
        <translation>A쪽</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="150"/>
        <source>side B</source>
        <translation>B쪽</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="154"/>
        <source>Factory defaults</source>
        <translation>공장 출하값</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="161"/>
        <source>Choose a backup file and a drive in it for %1.</source>
        <translation>%1에 사용할 백업 파일과 그 안의 드라이버를 선택하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="165"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="175"/>
        <source>Choose an identified drive on the bus for %1.</source>
        <translation>%1에 사용할 버스의 식별된 드라이버를 선택하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="183"/>
        <source>%1: cannot read %2</source>
        <translation>%1: %2을(를) 읽을 수 없습니다</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="208"/>
        <source>Unknown family %1</source>
        <translation>알 수 없는 제품군 %1</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="227"/>
        <source>A: %1</source>
        <translation>A: %1</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="228"/>
        <source>B: %1</source>
        <translation>B: %1</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="229"/>
        <source>factory defaults (%1)</source>
        <translation>공장 출하값 (%1)</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="239"/>
        <source>(no documented default)</source>
        <translation>(문서화된 기본값 없음)</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="240"/>
        <location filename="../ui/files/CompareDialog.cpp" line="242"/>
        <source>(not held)</source>
        <translation>(포함 안 됨)</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/CompareDialog.cpp" line="258"/>
        <source>%n difference(s)</source>
        <translation>
            <numerusform>차이 %n건</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="259"/>
        <source> in %1 settings compared</source>
        <translation> (설정 %1개 비교)</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="262"/>
        <source>Note: %1</source>
        <translation>참고: %1</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="269"/>
        <source>No factory default documented (never counted as a difference): %1</source>
        <translation>문서화된 공장 출하값 없음(차이로 세지 않음): %1</translation>
    </message>
</context>
<context>
    <name>opentop::CompareSide</name>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="23"/>
        <source>Browse…</source>
        <translation>찾아보기…</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="27"/>
        <source>Drive on the bus</source>
        <translation>버스의 드라이버</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="28"/>
        <source>Drive in a backup file</source>
        <translation>백업 파일의 드라이버</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="30"/>
        <source>Factory defaults</source>
        <translation>공장 출하값</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="34"/>
        <source>Drive %1 (%2)</source>
        <translation>드라이버 %1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="41"/>
        <source>Backup file</source>
        <translation>백업 파일</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="46"/>
        <source>Source:</source>
        <translation>원본:</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="47"/>
        <source>Drive:</source>
        <translation>드라이버:</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="48"/>
        <source>File:</source>
        <translation>파일:</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="49"/>
        <source>Drive in file:</source>
        <translation>파일 안의 드라이버:</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="170"/>
        <source>Open backup file</source>
        <translation>백업 파일 열기</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="171"/>
        <source>OpenTOP backups (*.json);;All files (*)</source>
        <translation>OpenTOP 백업 (*.json);;모든 파일 (*)</translation>
    </message>
</context>
<context>
    <name>opentop::Comparer</name>
    <message>
        <location filename="../model/files/Comparer.cpp" line="15"/>
        <source>nothing to compare: %1 is a %2 drive, %3 a %4 drive</source>
        <translation>비교할 수 없습니다: %1은(는) %2 드라이버, %3은(는) %4 드라이버입니다</translation>
    </message>
    <message>
        <location filename="../model/files/Comparer.cpp" line="20"/>
        <source>the variants differ: %1 and %2</source>
        <translation>기종이 다릅니다: %1, %2</translation>
    </message>
    <message>
        <location filename="../model/files/Comparer.cpp" line="55"/>
        <source>factory defaults</source>
        <translation>공장 출하값</translation>
    </message>
</context>
<context>
    <name>opentop::ConnectionDialog</name>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="63"/>
        <source>Connect to a bus</source>
        <translation>버스에 연결</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="68"/>
        <source>&amp;Serial port</source>
        <translation>시리얼 포트(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="68"/>
        <source>Modbus &amp;TCP gateway</source>
        <translation>Modbus TCP 게이트웨이(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="69"/>
        <source>Si&amp;mulated bus</source>
        <translation>시뮬레이션 버스(&amp;M)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="85"/>
        <source>&amp;Advanced</source>
        <translation>고급(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="108"/>
        <source>&amp;Connect</source>
        <translation>연결(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="129"/>
        <source>&amp;Refresh</source>
        <translation>새로 고침(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="130"/>
        <source>List the serial ports again (after plugging in an adapter)</source>
        <translation>시리얼 포트 목록을 다시 불러옵니다(어댑터를 꽂은 후)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="135"/>
        <source>&amp;Port:</source>
        <translation>포트(&amp;P):</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="144"/>
        <source>Custom</source>
        <translation>사용자 지정</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="146"/>
        <source>%1 (%2 %3%4%5)</source>
        <translation>%1 (%2 %3%4%5)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="153"/>
        <source>Fills in the factory line settings of a drive family</source>
        <translation>드라이버 제품군의 공장 출하 통신 설정을 채웁니다</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="156"/>
        <source>&amp;Family defaults:</source>
        <translation>제품군 기본값(&amp;F):</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="160"/>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="293"/>
        <source>%1 bit/s</source>
        <translation>%1 bit/s</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="161"/>
        <source>&amp;Baud rate:</source>
        <translation>통신 속도(&amp;B):</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="163"/>
        <source>None (N)</source>
        <translation>없음 (N)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="164"/>
        <source>Even (E)</source>
        <translation>짝수 (E)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="165"/>
        <source>Odd (O)</source>
        <translation>홀수 (O)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="166"/>
        <source>P&amp;arity:</source>
        <translation>패리티(&amp;A):</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="168"/>
        <source>1 bit</source>
        <translation>1 비트</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="169"/>
        <source>2 bits</source>
        <translation>2 비트</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="170"/>
        <source>S&amp;top bits:</source>
        <translation>스톱 비트(&amp;T):</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="186"/>
        <source>e.g. 192.168.1.10</source>
        <translation>예: 192.168.1.10</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="187"/>
        <source>&amp;Host:</source>
        <translation>호스트(&amp;H):</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="190"/>
        <source>Modbus TCP uses port 502</source>
        <translation>Modbus TCP는 포트 502를 사용합니다</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="191"/>
        <source>TCP p&amp;ort:</source>
        <translation>TCP 포트(&amp;O):</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="203"/>
        <source>Device types and machine numbers: TYPE@NUMBER, comma separated. Types: %1</source>
        <translation>장치 유형과 국번: TYPE@NUMBER, 쉼표로 구분. 유형: %1</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="206"/>
        <source>&amp;Devices:</source>
        <translation>장치(&amp;D):</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="220"/>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="221"/>
        <source>How long to wait for each reply</source>
        <translation>각 응답을 기다리는 시간</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="222"/>
        <source>Response &amp;timeout:</source>
        <translation>응답 타임아웃(&amp;T):</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="225"/>
        <source>Extra attempts after a request got no valid reply</source>
        <translation>요청에 올바른 응답이 없을 때 추가로 시도하는 횟수</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="226"/>
        <source>R&amp;etries:</source>
        <translation>재시도(&amp;E):</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="333"/>
        <source>The device list is not valid.</source>
        <translation>장치 목록이 올바르지 않습니다.</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="26"/>
        <source>The port is in use by another program (named above where the system tells it): a terminal program, ModemManager, another OpenTOP window or an opentop-cli command. Close it, or disconnect the other window, and connect again. Nothing was sent on the port.</source>
        <translation>다른 프로그램이 포트를 사용 중입니다(시스템이 알려준 경우 위에 이름이 표시됨): 터미널 프로그램, ModemManager, 다른 OpenTOP 창 또는 opentop-cli 명령. 그 프로그램을 닫거나 다른 창의 연결을 해제한 뒤 다시 연결하십시오. 포트로는 아무것도 보내지 않았습니다.</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="33"/>
        <source>Your user may not open serial ports: add it to the dialout group with the command above, then log out and in again.</source>
        <translation>현재 사용자에게 시리얼 포트를 열 권한이 없습니다: 위 명령으로 dialout 그룹에 추가한 뒤 로그아웃했다가 다시 로그인하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="36"/>
        <source>Your user may not open serial ports. Add it to the dialout group:
    sudo usermod -aG dialout $USER
then log out and in again (the group applies to new sessions only).</source>
        <translation>현재 사용자에게 시리얼 포트를 열 권한이 없습니다. dialout 그룹에 추가하십시오:
    sudo usermod -aG dialout $USER
그런 다음 로그아웃했다가 다시 로그인하십시오(그룹은 새 세션에만 적용됨).</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="41"/>
        <source>The port %1 does not exist: the USB adapter may be unplugged or have come back under another name, or the path is mistyped. Plug it in, press Refresh and pick it from the list; for a pseudo-terminal check that the program serving it (opentop-sim, socat) still runs.</source>
        <translation>포트 %1이(가) 없습니다: USB 어댑터가 빠졌거나 다른 이름으로 다시 인식되었거나 경로를 잘못 입력했습니다. 어댑터를 꽂고 새로 고침을 누른 뒤 목록에서 선택하십시오. 가상 터미널(pty)이면 이를 제공하는 프로그램(opentop-sim, socat)이 아직 실행 중인지 확인하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="48"/>
        <source>The connection opened but no drive answered. Check that the baud rate, parity and stop bits (%1) match the drives&apos; settings (DBU: 19200 8N1, DC controller: 9600 8E1) — a framing mismatch looks like silence — that the machine number is right, and that the A and B (D+ and D−) wires are not swapped.</source>
        <translation>연결은 열렸지만 응답한 드라이버가 없습니다. 통신 속도, 패리티, 스톱 비트(%1)가 드라이버 설정과 맞는지(DBU: 19200 8N1, DC 컨트롤러: 9600 8E1) — 프레임 형식이 맞지 않으면 무응답처럼 보입니다 — 국번이 맞는지, A와 B(D+와 D−) 선이 바뀌지 않았는지 확인하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="56"/>
        <source>The gateway %1:%2 did not accept the connection: check the address and port (Modbus TCP uses 502), that the gateway is powered and on this network, and that no firewall blocks it.</source>
        <translation>게이트웨이 %1:%2이(가) 연결을 받지 않았습니다: 주소와 포트(Modbus TCP는 502 사용), 게이트웨이 전원이 켜져 있고 이 네트워크에 있는지, 방화벽이 막고 있지 않은지 확인하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="63"/>
        <source>Check that the adapter is plugged in, that %1 is the right port, and that no other program uses it.</source>
        <translation>어댑터가 꽂혀 있는지, %1이(가) 올바른 포트인지, 다른 프로그램이 사용하고 있지 않은지 확인하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="66"/>
        <source>Check the connection settings and try again.</source>
        <translation>연결 설정을 확인하고 다시 시도하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="68"/>
        <source>Could not use %1: %2</source>
        <translation>%1을(를) 사용할 수 없습니다: %2</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="69"/>
        <source>What to check:</source>
        <translation>확인할 사항:</translation>
    </message>
</context>
<context>
    <name>opentop::ConnectionOptions</name>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="30"/>
        <source>--rs485 %1: use off (the adapter switches direction itself), auto, kernel or rts</source>
        <translation>--rs485 %1: off(어댑터가 직접 방향 전환), auto, kernel 또는 rts를 사용하십시오</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="36"/>
        <source>--rts-polarity %1: use high or low (the RTS level while sending)</source>
        <translation>--rts-polarity %1: high 또는 low를 사용하십시오(송신 중 RTS 레벨)</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="44"/>
        <source>--rts-delay %1: use 0–%2 µs (0: the driver&apos;s or libmodbus&apos; own delay)</source>
        <translation>--rts-delay %1: 0–%2 µs를 사용하십시오(0: 시리얼 드라이버 또는 libmodbus 자체 지연)</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="51"/>
        <source>--low-latency %1: use on or off</source>
        <translation>--low-latency %1: on 또는 off를 사용하십시오</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="61"/>
        <source>--%1 applies to a serial port (--port), not to a Modbus TCP gateway (--tcp)</source>
        <translation>--%1은(는) 시리얼 포트(--port)에 적용되며, Modbus TCP 게이트웨이(--tcp)에는 적용되지 않습니다</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="65"/>
        <source>--%1 applies to a serial port (--port), not to a simulated bus</source>
        <translation>--%1은(는) 시리얼 포트(--port)에 적용되며, 시뮬레이션 버스에는 적용되지 않습니다</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="66"/>
        <source>--%1 applies to a serial port only: give it with --port PATH</source>
        <translation>--%1은(는) 시리얼 포트에만 적용됩니다: --port PATH와 함께 지정하십시오</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="74"/>
        <source>Serial device (e.g. /dev/ttyUSB0 or a pty path).</source>
        <translation>시리얼 장치(예: /dev/ttyUSB0 또는 pty 경로).</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="75"/>
        <source>PATH</source>
        <translation>PATH</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="76"/>
        <source>Modbus TCP gateway, HOST:PORT (port defaults to 502).</source>
        <translation>Modbus TCP 게이트웨이, HOST:PORT (포트 기본값 502).</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="77"/>
        <source>HOST:PORT</source>
        <translation>HOST:PORT</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="78"/>
        <source>In-process simulated bus, e.g. dbu200@1,dbu400@150,dcpid@7.</source>
        <translation>프로세스 내부 시뮬레이션 버스, 예: dbu200@1,dbu400@150,dcpid@7.</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="79"/>
        <source>SPEC</source>
        <translation>SPEC</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="81"/>
        <source>Device family whose serial defaults apply (dbu: 19200 8N1, dcpid: 9600 8E1).</source>
        <translation>시리얼 기본값을 적용할 장치 제품군(dbu: 19200 8N1, dcpid: 9600 8E1).</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="82"/>
        <source>FAMILY</source>
        <translation>FAMILY</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="83"/>
        <source>Baud rate, 1200–115200.</source>
        <translation>통신 속도, 1200–115200.</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="83"/>
        <source>BAUD</source>
        <translation>BAUD</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="84"/>
        <source>Parity: N, E or O.</source>
        <translation>패리티: N, E 또는 O.</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="84"/>
        <source>N|E|O</source>
        <translation>N|E|O</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="85"/>
        <source>Stop bits: 1 or 2.</source>
        <translation>스톱 비트: 1 또는 2.</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="85"/>
        <location filename="../connection/ConnectionOptions.cpp" line="96"/>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="87"/>
        <source>Drives that talk another line format than the port&apos;s, switched to between transactions: ID=[BAUD:]FORMAT,... e.g. 7=9600:8E1 or 7=8N2 (BAUD defaults to the port&apos;s). A DBU works only at 8N1; a DC controller at 8E1, 8O1 or 8N2.</source>
        <translation>포트와 다른 통신 형식을 쓰는 드라이브. 트랜잭션 사이에 전환합니다: ID=[BAUD:]FORMAT,... 예: 7=9600:8E1 또는 7=8N2 (BAUD 기본값은 포트의 속도). DBU는 8N1만, DC 컨트롤러는 8E1, 8O1, 8N2를 씁니다.</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="90"/>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="92"/>
        <source>Response timeout per attempt in ms, 10–10000 (default 200).</source>
        <translation>시도당 응답 타임아웃(ms), 10–10000 (기본값 200).</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="92"/>
        <source>MS</source>
        <translation>MS</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="94"/>
        <source>Extra attempts after no reply or a garbled one, 0–10 (default 3; 2 more while the line is noisy).</source>
        <translation>응답이 없거나 깨졌을 때 추가 시도 횟수, 0–10 (기본값 3; 라인에 노이즈가 있으면 2회 추가).</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="98"/>
        <source>Who switches the RS-485 direction (serial port only): off (default: the adapter itself, as USB–RS-485 adapters do), kernel (the driver&apos;s RS-485 mode), rts (RTS from the program) or auto (kernel where the driver has it, else rts).</source>
        <translation>RS-485 송수신 방향을 누가 전환하는지 지정합니다(시리얼 포트 전용): off (기본값: USB–RS-485 어댑터처럼 어댑터가 직접 전환), kernel (시리얼 드라이버의 RS-485 모드), rts (프로그램이 RTS 제어) 또는 auto (시리얼 드라이버가 지원하면 kernel, 아니면 rts).</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="101"/>
        <source>MODE</source>
        <translation>MODE</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="103"/>
        <source>RTS level while sending with --rs485 kernel, rts or auto: high (default) or low.</source>
        <translation>--rs485 kernel, rts 또는 auto 사용 시 송신 중 RTS 레벨: high (기본값) 또는 low.</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="104"/>
        <source>high|low</source>
        <translation>high|low</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="106"/>
        <source>RTS delay before and after sending in µs, 0–100000 (default 0: the driver&apos;s, or libmodbus&apos; one character time; the kernel rounds up to whole ms).</source>
        <translation>송신 전후의 RTS 지연(µs), 0–100000 (기본값 0: 시리얼 드라이버의 지연 또는 libmodbus의 1문자 시간; 커널은 ms 단위로 올림합니다).</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="108"/>
        <source>US</source>
        <translation>US</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="110"/>
        <source>Ask the serial driver to pass received bytes on at once (USB adapters otherwise hold them up to 16 ms): on (default) or off.</source>
        <translation>시리얼 드라이버가 수신한 바이트를 즉시 넘기도록 요청합니다(그렇지 않으면 USB 어댑터가 최대 16 ms 동안 보류): on (기본값) 또는 off.</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="112"/>
        <source>on|off</source>
        <translation>on|off</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="157"/>
        <source>give only one of --port, --tcp and --sim</source>
        <translation>--port, --tcp, --sim 중 하나만 지정하십시오</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="159"/>
        <source>no bus given: use --port PATH, --tcp HOST:PORT or --sim SPEC</source>
        <translation>버스가 지정되지 않았습니다: --port PATH, --tcp HOST:PORT 또는 --sim SPEC을 사용하십시오</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="168"/>
        <source>--family %1: unknown family; use one of %2</source>
        <translation>--family %1: 알 수 없는 제품군입니다. 다음 중 하나를 사용하십시오: %2</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="187"/>
        <source>--tcp: &quot;%1&quot; is not HOST:PORT</source>
        <translation>--tcp: &quot;%1&quot;은(는) HOST:PORT 형식이 아닙니다</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="196"/>
        <source>--sim: %1</source>
        <translation>--sim: %1</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="209"/>
        <source>--baud %1: use a baud rate 1200–115200 (e.g. 9600, 19200, 38400)</source>
        <translation>--baud %1: 통신 속도는 1200–115200을 사용하십시오(예: 9600, 19200, 38400)</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="213"/>
        <source>--stop-bits %1: use 1 or 2</source>
        <translation>--stop-bits %1: 1 또는 2를 사용하십시오</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="215"/>
        <source>--timeout %1: use a response timeout of 10–10000 ms</source>
        <translation>--timeout %1: 응답 타임아웃은 10–10000 ms를 사용하십시오</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="218"/>
        <source>--retries %1: use 0–10 extra attempts</source>
        <translation>--retries %1: 추가 시도는 0–10회를 사용하십시오</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="223"/>
        <source>--parity %1: use N (none), E (even) or O (odd)</source>
        <translation>--parity %1: N(없음), E(짝수) 또는 O(홀수)를 사용하십시오</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="229"/>
        <source>--drive-format applies to a serial port (--port) or a simulated bus, not to a Modbus TCP gateway (--tcp): the gateway sets its line itself</source>
        <translation>--drive-format는 시리얼 포트(--port)나 시뮬레이션 버스에 적용되며 Modbus TCP 게이트웨이(--tcp)에는 적용되지 않습니다. 게이트웨이는 라인을 스스로 설정합니다</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="236"/>
        <source>--drive-format: %1</source>
        <translation>--drive-format: %1</translation>
    </message>
</context>
<context>
    <name>opentop::ConnectionStatus</name>
    <message>
        <location filename="../ui/main/ConnectionStatus.cpp" line="21"/>
        <source>SIMULATED BUS — no hardware</source>
        <translation>시뮬레이션 버스 — 실제 하드웨어 없음</translation>
    </message>
    <message>
        <location filename="../ui/main/ConnectionStatus.cpp" line="22"/>
        <source>These drives exist only in this program; nothing moves.</source>
        <translation>이 드라이버들은 이 프로그램 안에만 있습니다. 실제로 움직이는 것은 없습니다.</translation>
    </message>
    <message>
        <location filename="../ui/main/ConnectionStatus.cpp" line="27"/>
        <location filename="../ui/main/ConnectionStatus.cpp" line="76"/>
        <source>Not connected</source>
        <translation>연결 안 됨</translation>
    </message>
    <message>
        <location filename="../ui/main/ConnectionStatus.cpp" line="54"/>
        <source>Connected: %1</source>
        <translation>연결됨: %1</translation>
    </message>
    <message>
        <location filename="../ui/main/ConnectionStatus.cpp" line="56"/>
        <source> — %1</source>
        <translation> — %1</translation>
    </message>
</context>
<context>
    <name>opentop::ConnectionViews</name>
    <message>
        <location filename="../ui/main/ConnectionViews.cpp" line="80"/>
        <source>Communication groups: %1 (Bus › Communication groups)</source>
        <translation>통신 그룹: %1 (버스 › 통신 그룹)</translation>
    </message>
</context>
<context>
    <name>opentop::DbuSimDevice</name>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="340"/>
        <source>alarm 0x%1</source>
        <translation>알람 0x%1</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="341"/>
        <source>running</source>
        <translation>운전 중</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="342"/>
        <source>stopped</source>
        <translation>정지됨</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="343"/>
        <source>%1 %2 r/min (target %3) SPno%4 load %5 % %6, %7 priority, %8%9</source>
        <translation>%1 %2 r/min (목표 %3) SPno%4 부하 %5 % %6, %7 우선, %8%9</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="347"/>
        <source>communication</source>
        <translation>통신</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="347"/>
        <source>I/O</source>
        <translation>I/O</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="348"/>
        <source>offline</source>
        <translation>오프라인</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="348"/>
        <source>online</source>
        <translation>온라인</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="349"/>
        <source>, ignoring stop</source>
        <translation>, 정지 무시</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="357"/>
        <source>usage: %1 ID CODE</source>
        <translation>사용법: %1 ID CODE</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="360"/>
        <source>warning cleared</source>
        <translation>경고 해제됨</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="365"/>
        <source>unknown %1 code %2; allowed: %3</source>
        <translation>알 수 없는 %1 코드 %2; 허용: %3</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="373"/>
        <source>%1 0x%2 raised</source>
        <translation>%1 0x%2 발생</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="384"/>
        <source>usage: ignore-stop ID on|off</source>
        <translation>사용법: ignore-stop ID on|off</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="386"/>
        <source>stop commands are acknowledged and ignored</source>
        <translation>정지 명령을 수신 확인만 하고 무시합니다</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="387"/>
        <source>stop commands are obeyed</source>
        <translation>정지 명령을 따릅니다</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="403"/>
        <source>usage: %1 ID VALUE with VALUE %2..%3</source>
        <translation>사용법: %1 ID VALUE (VALUE는 %2..%3)</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="405"/>
        <source>%1 = %2</source>
        <translation>%1 = %2</translation>
    </message>
</context>
<context>
    <name>opentop::DcControllerPage</name>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="43"/>
        <source>DC controller</source>
        <translation>DC 컨트롤러</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="46"/>
        <source>Re&amp;load stored configuration</source>
        <translation>저장된 설정 다시 불러오기(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="68"/>
        <source>Store &amp;configuration</source>
        <translation>설정 저장(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="69"/>
        <source>Store P&amp;ID</source>
        <translation>PID 저장(&amp;I)</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="70"/>
        <source>Store pre&amp;set</source>
        <translation>프리셋 저장(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="73"/>
        <source>Writes %1 = 1: %2</source>
        <translation>%1 = 1 쓰기: %2</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="78"/>
        <source>Writes store.config = 0: the controller reloads the stored configuration; unstored configuration changes are discarded</source>
        <translation>store.config = 0 쓰기: 컨트롤러가 저장된 설정을 다시 불러옵니다. 저장하지 않은 설정 변경은 버려집니다</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="85"/>
        <source>Speed mode and motor currents</source>
        <translation>속도 모드와 모터 전류</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="86"/>
        <source>Speed &amp;mode:</source>
        <translation>속도 모드(&amp;M):</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="87"/>
        <source>Rated current:</source>
        <translation>정격 전류:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="88"/>
        <source>Maximum start/load current:</source>
        <translation>최대 기동/부하 전류:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="89"/>
        <source>Brake current:</source>
        <translation>브레이크 전류:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="91"/>
        <source>Limit switches</source>
        <translation>리밋 스위치</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="92"/>
        <source>Limits:</source>
        <translation>리밋:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="93"/>
        <source>SQ1 active level (forward):</source>
        <translation>SQ1 동작 레벨 (정회전):</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="94"/>
        <source>SQ2 active level (reverse):</source>
        <translation>SQ2 동작 레벨 (역회전):</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="96"/>
        <source>Protective stops (0 = off)</source>
        <translation>보호 정지 (0 = 사용 안 함)</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="97"/>
        <source>S&amp;tall stop time:</source>
        <translation>구속 정지 시간(&amp;T):</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="98"/>
        <source>Communication loss stop time:</source>
        <translation>통신 두절 정지 시간:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="106"/>
        <source>Serial port (used from the next power-up)</source>
        <translation>시리얼 포트 (다음 전원 투입부터 적용)</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="111"/>
        <source>Baud rate and parity are written as one 15-register block from 0x0080 that also stores the configuration; the controller uses them from the next power-up on: switch it off and on, then reconnect with them. The lock is lost at power-off until stored (Store configuration).</source>
        <translation>통신 속도와 패리티는 0x0080부터의 15개 레지스터 블록 하나로 쓰이며, 이 쓰기는 설정도 저장합니다. 컨트롤러는 다음 전원 투입부터 이 값을 사용합니다: 전원을 껐다 켠 뒤 새 설정으로 다시 연결하십시오. 시리얼 설정 잠금은 저장(설정 저장)하기 전까지 전원을 끄면 사라집니다.</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="133"/>
        <source>Takes effect now and is kept over power-off: each change is written as one 5-register block from 0x0050 that also stores the port states.</source>
        <translation>즉시 적용되며 전원을 꺼도 유지됩니다: 변경할 때마다 0x0050부터의 5개 레지스터 블록 하나로 쓰이며, 이 쓰기는 포트 상태도 저장합니다.</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="175"/>
        <source>The communication loss stop time is 0 s (%1): the manual does not say what 0 does, and OpenTOP assumes the stop is then off: if the connection is lost while the motor runs, the controller keeps it running at the last speed command. Set a time so that it brakes when the bus goes quiet.</source>
        <translation>통신 두절 정지 시간이 0 s입니다(%1): 매뉴얼은 0의 의미를 설명하지 않으며, OpenTOP은 이 경우 정지 기능이 꺼진다고 가정합니다: 모터 운전 중 연결이 끊기면 컨트롤러는 마지막 속도 명령으로 계속 운전합니다. 버스 통신이 끊기면 브레이크가 걸리도록 시간을 설정하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="107"/>
        <source>Baud rate:</source>
        <translation>통신 속도:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="108"/>
        <source>Parity and stop bits:</source>
        <translation>패리티와 스톱 비트:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="109"/>
        <source>Configuration over serial:</source>
        <translation>시리얼로 설정 변경:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="115"/>
        <source>Speed loop PID</source>
        <translation>속도 루프 PID</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="116"/>
        <source>&amp;P coefficient:</source>
        <translation>P 계수(&amp;P):</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="117"/>
        <source>I coefficient:</source>
        <translation>I 계수:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="118"/>
        <source>&amp;D coefficient:</source>
        <translation>D 계수(&amp;D):</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="119"/>
        <source>D period:</source>
        <translation>D 주기:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="121"/>
        <source>Preset speed (potentiometer/analog control)</source>
        <translation>프리셋 속도 (포텐셔미터/아날로그 제어)</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="122"/>
        <source>Preset speed mo&amp;de:</source>
        <translation>프리셋 속도 모드(&amp;D):</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="123"/>
        <source>Trigger:</source>
        <translation>트리거:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="124"/>
        <source>&amp;Forward speed:</source>
        <translation>정회전 속도(&amp;F):</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="125"/>
        <source>Reverse speed:</source>
        <translation>역회전 속도:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="127"/>
        <source>AI1/AI2 as digital ports</source>
        <translation>AI1/AI2를 디지털 포트로 사용</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="128"/>
        <source>AI1 direction:</source>
        <translation>AI1 방향:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="129"/>
        <source>AI2 direction:</source>
        <translation>AI2 방향:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="130"/>
        <source>AI1 level:</source>
        <translation>AI1 레벨:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="131"/>
        <source>AI2 level:</source>
        <translation>AI2 레벨:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="191"/>
        <source>Takes effect now, lost at power-off until stored (%1).</source>
        <translation>즉시 적용되며, 저장하기 전까지는 전원을 끄면 사라집니다(%1).</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="252"/>
        <source>Set it anyway?</source>
        <translation>그래도 설정하시겠습니까?</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="268"/>
        <source>Forward and reverse speed in this mode (%1): %2</source>
        <translation>이 모드(%1)의 정회전·역회전 속도: %2</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="270"/>
        <source>The unit and range of the speeds follow the preset speed mode (not read yet).</source>
        <translation>속도의 단위와 범위는 프리셋 속도 모드에 따릅니다(아직 읽지 않음).</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="294"/>
        <source>&lt;b&gt;Written but not stored:&lt;/b&gt; %1. These values act now and are lost when the controller is switched off.</source>
        <translation>&lt;b&gt;쓰기 완료, 저장 안 됨:&lt;/b&gt; %1. 이 값은 지금 적용되어 있지만 컨트롤러 전원을 끄면 사라집니다.</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="316"/>
        <source>%1: the controller writes the values now in effect to its memory and uses them from the next power-up on.

Stored: %2.</source>
        <translation>%1: 컨트롤러가 현재 적용 중인 값을 메모리에 저장하고 다음 전원 투입부터 사용합니다.

저장 대상: %2.</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="327"/>
        <source>Not written yet, so not stored: %1.</source>
        <translation>아직 쓰지 않아 저장되지 않음: %1.</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="330"/>
        <source>%1: done, kept over power-off.</source>
        <translation>%1: 완료, 전원을 꺼도 유지됩니다.</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="338"/>
        <source>The controller replaces its configuration (%1) with the one stored in its memory.

Configuration changes written but not stored are discarded.</source>
        <translation>컨트롤러가 현재 설정(%1)을 메모리에 저장된 설정으로 교체합니다.

쓰기만 하고 저장하지 않은 설정 변경은 버려집니다.</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="344"/>
        <source>Stored configuration reloaded.</source>
        <translation>저장된 설정을 다시 불러왔습니다.</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="352"/>
        <source>Writing %1 = %2…</source>
        <translation>%1 = %2 쓰는 중…</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="362"/>
        <source>%1 = %2 failed: %3</source>
        <translation>%1 = %2 실패: %3</translation>
    </message>
</context>
<context>
    <name>opentop::DcMotor</name>
    <message>
        <location filename="../sim/DcMotor.cpp" line="64"/>
        <source>unknown motor setting &apos;%1&apos;; settings: %2</source>
        <translation>알 수 없는 모터 설정 &apos;%1&apos;; 설정: %2</translation>
    </message>
    <message>
        <location filename="../sim/DcMotor.cpp" line="71"/>
        <source>motor setting %1 must be a number %2..%3, got &apos;%4&apos;</source>
        <translation>모터 설정 %1은(는) %2..%3의 숫자여야 합니다. 입력값: &apos;%4&apos;</translation>
    </message>
</context>
<context>
    <name>opentop::DcPidSimDevice</name>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="366"/>
        <source>%1 %2%3, output %4 %, command %5, line %6 %7</source>
        <translation>%1 %2%3, 출력 %4 %, 명령 %5, 라인 %6 %7</translation>
    </message>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="368"/>
        <source> (stall stop)</source>
        <translation> (구속 정지)</translation>
    </message>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="384"/>
        <source>usage: %1 ID VALUE with VALUE %2..%3 %4</source>
        <translation>사용법: %1 ID VALUE (VALUE는 %2..%3 %4)</translation>
    </message>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="388"/>
        <source>(bit0 SQ1, bit1 SQ2, bit2 DE)</source>
        <translation>(bit0 SQ1, bit1 SQ2, bit2 DE)</translation>
    </message>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="388"/>
        <source>(% current)</source>
        <translation>(전류 %)</translation>
    </message>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="390"/>
        <source>%1 = %2</source>
        <translation>%1 = %2</translation>
    </message>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="407"/>
        <source>motor %1, speed %2 1/s, current %3 A</source>
        <translation>모터 %1, 속도 %2 1/s, 전류 %3 A</translation>
    </message>
</context>
<context>
    <name>opentop::DcRunCommands</name>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="26"/>
        <source>Set s&amp;peed</source>
        <translation>속도 설정(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="31"/>
        <source>set point, e.g. 50 or -20</source>
        <translation>설정값, 예: 50 또는 -20</translation>
    </message>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="39"/>
        <source>Speed command:</source>
        <translation>속도 명령:</translation>
    </message>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="54"/>
        <source>&amp;Brake (speed 0)</source>
        <translation>브레이크(&amp;B) (속도 0)</translation>
    </message>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="56"/>
        <source>&amp;Natural stop</source>
        <translation>자연 정지(&amp;N)</translation>
    </message>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="90"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="91"/>
        <source>(reading %1…)</source>
        <translation>(%1 읽는 중…)</translation>
    </message>
</context>
<context>
    <name>opentop::DependentValues</name>
    <message>
        <location filename="../model/session/DependentValues.cpp" line="45"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../model/session/DependentValues.cpp" line="53"/>
        <source>%1 = %2 would leave %3 without a valid value, because what they allow depends on it. Choose new values for them and write them together with it.</source>
        <translation>%1 = %2(으)로 하면 허용 범위가 이 값에 따라 달라지는 %3이(가) 올바르지 않은 값이 됩니다. 새 값을 정해 함께 쓰십시오.</translation>
    </message>
    <message>
        <location filename="../model/session/DependentValues.cpp" line="57"/>
        <source>%1 cannot be checked: the values of %2 depend on it and could not be read</source>
        <translation>%1을(를) 검사할 수 없습니다: %2의 값이 이 값에 따라 달라지는데 읽을 수 없었습니다</translation>
    </message>
</context>
<context>
    <name>opentop::DeviceIdentifier</name>
    <message>
        <location filename="../model/session/DeviceIdentifier.cpp" line="31"/>
        <source>answers, but none of the device profiles matches</source>
        <translation>응답은 있지만 일치하는 장치 프로파일이 없습니다</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceIdentifier.cpp" line="96"/>
        <source>device name &quot;%1&quot; is not a %2</source>
        <translation>장치 이름 &quot;%1&quot;은(는) %2이(가) 아닙니다</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceIdentifier.cpp" line="116"/>
        <source>the variant cannot be read from the device; choose it</source>
        <translation>장치에서 기종을 읽을 수 없습니다. 기종을 선택하십시오</translation>
    </message>
</context>
<context>
    <name>opentop::DeviceInfo</name>
    <message>
        <location filename="../model/session/DeviceInfo.cpp" line="59"/>
        <source>not checked</source>
        <translation>확인 안 됨</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceInfo.cpp" line="61"/>
        <source>online</source>
        <translation>온라인</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceInfo.cpp" line="63"/>
        <source>no answer</source>
        <translation>응답 없음</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceInfo.cpp" line="65"/>
        <source>garbled replies (duplicate machine number?)</source>
        <translation>응답이 깨짐(국번 중복?)</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceInfo.cpp" line="68"/>
        <source>unknown device</source>
        <translation>알 수 없는 장치</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceInfo.cpp" line="70"/>
        <source>answered, identification failed</source>
        <translation>응답 있음, 식별 실패</translation>
    </message>
</context>
<context>
    <name>opentop::DeviceMonitor</name>
    <message>
        <location filename="../model/monitor/DeviceMonitor.cpp" line="66"/>
        <source>Stopped</source>
        <translation>정지</translation>
    </message>
    <message>
        <location filename="../model/monitor/DeviceMonitor.cpp" line="68"/>
        <source>Running</source>
        <translation>운전 중</translation>
    </message>
    <message>
        <location filename="../model/monitor/DeviceMonitor.cpp" line="69"/>
        <source>Running CCW</source>
        <translation>CCW 운전 중</translation>
    </message>
    <message>
        <location filename="../model/monitor/DeviceMonitor.cpp" line="69"/>
        <source>Running CW</source>
        <translation>CW 운전 중</translation>
    </message>
    <message>
        <location filename="../model/monitor/DeviceMonitor.cpp" line="212"/>
        <source>machine number %1: %2</source>
        <translation>국번 %1: %2</translation>
    </message>
</context>
<context>
    <name>opentop::DeviceParameters</name>
    <message>
        <location filename="../model/session/DeviceParameters.cpp" line="92"/>
        <source>%1 has no parameter &quot;%2&quot;</source>
        <translation>%1에 파라미터 &quot;%2&quot;이(가) 없습니다</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceParameters.cpp" line="94"/>
        <source>%1 is read-only</source>
        <translation>%1은(는) 읽기 전용입니다</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceParameters.cpp" line="96"/>
        <source>%1 is a command, not a setting; commands are sent one by one on request</source>
        <translation>%1은(는) 설정이 아니라 명령입니다. 명령은 요청할 때 하나씩 보냅니다</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceParameters.cpp" line="252"/>
        <location filename="../model/session/DeviceParameters.cpp" line="263"/>
        <location filename="../model/session/DeviceParameters.cpp" line="275"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/session/DeviceParameters.cpp" line="286"/>
        <source>%n write(s) failed: %1</source>
        <translation>
            <numerusform>쓰기 %n건 실패: %1</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/session/DeviceParameters.cpp" line="289"/>
        <source>Written, but not verified on every drive it reached: %1</source>
        <translation>쓰기는 했지만, 받은 모든 드라이버에서 확인되지는 않았습니다: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/session/DeviceParameters.cpp" line="292"/>
        <source>%n value(s) written and verified</source>
        <translation>
            <numerusform>값 %n개 쓰기 및 검증 완료</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::DeviceSession</name>
    <message>
        <location filename="../model/session/DeviceSession.cpp" line="83"/>
        <source>%1 has no parameter &quot;%2&quot;</source>
        <translation>%1에 파라미터 &quot;%2&quot;이(가) 없습니다</translation>
    </message>
    <message>
        <location filename="../model/session/BlockReader.cpp" line="50"/>
        <location filename="../model/session/DeviceSession.cpp" line="92"/>
        <source>%1 cannot be read (it is a write-only command)</source>
        <translation>%1은(는) 읽을 수 없습니다(쓰기 전용 명령)</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceSession.cpp" line="137"/>
        <source>%1 is read-only</source>
        <translation>%1은(는) 읽기 전용입니다</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceSession.cpp" line="143"/>
        <source>%1 is a %2 command; it is only sent when explicitly requested</source>
        <translation>%1은(는) %2 명령입니다. 명시적으로 요청할 때만 보냅니다</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceSession.cpp" line="173"/>
        <source>%1 cannot be checked: %2</source>
        <translation>%1을(를) 검사할 수 없습니다: %2</translation>
    </message>
    <message>
        <location filename="../model/session/BlockWriter.cpp" line="28"/>
        <source>not written: %1 is written together with 0x%2–0x%3, and reading those first failed: %4</source>
        <translation>쓰지 않음: %1은(는) 0x%2–0x%3과(와) 함께 쓰는데, 이 레지스터를 먼저 읽지 못했습니다: %4</translation>
    </message>
    <message>
        <location filename="../model/session/BlockWriter.cpp" line="33"/>
        <source>short reply</source>
        <translation>응답이 너무 짧음</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceSession.cpp" line="254"/>
        <source>written, but reading it back failed: %1</source>
        <translation>썼지만 다시 읽기에 실패했습니다: %1</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceSession.cpp" line="263"/>
        <source>verification failed: wrote %1, the device holds %2</source>
        <translation>검증 실패: %1을(를) 썼지만 장치 값은 %2입니다</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceRefusal.cpp" line="67"/>
        <source>error code %1</source>
        <translation>오류 코드 %1</translation>
    </message>
</context>
<context>
    <name>opentop::DriveBatchReader</name>
    <message>
        <location filename="../model/files/DriveBatchReader.cpp" line="13"/>
        <source>machine number %1: not read</source>
        <translation>국번 %1: 읽지 않음</translation>
    </message>
    <message>
        <location filename="../model/files/DriveBatchReader.cpp" line="22"/>
        <source>%1: cannot read %2</source>
        <translation>%1: %2을(를) 읽을 수 없습니다</translation>
    </message>
    <message>
        <location filename="../model/files/DriveBatchReader.cpp" line="24"/>
        <source>%1 holds a value its profile does not allow, so the backup could not be restored: %2</source>
        <translation>%1에 프로파일이 허용하지 않는 값이 있어 이 백업은 복원할 수 없습니다: %2</translation>
    </message>
    <message>
        <location filename="../model/files/DriveBatchReader.cpp" line="89"/>
        <source>machine number %1 is not a drive on the bus</source>
        <translation>국번 %1은(는) 버스에 있는 드라이버가 아닙니다</translation>
    </message>
</context>
<context>
    <name>opentop::DriveFormatsField</name>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="28"/>
        <source>none: every drive at the port&apos;s format</source>
        <translation>없음: 모든 드라이브가 포트 형식</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="30"/>
        <source>Drives set to another line format than the port&apos;s, e.g. 7=9600:8E1 or 7=8N2 (the baud rate may be left out): requests to them switch the line to their format and back between transactions. A DBU works only at 8N1; a DC controller at 8E1, 8O1 or 8N2. The bus list&apos;s context menu sets them too.</source>
        <translation>포트와 다른 통신 형식으로 설정된 드라이브. 예: 7=9600:8E1 또는 7=8N2 (통신 속도는 생략 가능). 이 드라이브로 가는 요청은 트랜잭션 사이에 라인을 그 형식으로 전환했다가 되돌립니다. DBU는 8N1만, DC 컨트롤러는 8E1, 8O1, 8N2를 씁니다. 버스 목록의 컨텍스트 메뉴에서도 설정할 수 있습니다.</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="36"/>
        <source>&amp;Mixed bus…</source>
        <translation>혼합 버스(&amp;M)…</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="37"/>
        <source>How a drive of another format joins this bus</source>
        <translation>다른 형식의 드라이브를 이 버스에 넣는 방법</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="39"/>
        <source>Drives of different line formats</source>
        <translation>통신 형식이 다른 드라이브</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="47"/>
        <source>Drive f&amp;ormats:</source>
        <translation>드라이브 형식(&amp;O):</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="68"/>
        <source>Drive formats: %1</source>
        <translation>드라이브 형식: %1</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="74"/>
        <source>Every drive hears only frames sent in its own line format: a DBU works only at 8N1 (19200 bit/s from the factory), a DC controller at 8E1 (9600 bit/s from the factory), 8O1 or 8N2. OpenTOP can talk to drives of different formats on one port: give each drive that is not at the port&apos;s format its own (Drive formats here, or Line format… in the bus list&apos;s context menu); the port is switched between transactions. To put all drives at one format for good, change the drives:</source>
        <translation>각 드라이브는 자신의 통신 형식으로 보낸 프레임만 받습니다. DBU는 8N1만(공장 출하 19200 bit/s), DC 컨트롤러는 8E1(공장 출하 9600 bit/s), 8O1, 8N2를 씁니다. OpenTOP은 한 포트에서 형식이 다른 드라이브와 통신할 수 있습니다. 포트 형식이 아닌 드라이브마다 자체 형식을 지정하십시오(여기의 「드라이브 형식」 또는 버스 목록 컨텍스트 메뉴의 「통신 형식…」). 포트는 트랜잭션 사이에 전환됩니다. 모든 드라이브를 계속 한 형식으로 쓰려면 드라이브 설정을 바꾸십시오:</translation>
    </message>
</context>
<context>
    <name>opentop::DriveLineDialog</name>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="29"/>
        <source>Line format of machine number %1</source>
        <translation>국번 %1의 통신 형식</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="29"/>
        <source>Add drive</source>
        <translation>드라이브 추가</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="37"/>
        <source>&amp;Machine number:</source>
        <translation>국번(&amp;M):</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="51"/>
        <source>The port&apos;s (%1)</source>
        <translation>포트 형식 (%1)</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="63"/>
        <source>The baud rate and format the drive is set to: requests to it switch the port to it and back between transactions. Type another as 38400 8E1.</source>
        <translation>드라이브에 설정된 통신 속도와 형식. 이 드라이브로 가는 요청은 트랜잭션 사이에 포트를 그 형식으로 전환했다가 되돌립니다. 다른 형식은 38400 8E1처럼 입력하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="66"/>
        <source>&amp;Line format:</source>
        <translation>통신 형식(&amp;L):</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="74"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="147"/>
        <source>Line &amp;format…</source>
        <translation>통신 형식(&amp;F)…</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="152"/>
        <source>Machine number %1 talks %2, not the port&apos;s %3</source>
        <translation>국번 %1은(는) 포트의 %3이(가) 아니라 %2(으)로 통신합니다</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="155"/>
        <source>Machine number %1 talks the port&apos;s %2</source>
        <translation>국번 %1은(는) 포트의 %2(으)로 통신합니다</translation>
    </message>
</context>
<context>
    <name>opentop::DriveName</name>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="19"/>
        <source>A machine&apos;s name has at most %1 characters; &quot;%2&quot; has %3.</source>
        <translation>기계 이름은 최대 %1자입니다. &quot;%2&quot;은(는) %3자입니다.</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="30"/>
        <source>A machine&apos;s name may not hold control characters or line breaks (U+%1).</source>
        <translation>기계 이름에는 제어 문자나 줄바꿈을 넣을 수 없습니다(U+%1).</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="38"/>
        <source>A machine&apos;s name may not hold %1 (a percent sign directly before a digit).</source>
        <translation>기계 이름에는 %1(퍼센트 기호 바로 뒤에 숫자)을 넣을 수 없습니다.</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="47"/>
        <source>machine number %1</source>
        <translation>국번 %1</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="48"/>
        <source>machine number %1 (%2)</source>
        <translation>국번 %1(%2)</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="53"/>
        <source>Machine number %1</source>
        <translation>국번 %1</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="54"/>
        <source>Machine number %1 (%2)</source>
        <translation>국번 %1(%2)</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="72"/>
        <source>drive %1 (%2)</source>
        <translation>드라이버 %1(%2)</translation>
    </message>
</context>
<context>
    <name>opentop::DrivePages</name>
    <message>
        <location filename="../ui/main/DrivePages.cpp" line="102"/>
        <source>Monitor</source>
        <translation>모니터</translation>
    </message>
    <message>
        <location filename="../ui/main/DrivePages.cpp" line="115"/>
        <source>Test run</source>
        <translation>시운전</translation>
    </message>
    <message>
        <location filename="../ui/main/DrivePages.cpp" line="139"/>
        <source>%1 — %2, firmware V%3, switches %4</source>
        <translation>%1 — %2, 펌웨어 V%3, 스위치 %4</translation>
    </message>
    <message>
        <location filename="../ui/main/DrivePages.cpp" line="123"/>
        <source>Speed loop tuning</source>
        <translation>속도 루프 튜닝</translation>
    </message>
    <message>
        <location filename="../ui/main/DrivePages.cpp" line="129"/>
        <source>Alarms</source>
        <translation>알람</translation>
    </message>
</context>
<context>
    <name>opentop::DriveStatus</name>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="8"/>
        <source>not polled yet</source>
        <translation>아직 폴링 안 함</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="10"/>
        <source>online</source>
        <translation>온라인</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/bus/DriveStatus.cpp" line="12"/>
        <source>no answer (%n poll(s) in a row)</source>
        <translation>
            <numerusform>응답 없음(연속 %n회 폴링)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../model/bus/DriveStatus.cpp" line="13"/>
        <source>communication error (%n in a row)</source>
        <translation>
            <numerusform>통신 오류(연속 %n회)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="19"/>
        <location filename="../model/bus/DriveStatus.cpp" line="31"/>
        <source>Status not known yet</source>
        <translation>상태 아직 알 수 없음</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="21"/>
        <source>No answer: %1</source>
        <translation>응답 없음: %1</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="24"/>
        <source>Communication error: %1</source>
        <translation>통신 오류: %1</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="34"/>
        <source>Alarm %1 %2</source>
        <translation>알람 %1 %2</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="36"/>
        <source>Alarm %1h (not in the alarm table)</source>
        <translation>알람 %1h (알람 표에 없음)</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="38"/>
        <source>Alarm active</source>
        <translation>알람 발생 중</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="42"/>
        <source>Running</source>
        <translation>운전 중</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="43"/>
        <source>Running CCW</source>
        <translation>CCW 운전 중</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="43"/>
        <source>Running CW</source>
        <translation>CW 운전 중</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="45"/>
        <source>Stopped, no alarm</source>
        <translation>정지, 알람 없음</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="52"/>
        <source>grey</source>
        <translation>회색</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="54"/>
        <source>green</source>
        <translation>초록</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="56"/>
        <source>orange</source>
        <translation>주황</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="58"/>
        <source>sky blue</source>
        <translation>하늘색</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="60"/>
        <source>red</source>
        <translation>빨강</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="62"/>
        <source>purple</source>
        <translation>보라</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="64"/>
        <source>blue</source>
        <translation>파랑</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="101"/>
        <source>%1; %2</source>
        <translation>%1; %2</translation>
    </message>
</context>
<context>
    <name>opentop::DriveWorkspace</name>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="35"/>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="169"/>
        <source>Write &amp;all pending</source>
        <translation>쓰기 대기 모두 쓰기(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="36"/>
        <source>Revert all</source>
        <translation>모두 되돌리기</translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="37"/>
        <source>Re-read all</source>
        <translation>모두 다시 읽기</translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="55"/>
        <source>Write every pending edit of this drive, on all pages, and verify</source>
        <translation>이 드라이버의 모든 페이지에서 쓰기 대기 중인 편집을 모두 쓰고 검증합니다</translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="88"/>
        <source>Select a drive in the bus list to set it up.</source>
        <translation>설정할 드라이버를 버스 목록에서 선택하십시오.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="152"/>
        <source>Every edit is accepted now. Nothing has been written yet: Write all pending sends %n value(s).</source>
        <translation>
            <numerusform>이제 모든 편집이 허용됩니다. 아직 아무것도 쓰지 않았습니다: 모든 쓰기 대기 쓰기가 값 %n개를 보냅니다.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="168"/>
        <source>Write &amp;all pending (%1)</source>
        <translation>쓰기 대기 모두 쓰기(&amp;A) (%1)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="190"/>
        <source>Reading the drive…</source>
        <translation>드라이버를 읽는 중…</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="192"/>
        <source>%n value(s) could not be read</source>
        <translation>
            <numerusform>값 %n개를 읽을 수 없습니다</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="147"/>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="210"/>
        <source>Nothing was written: %1</source>
        <translation>아무것도 쓰지 않았습니다: %1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="144"/>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="224"/>
        <source>%1: %2 Nothing was written.</source>
        <translation>%1: %2 아무것도 쓰지 않았습니다.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="233"/>
        <source>Write %n pending value(s) to machine number %1</source>
        <translation>
            <numerusform>쓰기 대기 값 %n개를 국번 %1에 쓰기</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="205"/>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="235"/>
        <source>Nothing was written.</source>
        <translation>아무것도 쓰지 않았습니다.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="238"/>
        <source>Writing %n value(s)…</source>
        <translation>
            <numerusform>값 %n개 쓰는 중…</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::EolAuditCommand</name>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="34"/>
        <source>Show the audit trail: who logged in, approved, used or was refused a privilege</source>
        <translation>감사 기록 표시: 누가 로그인, 승인했는지, 권한을 사용했거나 거부당했는지</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="40"/>
        <source>Results database: an SQLite file or postgresql://user@host/db.</source>
        <translation>결과 데이터베이스: SQLite 파일 또는 postgresql://user@host/db.</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="41"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="42"/>
        <source>audit: at or after T (2026-11-24, 8h, 2d, today).</source>
        <translation>audit: T 이후(2026-11-24, 8h, 2d, today).</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="42"/>
        <source>T</source>
        <translation>T</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="43"/>
        <source>audit: only this user.</source>
        <translation>audit: 이 사용자만.</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="43"/>
        <location filename="../cli/EolAuditCommand.cpp" line="44"/>
        <source>NAME</source>
        <translation>이름</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="44"/>
        <source>audit: only this station.</source>
        <translation>audit: 이 스테이션만.</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="53"/>
        <source>usage: opentop-cli eol %1</source>
        <translation>사용법: opentop-cli eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="62"/>
        <source>error: --since: %1</source>
        <translation>오류: --since: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="74"/>
        <source>error: %1</source>
        <translation>오류: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="89"/>
        <source>no audit entry matches</source>
        <translation>일치하는 감사 기록이 없습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="92"/>
        <source>time</source>
        <translation>시각</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="92"/>
        <source>station</source>
        <translation>스테이션</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="92"/>
        <source>user</source>
        <translation>사용자</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="92"/>
        <source>action</source>
        <translation>동작</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="92"/>
        <source>detail</source>
        <translation>내용</translation>
    </message>
</context>
<context>
    <name>opentop::EolCertificateCommand</name>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="31"/>
        <source>A unit&apos;s certificate: its newest record as a PDF, or as JSON with --json</source>
        <translation>제품의 성적서: 최신 기록을 PDF로, --json을 주면 JSON으로</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="37"/>
        <source>The results database (see results).</source>
        <translation>결과 데이터베이스(results 참조).</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="37"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="38"/>
        <source>certificate: the record with this id instead of the newest.</source>
        <translation>certificate: 최신 기록 대신 이 id의 기록.</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="39"/>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="59"/>
        <source>error: name one serial number, or a record with --id ID; usage: eol %1</source>
        <translation>오류: 시리얼 번호 하나 또는 --id ID로 기록을 지정하십시오. 사용법: eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="67"/>
        <source>error: the serial number is empty</source>
        <translation>오류: 시리얼 번호가 비어 있습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="73"/>
        <location filename="../cli/EolCertificateCommand.cpp" line="138"/>
        <location filename="../cli/EolCertificateCommand.cpp" line="154"/>
        <source>error: %1</source>
        <translation>오류: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="80"/>
        <source>error: this program cannot draw a PDF (no Qt GUI application); use --json</source>
        <translation>오류: 이 프로그램은 PDF를 그릴 수 없습니다(Qt GUI 애플리케이션 아님). --json을 사용하십시오</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="96"/>
        <source>error: no record %1 in %2 (%3)</source>
        <translation>오류: %2에 기록 %1이(가) 없습니다(%3)</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="104"/>
        <source>error: record %1 is of serial number %2, not %3</source>
        <translation>오류: 기록 %1은(는) 시리얼 번호 %3이(가) 아니라 %2의 기록입니다</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="114"/>
        <location filename="../cli/EolCertificateCommand.cpp" line="147"/>
        <source>error: %1: %2</source>
        <translation>오류: %1: %2</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="121"/>
        <source>error: no record of serial number %1 in %2</source>
        <translation>오류: %2에 시리얼 번호 %1의 기록이 없습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="141"/>
        <source>wrote %1</source>
        <translation>%1 저장함</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="157"/>
        <source>wrote %1: serial number %2, %3, recorded %4</source>
        <translation>%1 저장함: 시리얼 번호 %2, %3, 기록 시각 %4</translation>
    </message>
</context>
<context>
    <name>opentop::EolCommand</name>
    <message>
        <location filename="../cli/EolCommand.cpp" line="36"/>
        <source>End-of-line station: recipes, the results database, unit certificates</source>
        <translation>출하 검사 스테이션: 레시피, 결과 데이터베이스, 제품 성적서</translation>
    </message>
    <message>
        <location filename="../cli/EolCommand.cpp" line="41"/>
        <source>Subcommands:
</source>
        <translation>하위 명령:
</translation>
    </message>
    <message>
        <location filename="../cli/EolCommand.cpp" line="44"/>
        <source>Results database: --db URL, else OPENTOP_EOL_DB, else the SQLite file
$XDG_DATA_HOME/opentop/results.db (~/.local/share/opentop/results.db).
&quot;opentop-cli help eol&quot; lists every option; each subcommand takes only its own.</source>
        <translation>결과 데이터베이스: --db URL, 없으면 OPENTOP_EOL_DB, 없으면 SQLite 파일
$XDG_DATA_HOME/opentop/results.db (~/.local/share/opentop/results.db).
&quot;opentop-cli help eol&quot;로 모든 옵션을 볼 수 있습니다. 각 하위 명령은 자신의 옵션만 받습니다.</translation>
    </message>
    <message>
        <location filename="../cli/EolCommand.cpp" line="92"/>
        <source>error: name a subcommand: eol %1</source>
        <translation>오류: 하위 명령을 지정하십시오: eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolCommand.cpp" line="94"/>
        <source>error: unknown subcommand &quot;eol %1&quot;; subcommands: %2</source>
        <translation>오류: 알 수 없는 하위 명령 &quot;eol %1&quot;; 하위 명령: %2</translation>
    </message>
    <message>
        <location filename="../cli/EolCommand.cpp" line="98"/>
        <source>See &quot;opentop-cli help eol&quot;.</source>
        <translation>&quot;opentop-cli help eol&quot;을 참조하십시오.</translation>
    </message>
    <message>
        <location filename="../cli/EolCommand.cpp" line="114"/>
        <source>error: eol %1: --%2 is not an option of this subcommand; usage: eol %3</source>
        <translation>오류: eol %1: --%2은(는) 이 하위 명령의 옵션이 아닙니다. 사용법: eol %3</translation>
    </message>
</context>
<context>
    <name>opentop::EolDriveRun</name>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="56"/>
        <source>identifying</source>
        <translation>식별 중</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="84"/>
        <source>no drive answers at machine number %1</source>
        <translation>국번 %1에서 응답하는 드라이버가 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="85"/>
        <source>the drive at machine number %1 is not identified: %2</source>
        <translation>국번 %1의 드라이버가 식별되지 않았습니다: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="99"/>
        <source>a %1 drive, the recipe needs a %2 drive</source>
        <translation>%1 드라이버입니다. 레시피에는 %2 드라이버가 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="103"/>
        <source>firmware %1, the recipe allows %2</source>
        <translation>펌웨어 %1, 레시피가 허용하는 펌웨어: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="104"/>
        <source>unknown</source>
        <translation>알 수 없음</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="110"/>
        <source>no profile for the family %1</source>
        <translation>제품군 %1의 프로파일이 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="193"/>
        <source>cannot read whether the motor runs or an alarm is active: %1</source>
        <translation>모터 운전 여부나 알람 발생 여부를 읽을 수 없습니다: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="194"/>
        <source>no answer</source>
        <translation>응답 없음</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="201"/>
        <source>its motor was running before the test</source>
        <translation>검사 전에 모터가 운전 중이었습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="202"/>
        <source>the motor is already running before the test (left by an interrupted run?); nothing was written: stop it first (STOP ALL, or at the drive)</source>
        <translation>검사 전에 모터가 이미 운전 중입니다(중단된 검사가 남긴 상태?). 아무것도 쓰지 않았습니다: 먼저 정지하십시오(전체 정지 또는 드라이버에서)</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="209"/>
        <source>an alarm is active before the test (left by the last unit?); nothing was written: reset the alarm and test again</source>
        <translation>검사 전에 알람이 발생해 있습니다(이전 제품이 남긴 알람?). 아무것도 쓰지 않았습니다: 알람을 리셋하고 다시 검사하십시오</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="219"/>
        <source>writing the settings</source>
        <translation>설정 쓰는 중</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="224"/>
        <source>writing the settings: %1</source>
        <translation>설정 쓰는 중: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="233"/>
        <source>reading every setting back</source>
        <translation>모든 설정을 다시 읽는 중</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="238"/>
        <source>verifying the settings: %1</source>
        <translation>설정 검증 중: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="252"/>
        <source>arming the communication-loss stop</source>
        <translation>통신 두절 정지를 설정하는 중</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="266"/>
        <source>testing</source>
        <translation>검사 중</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="270"/>
        <source>step %1 of %2: %3</source>
        <translation>단계 %1/%2: %3</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="335"/>
        <source>passed</source>
        <translation>합격</translation>
    </message>
</context>
<context>
    <name>opentop::EolMenu</name>
    <message>
        <location filename="../ui/eol/EolMenu.cpp" line="38"/>
        <source>&amp;Recipe editor…</source>
        <translation>레시피 편집기(&amp;R)…</translation>
    </message>
    <message>
        <location filename="../ui/eol/EolMenu.cpp" line="51"/>
        <source>the recipe editor</source>
        <translation>레시피 편집기</translation>
    </message>
    <message>
        <location filename="../ui/eol/EolMenu.cpp" line="57"/>
        <source>Re&amp;sults…</source>
        <translation>결과(&amp;S)…</translation>
    </message>
</context>
<context>
    <name>opentop::EolRecipeApproveCommand</name>
    <message>
        <location filename="../cli/EolRecipeApproveCommand.cpp" line="35"/>
        <source>Approve a signed recipe for the line (an engineer): stations then run it</source>
        <translation>서명된 레시피를 라인용으로 승인(엔지니어): 이후 스테이션에서 실행됩니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeApproveCommand.cpp" line="41"/>
        <source>Results database: an SQLite file or postgresql://user@host/db.</source>
        <translation>결과 데이터베이스: SQLite 파일 또는 postgresql://user@host/db.</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeApproveCommand.cpp" line="41"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeApproveCommand.cpp" line="49"/>
        <source>usage: opentop-cli eol %1</source>
        <translation>사용법: opentop-cli eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeApproveCommand.cpp" line="61"/>
        <source>%1: the recipe is not valid, so it cannot be approved:</source>
        <translation>%1: 레시피가 유효하지 않아 승인할 수 없습니다:</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeApproveCommand.cpp" line="80"/>
        <source>error: %1; the recipe was not approved</source>
        <translation>오류: %1. 레시피는 승인되지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeApproveCommand.cpp" line="98"/>
        <source>%1 rev. %2 approved by %3 (approval %4, checksum %5)</source>
        <translation>%1 rev. %2을(를) %3이(가) 승인했습니다(승인 %4, 체크섬 %5)</translation>
    </message>
</context>
<context>
    <name>opentop::EolRecipeCheckCommand</name>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="27"/>
        <source>Check a recipe against the drive profiles (and per-unit values of a CSV file)</source>
        <translation>레시피를 드라이버 프로파일(및 CSV 파일의 제품별 값)과 대조하여 검사합니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="33"/>
        <source>recipe check: also check every unit&apos;s per-unit values in this CSV file.</source>
        <translation>recipe check: 이 CSV 파일에 있는 모든 제품의 제품별 값도 검사합니다.</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="34"/>
        <source>CSV</source>
        <translation>CSV</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="55"/>
        <source>error: %1 refused: %2</source>
        <translation>오류: %1 거부됨: %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="65"/>
        <source>%1, serial %2</source>
        <translation>%1, 시리얼 %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="91"/>
        <source>error: %1</source>
        <translation>오류: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="93"/>
        <source>%1 is not valid: %n problem(s); nothing may be run with it</source>
        <translation>
            <numerusform>%1이(가) 올바르지 않습니다: 문제 %n건. 이 레시피로는 아무것도 실행할 수 없습니다</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="102"/>
        <source>valid: %1 revision %2: %3</source>
        <translation>유효: %1 개정 %2: %3</translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="107"/>
        <source>; %n unit(s) of %1 checked</source>
        <translation>
            <numerusform>; %1의 제품 %n대 검사함</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::EolRecipeCreateCommand</name>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="39"/>
        <source>Make a recipe from a golden unit: a backup file or drives on the bus</source>
        <translation>기준 제품(골든 유닛)으로 레시피를 만듭니다: 백업 파일 또는 버스의 드라이버</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="45"/>
        <source>recipe create: the golden unit&apos;s backup file.</source>
        <translation>recipe create: 기준 제품의 백업 파일.</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="46"/>
        <source>FILE</source>
        <translation>FILE</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="48"/>
        <source>recipe create: the golden unit&apos;s drives on the bus, e.g. 1,2 (with the connection options).</source>
        <translation>recipe create: 버스에 있는 기준 제품의 드라이버, 예: 1,2 (연결 옵션과 함께).</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="50"/>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="51"/>
        <source>recipe create: the product&apos;s name.</source>
        <translation>recipe create: 제품 이름.</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="51"/>
        <source>NAME</source>
        <translation>NAME</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="52"/>
        <source>recipe create: the recipe&apos;s revision.</source>
        <translation>recipe create: 레시피 개정.</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="52"/>
        <source>REV</source>
        <translation>REV</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="54"/>
        <source>recipe create: replace an existing recipe file.</source>
        <translation>recipe create: 기존 레시피 파일을 교체합니다.</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="56"/>
        <source>recipe create --drives: run the golden unit through the recipe&apos;s steps once (its motors turn) and take the hold limits from what it measured.</source>
        <translation>recipe create --drives: 기준 제품을 레시피 단계대로 한 번 운전하고(모터가 회전합니다) 측정값으로 유지 단계의 한계값을 정합니다.</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="59"/>
        <source>recipe create --measure: the margin around a measured value, in % of it (default 25; at least 5 % of the parameter&apos;s full scale).</source>
        <translation>recipe create --measure: 측정값 주위의 여유, 측정값의 %로 지정 (기본 25, 최소 해당 파라미터 풀스케일의 5 %).</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="61"/>
        <source>PERCENT</source>
        <translation>퍼센트</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="62"/>
        <source>recipe create --measure: run the motors.</source>
        <translation>recipe create --measure: 모터 운전을 확인합니다.</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="76"/>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="177"/>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="282"/>
        <source>error: %1; nothing written</source>
        <translation>오류: %1; 아무것도 저장하지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="118"/>
        <source>nothing written</source>
        <translation>아무것도 저장하지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="91"/>
        <source>%1: %2 settings read</source>
        <translation>%1: 설정 %2개 읽음</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="106"/>
        <source>interrupted while reading the golden unit: nothing written</source>
        <translation>기준 제품을 읽는 중 중단됨: 아무것도 저장하지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="112"/>
        <source>note: %1</source>
        <translation>참고: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="117"/>
        <source>give its variant with --variant %1=VARIANT</source>
        <translation>--variant %1=기종 으로 기종을 지정하십시오</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="133"/>
        <source>Would run the golden unit through the recipe&apos;s steps:</source>
        <translation>기준 제품을 레시피 단계대로 운전하려고 합니다:</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="136"/>
        <source>This turns motors: add --yes to run them. Nothing was run; nothing written.</source>
        <translation>모터가 회전합니다. 운전하려면 --yes를 붙이십시오. 아무것도 운전하지 않았고 아무것도 저장하지 않았습니다.</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="141"/>
        <source>measuring the golden unit (Ctrl-C stops every motor):</source>
        <translation>기준 제품 측정 중 (Ctrl-C로 모든 모터 정지):</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="150"/>
        <source>drive %1: %2</source>
        <translation>드라이버 %1: %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="162"/>
        <source>interrupted</source>
        <translation>중단됨</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="175"/>
        <source>WARNING: %1 is not confirmed stopped</source>
        <translation>경고: %1의 정지가 확인되지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="185"/>
        <source>limits from the golden unit:</source>
        <translation>기준 제품으로 정한 한계값:</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="189"/>
        <source>  drive %1, step %2: %3</source>
        <translation>  드라이버 %1, 단계 %2: %3</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="213"/>
        <source>error: %1; usage: eol %2</source>
        <translation>오류: %1; 사용법: eol %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="218"/>
        <source>unexpected argument &quot;%1&quot;</source>
        <translation>예상치 못한 인수 &quot;%1&quot;</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="222"/>
        <source>give either --from-backup FILE or --drives LIST</source>
        <translation>--from-backup FILE 또는 --drives LIST 중 하나를 지정하십시오</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="225"/>
        <source>--measure needs the golden unit on the bus: give --drives LIST</source>
        <translation>--measure에는 버스에 연결된 기준 제품이 필요합니다: --drives 목록을 지정하십시오</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="231"/>
        <source>--margin is for --measure</source>
        <translation>--margin은 --measure와 함께 씁니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="233"/>
        <source>--margin %1: give a percentage from 1 to 100</source>
        <translation>--margin %1: 1에서 100 사이의 퍼센트를 지정하십시오</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="239"/>
        <source>give the product&apos;s name with --product NAME</source>
        <translation>--product NAME으로 제품 이름을 지정하십시오</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="241"/>
        <source>give the recipe&apos;s revision with --revision REV</source>
        <translation>--revision REV로 레시피 개정을 지정하십시오</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="244"/>
        <source>give the recipe file to write with -o RECIPE</source>
        <translation>-o RECIPE로 저장할 레시피 파일을 지정하십시오</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="248"/>
        <source>error: %1 exists; give --force to replace it</source>
        <translation>오류: %1이(가) 이미 있습니다. 교체하려면 --force를 주십시오</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="253"/>
        <source>error: %1; nothing read</source>
        <translation>오류: %1; 아무것도 읽지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="272"/>
        <source>--drives %1: %2</source>
        <translation>--drives %1: %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="115"/>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="290"/>
        <source>error: %1</source>
        <translation>오류: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="308"/>
        <source>wrote %1: %2 revision %3, %4</source>
        <translation>%1 저장함: %2 개정 %3, %4</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="316"/>
        <source>error: the recipe does not pass &quot;eol recipe check&quot;: fix it, then sign it with &quot;opentop-cli eol recipe sign %1&quot;</source>
        <translation>오류: 레시피가 &quot;eol recipe check&quot;를 통과하지 못합니다. 수정한 뒤 &quot;opentop-cli eol recipe sign %1&quot;로 서명하십시오</translation>
    </message>
</context>
<context>
    <name>opentop::EolRecipeShowCommand</name>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="61"/>
        <source>Show a recipe: positions, settings by label with units, steps and limits</source>
        <translation>레시피를 표시합니다: 위치, 표시 이름과 단위를 붙인 설정, 단계와 한계값</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="72"/>
        <source>&apos;%1&apos;</source>
        <translation>&apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="73"/>
        <source>&apos;%1&apos; %2</source>
        <translation>&apos;%1&apos; %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="74"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="88"/>
        <source>  no settings</source>
        <translation>  설정 없음</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="90"/>
        <source>  setting</source>
        <translation>  설정</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="90"/>
        <source>value</source>
        <translation>값</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="90"/>
        <source>unit</source>
        <translation>단위</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="100"/>
        <source>  per-unit value</source>
        <translation>  제품별 값</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="100"/>
        <source>range</source>
        <translation>범위</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="100"/>
        <source>from</source>
        <translation>출처</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="103"/>
        <source>%1 … %2</source>
        <translation>%1 … %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="106"/>
        <source>CSV file by serial</source>
        <translation>시리얼 번호별 CSV 파일</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="107"/>
        <source>typed by the operator</source>
        <translation>작업자 입력</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="112"/>
        <source>  no test steps</source>
        <translation>  검사 단계 없음</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="115"/>
        <source>  steps:</source>
        <translation>  단계:</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="174"/>
        <source>%1, revision %2</source>
        <translation>%1, 개정 %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="180"/>
        <source>serial numbers: %1</source>
        <translation>시리얼 번호: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="181"/>
        <source>checksum %1</source>
        <translation>체크섬 %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="182"/>
        <source>position</source>
        <translation>위치</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="182"/>
        <source>machine number</source>
        <translation>국번</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="182"/>
        <source>name</source>
        <translation>이름</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="182"/>
        <source>family</source>
        <translation>제품군</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="183"/>
        <source>variants</source>
        <translation>기종</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="183"/>
        <source>firmware</source>
        <translation>펌웨어</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="194"/>
        <source>any</source>
        <translation>모두</translation>
    </message>
</context>
<context>
    <name>opentop::EolRecipeSignCommand</name>
    <message>
        <location filename="../cli/EolRecipeSignCommand.cpp" line="27"/>
        <source>Accept a recipe edited by hand: a new checksum, only when it passes check</source>
        <translation>손으로 편집한 레시피를 승인합니다: 검사를 통과할 때만 새 체크섬을 붙입니다</translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolRecipeSignCommand.cpp" line="49"/>
        <source>error: %1 does not pass check (%n problem(s)); not signed</source>
        <translation>
            <numerusform>오류: %1이(가) 검사를 통과하지 못했습니다(문제 %n건). 서명하지 않았습니다</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeSignCommand.cpp" line="57"/>
        <source>error: %1; not signed</source>
        <translation>오류: %1; 서명하지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeSignCommand.cpp" line="70"/>
        <source>%1 is signed already (%2); nothing changed</source>
        <translation>%1은(는) 이미 서명되어 있습니다(%2). 변경 사항 없음</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeSignCommand.cpp" line="74"/>
        <source>signed %1: %2 revision %3, %4</source>
        <translation>%1 서명함: %2 개정 %3, %4</translation>
    </message>
</context>
<context>
    <name>opentop::EolResultsCommand</name>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="74"/>
        <source>List units of the results database, their first-pass yield, or export them as CSV</source>
        <translation>결과 데이터베이스의 제품 목록, 직행률을 표시하거나 CSV로 내보냅니다</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="81"/>
        <source>The results database: a SQLite file, sqlite:PATH or postgresql://user@host/db (default: OPENTOP_EOL_DB, else ~/.local/share/opentop/results.db).</source>
        <translation>결과 데이터베이스: SQLite 파일, sqlite:PATH 또는 postgresql://user@host/db (기본값: OPENTOP_EOL_DB, 없으면 ~/.local/share/opentop/results.db).</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="83"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="85"/>
        <source>results: only this serial number; with * or ? a pattern that ignores case (&quot;SN-10*&quot;).</source>
        <translation>results: 이 일련번호만. * 또는 ?가 있으면 대소문자를 구분하지 않는 패턴(&quot;SN-10*&quot;).</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="87"/>
        <source>S</source>
        <translation>S</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="89"/>
        <source>results: started at or after T (2026-11-24, 2026-11-24T06:00, 8h, 2d, today).</source>
        <translation>results: T 또는 그 이후에 시작한 것 (2026-11-24, 2026-11-24T06:00, 8h, 2d, today).</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="90"/>
        <location filename="../cli/EolResultsCommand.cpp" line="91"/>
        <source>T</source>
        <translation>T</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="91"/>
        <source>results: started before T.</source>
        <translation>results: T 이전에 시작한 것.</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="92"/>
        <source>results: only this recipe (product name).</source>
        <translation>results: 이 레시피(제품 이름)만.</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="92"/>
        <location filename="../cli/EolResultsCommand.cpp" line="100"/>
        <source>NAME</source>
        <translation>NAME</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="99"/>
        <source>V</source>
        <translation>V</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="100"/>
        <source>results: only this station.</source>
        <translation>results: 이 스테이션만.</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="101"/>
        <source>results: only the newest N units.</source>
        <translation>results: 최신 제품 N대만.</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="101"/>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="103"/>
        <source>results: CSV (RFC 4180) on standard output or to -o FILE.</source>
        <translation>results: CSV(RFC 4180)를 표준 출력 또는 -o FILE로.</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="108"/>
        <source>results --yield: the shifts&apos; start times in local time (default 06:00,14:00,22:00).</source>
        <translation>results --yield: 근무조 시작 시각(현지 시간, 기본값 06:00,14:00,22:00).</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="109"/>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="141"/>
        <source>&quot;%1&quot; is not a time; give 2026-11-24, 2026-11-24T06:00 (local, or with Z or +01:00), 8h, 2d, today or yesterday</source>
        <translation>&quot;%1&quot;은(는) 시각이 아닙니다. 2026-11-24, 2026-11-24T06:00 (현지 시간, 또는 Z나 +01:00 포함), 8h, 2d, today 또는 yesterday를 주십시오</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="151"/>
        <location filename="../cli/EolResultsCommand.cpp" line="297"/>
        <source>error: %1</source>
        <translation>오류: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="167"/>
        <source>--%1: %2</source>
        <translation>--%1: %2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="172"/>
        <source>--since %1 is not before --until %2</source>
        <translation>--since %1이(가) --until %2보다 이전이 아닙니다</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="94"/>
        <source>results: only this version of a recipe (its checksum, as eol recipe check prints it).</source>
        <translation>results: 이 버전의 레시피만(eol recipe check가 출력하는 체크섬으로 지정).</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="96"/>
        <source>SUM</source>
        <translation>SUM</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="98"/>
        <source>results: pass, fail, error (station error), interrupted, aborted or running.</source>
        <translation>results: pass, fail, error(스테이션 오류), interrupted, aborted 또는 running.</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="105"/>
        <source>results: first-, second- and last-pass yield and failure reasons per recipe version and per shift; station errors and aborts are kept out of yield.</source>
        <translation>results: 레시피 버전별·근무조별 직행률, 2회 이내 합격률, 최종 합격률과 불합격 원인. 스테이션 오류와 중지는 수율에 넣지 않습니다.</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="178"/>
        <source>--verdict &quot;%1&quot;: give pass, fail, error, interrupted, aborted or running</source>
        <translation>--verdict &quot;%1&quot;: pass, fail, error, interrupted, aborted 또는 running을 지정하십시오</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="186"/>
        <source>--limit &quot;%1&quot;: give a number of units from 1</source>
        <translation>--limit &quot;%1&quot;: 1 이상의 제품 수를 주십시오</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="196"/>
        <location filename="../cli/EolResultsCommand.cpp" line="226"/>
        <source>no unit matches</source>
        <translation>일치하는 제품 없음</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="199"/>
        <source>started</source>
        <translation>시작</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="199"/>
        <source>serial</source>
        <translation>시리얼</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="199"/>
        <location filename="../cli/EolResultsCommand.cpp" line="230"/>
        <source>recipe</source>
        <translation>레시피</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="199"/>
        <source>station</source>
        <translation>스테이션</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="199"/>
        <source>approved by</source>
        <translation>승인자</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="200"/>
        <source>operator</source>
        <translation>작업자</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="200"/>
        <source>verdict</source>
        <translation>판정</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="200"/>
        <source>time</source>
        <translation>시간</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="200"/>
        <source>reason</source>
        <translation>원인</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="200"/>
        <source>drives</source>
        <translation>드라이버</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="209"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="211"/>
        <source>%1 rev. %2</source>
        <translation>%1 개정 %2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="232"/>
        <source>shift</source>
        <translation>근무조</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="233"/>
        <source>serials</source>
        <translation>시리얼 수</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="233"/>
        <source>first pass</source>
        <translation>1회 합격</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="233"/>
        <source>second pass</source>
        <translation>2회 이내 합격</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="233"/>
        <source>last pass</source>
        <translation>최종 합격</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="234"/>
        <source>passed</source>
        <translation>합격</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="234"/>
        <source>failed</source>
        <translation>불합격</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="234"/>
        <source>station errors</source>
        <translation>스테이션 오류</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="254"/>
        <source>Yield per recipe version (station errors and aborts are not counted)</source>
        <translation>레시피 버전별 수율 (스테이션 오류와 중지는 집계하지 않음)</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="263"/>
        <source>%1: checksum %2</source>
        <translation>%1: 체크섬 %2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="234"/>
        <source>not finished</source>
        <translation>미완료</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="266"/>
        <source>Per shift</source>
        <translation>근무조별</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="282"/>
        <source>Failure reasons</source>
        <translation>불합격 원인</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="283"/>
        <source>Station errors (not counted in yield)</source>
        <translation>스테이션 오류 (수율에 집계하지 않음)</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="300"/>
        <source>wrote %1</source>
        <translation>%1 저장함</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="308"/>
        <source>error: unexpected argument &quot;%1&quot;; usage: eol %2</source>
        <translation>오류: 예상치 못한 인수 &quot;%1&quot;; 사용법: eol %2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="315"/>
        <source>error: give --csv or --json, not both</source>
        <translation>오류: --csv와 --json 중 하나만 주십시오</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="319"/>
        <source>error: -o names the CSV file: give --csv too</source>
        <translation>오류: -o는 CSV 파일을 지정합니다: --csv도 주십시오</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="324"/>
        <source>error: --shifts is for --yield</source>
        <translation>오류: --shifts는 --yield와 함께 씁니다</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="333"/>
        <source>error: --shifts %1: %2</source>
        <translation>오류: --shifts %1: %2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="352"/>
        <location filename="../cli/EolResultsCommand.cpp" line="382"/>
        <location filename="../cli/EolResultsCommand.cpp" line="393"/>
        <source>error: %1: %2</source>
        <translation>오류: %1: %2</translation>
    </message>
</context>
<context>
    <name>opentop::EolRun</name>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="59"/>
        <source>recording the unit before anything is sent</source>
        <translation>전송하기 전에 제품을 기록하는 중</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="65"/>
        <source>the results database cannot record the unit: %1</source>
        <translation>결과 데이터베이스에 제품을 기록할 수 없습니다: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="98"/>
        <source>the recipe has no drives</source>
        <translation>레시피에 드라이버가 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="111"/>
        <source>the recipe is not valid: %1</source>
        <translation>레시피가 올바르지 않습니다: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="116"/>
        <source>%1: no value for %2 for this unit</source>
        <translation>%1: 이 제품의 %2 값이 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="134"/>
        <source>cancelled by the operator</source>
        <translation>작업자가 취소함</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="145"/>
        <source>the connection was lost: %1</source>
        <translation>연결이 끊겼습니다: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="153"/>
        <location filename="../model/eol/EolRun.cpp" line="161"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="158"/>
        <source>%1 failed</source>
        <translation>%1 실패</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="198"/>
        <source>NOT CONFIRMED STOPPED: %1</source>
        <translation>정지 확인 안 됨: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="207"/>
        <source>recording the result</source>
        <translation>결과를 기록하는 중</translation>
    </message>
</context>
<context>
    <name>opentop::EolRunCommand</name>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="59"/>
        <source>Set up and test one unit at the end of the line; record the result</source>
        <translation>라인 끝에서 제품 하나를 설정·검사하고 결과를 기록합니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="65"/>
        <source>The unit&apos;s serial number (as its barcode reads).</source>
        <translation>제품의 시리얼 번호(바코드에 읽히는 그대로).</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="65"/>
        <source>S</source>
        <translation>S</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="66"/>
        <source>Who tests it, on a station without users (default: the login name).</source>
        <translation>사용자가 없는 스테이션에서 검사하는 사람(기본값: 로그인 이름).</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="67"/>
        <location filename="../cli/EolRunCommand.cpp" line="69"/>
        <source>NAME</source>
        <translation>NAME</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="69"/>
        <source>This station&apos;s name (default: the host name).</source>
        <translation>이 스테이션의 이름(기본값: 호스트 이름).</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="70"/>
        <source>Results database: an SQLite file or postgresql://user@host/db.</source>
        <translation>결과 데이터베이스: SQLite 파일 또는 postgresql://user@host/db.</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="70"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="71"/>
        <source>CSV file with the per-unit values, by serial number.</source>
        <translation>시리얼 번호별 제품별 값이 들어 있는 CSV 파일.</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="71"/>
        <source>CSV</source>
        <translation>CSV</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="72"/>
        <source>A per-unit value typed by the operator, e.g. 1:spno3.speed=1500.</source>
        <translation>작업자가 입력하는 제품별 값, 예: 1:spno3.speed=1500.</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="73"/>
        <source>ID:NAME=VALUE</source>
        <translation>ID:NAME=VALUE</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="75"/>
        <source>A technician allows a retest the recipe&apos;s rules hold back (a serial that passed already, or its attempts used up).</source>
        <translation>레시피 규칙으로 막힌 재검사(이미 합격한 시리얼, 또는 검사 횟수를 다 쓴 시리얼)를 기술자가 허가합니다.</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="109"/>
        <source>--value %1: write it as MACHINE:NAME=VALUE, e.g. 1:spno3.speed=1500</source>
        <translation>--value %1: MACHINE:NAME=VALUE 형식으로 쓰십시오. 예: 1:spno3.speed=1500</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="114"/>
        <source>--value %1: %2</source>
        <translation>--value %1: %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="137"/>
        <source>--variant %1: %2 allows %3; nothing was sent</source>
        <translation>--variant %1: %2은(는) %3을(를) 허용합니다. 아무것도 보내지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="139"/>
        <source>any %1 variant</source>
        <translation>모든 %1 기종</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="148"/>
        <source>--variant %1: the recipe has no position at machine number %2; nothing was sent</source>
        <translation>--variant %1: 레시피에 국번 %2의 위치가 없습니다. 아무것도 보내지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="162"/>
        <source>usage: opentop-cli eol %1</source>
        <translation>사용법: opentop-cli eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="178"/>
        <source>%1: the recipe is not valid; nothing was sent:</source>
        <translation>%1: 레시피가 올바르지 않습니다. 아무것도 보내지 않았습니다:</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="188"/>
        <source>--serial: %1; nothing was sent</source>
        <translation>--serial: %1. 아무것도 보내지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="217"/>
        <source>results database: %1; nothing was sent</source>
        <translation>결과 데이터베이스: %1; 아무것도 보내지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="223"/>
        <source>note: unit %1 (begun %2) was left unfinished by a station process that is gone; it is now recorded as interrupted. Check that its motor is stopped.</source>
        <translation>참고: 유닛 %1(%2 시작)은 스테이션 프로세스가 종료되어 완료되지 않았으며, 이제 &apos;중단됨&apos;으로 기록되었습니다. 모터가 정지했는지 확인하십시오.</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="228"/>
        <source>note: %1 result(s) kept on this station could not be sent to the results database yet</source>
        <translation>참고: 이 스테이션에 보관된 결과 %1건을 아직 결과 데이터베이스로 보내지 못했습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="317"/>
        <source>error: %1; nothing was sent</source>
        <translation>오류: %1. 아무것도 보내지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="320"/>
        <source>a technician allows it with --retest</source>
        <translation>기술자가 --retest로 허가할 수 있습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="269"/>
        <source>note: %1; tested again as --retest allows</source>
        <translation>참고: %1. --retest의 허가로 다시 검사합니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="273"/>
        <source>note: %1</source>
        <translation>참고: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="280"/>
        <source>station: %1</source>
        <translation>스테이션: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="326"/>
        <source>a drive of the station is not confirmed stopped; nothing was tested</source>
        <translation>스테이션의 드라이브 중 정지가 확인되지 않은 것이 있습니다. 아무것도 검사하지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="298"/>
        <source>interrupted at the station</source>
        <translation>스테이션에서 중단됨</translation>
    </message>
</context>
<context>
    <name>opentop::EolRunIdentity</name>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="50"/>
        <location filename="../cli/EolRunIdentity.cpp" line="88"/>
        <source>the results database is not open</source>
        <translation>결과 데이터베이스가 열려 있지 않습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="53"/>
        <location filename="../cli/EolRunIdentity.cpp" line="101"/>
        <source>results database: %1; nothing was sent</source>
        <translation>결과 데이터베이스: %1; 아무것도 보내지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="65"/>
        <location filename="../cli/EolRunIdentity.cpp" line="107"/>
        <source>refused: %1; nothing was sent</source>
        <translation>거부됨: %1. 아무것도 보내지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="66"/>
        <source>this station has users: name who tests with --user NAME (the password from OPENTOP_PASSWORD or the terminal)</source>
        <translation>이 스테이션에는 사용자가 있습니다: --user NAME으로 검사하는 사람을 지정하십시오(비밀번호는 OPENTOP_PASSWORD 또는 터미널에서)</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="73"/>
        <source>error: on a station with users the operator is the user who logs in (--user); --operator is not taken</source>
        <translation>오류: 사용자가 있는 스테이션에서는 로그인한 사용자(--user)가 작업자입니다. --operator는 받지 않습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="98"/>
        <source>run-units: recipe checksum %1 is not approved</source>
        <translation>run-units: 레시피 체크섬 %1은(는) 승인되지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="113"/>
        <source>refused: %1 Nothing was sent.</source>
        <translation>거부됨: %1 아무것도 보내지 않았습니다.</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="123"/>
        <source>%1 logged in; recipe approved by %2 (approval %3)</source>
        <translation>%1 로그인. 레시피 승인자 %2(승인 %3)</translation>
    </message>
</context>
<context>
    <name>opentop::EolRunOutput</name>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="98"/>
        <location filename="../cli/EolRunOutput.cpp" line="121"/>
        <source>drive %1</source>
        <translation>드라이버 %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="129"/>
        <source>ok</source>
        <translation>정상</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="129"/>
        <source>FAIL</source>
        <translation>불합격</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="165"/>
        <source>rev. %1</source>
        <translation>개정 %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="167"/>
        <source>attempt %1</source>
        <translation>%1회차 검사</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="174"/>
        <source>the result was NOT recorded: %1</source>
        <translation>결과가 기록되지 않았습니다: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="178"/>
        <source>the results database did not answer: the result is kept on this station (%1) and sent when a station program next reaches the database</source>
        <translation>결과 데이터베이스가 응답하지 않습니다: 결과는 이 스테이션(%1)에 보관되며, 스테이션 프로그램이 다음에 데이터베이스에 연결될 때 전송됩니다</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="183"/>
        <source>WARNING: motor not confirmed stopped: %1</source>
        <translation>경고: 모터 정지가 확인되지 않았습니다: %1</translation>
    </message>
</context>
<context>
    <name>opentop::EolSettingsWriter</name>
    <message>
        <location filename="../model/eol/EolSettingsWriter.cpp" line="69"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/EolSettingsWriter.cpp" line="95"/>
        <source>%1 cannot be read back: %2</source>
        <translation>%1을(를) 다시 읽을 수 없습니다: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/EolSettingsWriter.cpp" line="101"/>
        <source>%1 does not keep its value: set to %2, reads %3</source>
        <translation>%1이(가) 값을 유지하지 않습니다: %2(으)로 설정했지만 %3(으)로 읽힘</translation>
    </message>
</context>
<context>
    <name>opentop::EolSpeedChart</name>
    <message>
        <location filename="../ui/eol/EolSpeedChart.cpp" line="20"/>
        <source>time (s)</source>
        <translation>시간 (s)</translation>
    </message>
    <message>
        <location filename="../ui/eol/EolSpeedChart.cpp" line="44"/>
        <source>speed</source>
        <translation>속도</translation>
    </message>
    <message>
        <location filename="../ui/eol/EolSpeedChart.cpp" line="44"/>
        <location filename="../ui/eol/EolSpeedChart.cpp" line="57"/>
        <source>speed (%1)</source>
        <translation>속도 (%1)</translation>
    </message>
    <message>
        <location filename="../ui/eol/EolSpeedChart.cpp" line="52"/>
        <source>drive %1</source>
        <translation>드라이버 %1</translation>
    </message>
</context>
<context>
    <name>opentop::EolStation</name>
    <message>
        <location filename="../model/station/EolStation.cpp" line="121"/>
        <source>a unit is being tested</source>
        <translation>제품 검사 중</translation>
    </message>
    <message>
        <location filename="../model/station/EolStation.cpp" line="125"/>
        <source>open a recipe first</source>
        <translation>먼저 레시피를 여십시오</translation>
    </message>
    <message>
        <location filename="../model/station/EolStation.cpp" line="145"/>
        <source>run-units: serial %1: %2</source>
        <translation>run-units: 시리얼 번호 %1: %2</translation>
    </message>
    <message>
        <location filename="../model/station/EolStation.cpp" line="149"/>
        <source>not connected to a bus</source>
        <translation>버스에 연결되어 있지 않음</translation>
    </message>
    <message>
        <location filename="../model/station/EolStation.cpp" line="153"/>
        <source>unit %1 starts as soon as the station&apos;s drives are safe</source>
        <translation>스테이션의 드라이브가 안전해지는 즉시 유닛 %1 검사가 시작됩니다</translation>
    </message>
    <message>
        <location filename="../model/station/EolStation.cpp" line="185"/>
        <source>serial %1 tested again, allowed by %2: %3</source>
        <translation>시리얼 %1 재시험, %2 허가: %3</translation>
    </message>
    <message>
        <location filename="../model/station/EolStation.cpp" line="227"/>
        <source>no unit was started yet</source>
        <translation>아직 검사를 시작한 제품이 없습니다</translation>
    </message>
</context>
<context>
    <name>opentop::EolStepRunner</name>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="118"/>
        <source>step %1 (%2)</source>
        <translation>단계 %1 (%2)</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="124"/>
        <location filename="../model/eol/EolStepRunner.cpp" line="148"/>
        <source>the drive&apos;s session ended</source>
        <translation>드라이버 세션이 끝났습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="197"/>
        <location filename="../model/eol/EolStepRunner.cpp" line="215"/>
        <location filename="../model/eol/EolStepRunner.cpp" line="225"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="209"/>
        <source>%1: the drive has no communication priority</source>
        <translation>%1: 드라이버가 통신 우선이 아닙니다</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="256"/>
        <source>the stop command failed: %1</source>
        <translation>정지 명령 실패: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="269"/>
        <source>stopped after %1 s</source>
        <translation>%1 s 후 정지</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="270"/>
        <source>not confirmed stopped: %1</source>
        <translation>정지 확인 안 됨: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="326"/>
        <source>communication priority could not be given back: %1</source>
        <translation>통신 우선을 되돌릴 수 없습니다: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="157"/>
        <source>the steps ended with the motor running</source>
        <translation>모터가 운전 중인 상태로 단계가 끝났습니다</translation>
    </message>
</context>
<context>
    <name>opentop::EolSupport</name>
    <message>
        <location filename="../cli/EolSupport.cpp" line="26"/>
        <source>error: name one recipe file; usage: eol %1</source>
        <translation>오류: 레시피 파일 하나를 지정하십시오. 사용법: eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="39"/>
        <source>no such file</source>
        <translation>파일이 없습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="41"/>
        <source>is a directory; name a recipe file</source>
        <translation>디렉터리입니다. 레시피 파일을 지정하십시오</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="43"/>
        <source>is not a regular file (a device, FIFO or socket); name a recipe file</source>
        <translation>일반 파일이 아닙니다(장치, FIFO 또는 소켓). 레시피 파일을 지정하십시오</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="45"/>
        <source>is larger than %1 MB, the most a recipe file may hold</source>
        <translation>레시피 파일의 최대 크기 %1 MB보다 큽니다</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="49"/>
        <source>cannot be read: %1</source>
        <translation>읽을 수 없습니다: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="51"/>
        <location filename="../cli/EolSupport.cpp" line="177"/>
        <source>error: %1: %2</source>
        <translation>오류: %1: %2</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="78"/>
        <location filename="../cli/EolSupport.cpp" line="199"/>
        <source>error: %1</source>
        <translation>오류: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="86"/>
        <source>error: %1 refused: %2</source>
        <translation>오류: %1 거부됨: %2</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="95"/>
        <source>%1 was changed after OpenTOP wrote it (its checksum does not match), so no station runs it. Check it with &quot;opentop-cli eol recipe check %1&quot; and, when it is right, sign it with &quot;opentop-cli eol recipe sign %1&quot;</source>
        <translation>%1이(가) OpenTOP에서 저장한 후 변경되었으므로(체크섬 불일치) 어느 스테이션에서도 실행하지 않습니다. &quot;opentop-cli eol recipe check %1&quot;로 검사하고, 올바르면 &quot;opentop-cli eol recipe sign %1&quot;로 서명하십시오</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="113"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolSupport.cpp" line="140"/>
        <source>%n position(s)</source>
        <translation>
            <numerusform>위치 %n개</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolSupport.cpp" line="141"/>
        <source>%n setting(s)</source>
        <translation>
            <numerusform>설정 %n개</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolSupport.cpp" line="143"/>
        <source>%n per-unit value(s)</source>
        <translation>
            <numerusform>제품별 값 %n개</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolSupport.cpp" line="144"/>
        <source>%n step(s)</source>
        <translation>
            <numerusform>단계 %n개</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="151"/>
        <source>The file to write (recipe create; results --csv; certificate).</source>
        <translation>저장할 파일(recipe create; results --csv; certificate).</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="152"/>
        <source>FILE</source>
        <translation>FILE</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="188"/>
        <source>error: no results database at %1 (nothing recorded there yet); name one with --db URL</source>
        <translation>오류: %1에 결과 데이터베이스가 없습니다(아직 기록된 것 없음). --db URL로 지정하십시오</translation>
    </message>
</context>
<context>
    <name>opentop::EolTarget</name>
    <message>
        <location filename="../model/eol/EolTarget.cpp" line="26"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/EolTarget.cpp" line="38"/>
        <location filename="../model/eol/EolTarget.cpp" line="49"/>
        <source>not a parameter of %1</source>
        <translation>%1의 파라미터가 아닙니다</translation>
    </message>
    <message>
        <location filename="../model/eol/EolTarget.cpp" line="51"/>
        <source>this unit&apos;s value is missing</source>
        <translation>이 제품의 값이 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/EolTarget.cpp" line="54"/>
        <source>%1 is outside this product&apos;s range %2–%3 %4</source>
        <translation>%1이(가) 이 제품의 범위 %2–%3 %4을(를) 벗어납니다</translation>
    </message>
</context>
<context>
    <name>opentop::EolUserCommand</name>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="72"/>
        <source>Add a user (operator, technician, engineer or administrator); the first user is an administrator and needs no --user</source>
        <translation>사용자 추가(작업자, 기술자, 엔지니어 또는 관리자). 첫 사용자는 관리자이며 --user가 필요 없습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="75"/>
        <source>List the users of the results database</source>
        <translation>결과 데이터베이스의 사용자 목록</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="77"/>
        <source>Disable a user: they can no longer log in; their records stay</source>
        <translation>사용자 비활성화: 더 이상 로그인할 수 없으며 기록은 남습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="81"/>
        <source>Set a user&apos;s password (your own with your old one, anyone&apos;s as administrator)</source>
        <translation>사용자 비밀번호 설정(본인 것은 기존 비밀번호로, 관리자는 누구의 것이든)</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="87"/>
        <source>Results database: an SQLite file or postgresql://user@host/db.</source>
        <translation>결과 데이터베이스: SQLite 파일 또는 postgresql://user@host/db.</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="87"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="90"/>
        <source>user add: operator, technician, engineer or administrator.</source>
        <translation>user add: operator, technician, engineer 또는 administrator.</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="92"/>
        <source>ROLE</source>
        <translation>역할</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="93"/>
        <source>user add: the name shown on the screen.</source>
        <translation>user add: 화면에 표시되는 이름.</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="94"/>
        <source>TEXT</source>
        <translation>텍스트</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="109"/>
        <location filename="../cli/EolUserCommand.cpp" line="168"/>
        <source>error: %1</source>
        <translation>오류: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="124"/>
        <source>no users: this station is unmanaged (anyone can run, edit and leave); add the first administrator with: opentop-cli eol user add NAME --role administrator</source>
        <translation>사용자 없음: 이 스테이션은 관리되지 않습니다(누구나 실행, 편집, 종료 가능). 첫 관리자 추가: opentop-cli eol user add NAME --role administrator</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="130"/>
        <source>user</source>
        <translation>사용자</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="130"/>
        <source>name</source>
        <translation>이름</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="130"/>
        <source>role</source>
        <translation>역할</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="130"/>
        <source>active</source>
        <translation>활성</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="130"/>
        <source>created</source>
        <translation>생성</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="133"/>
        <source>yes</source>
        <translation>예</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="133"/>
        <source>no (disabled)</source>
        <translation>아니요(비활성)</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="145"/>
        <source>usage: opentop-cli eol %1</source>
        <translation>사용법: opentop-cli eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="153"/>
        <source>error: --role is one of: %1</source>
        <translation>오류: --role은 다음 중 하나입니다: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="183"/>
        <source>Present password for %1: </source>
        <translation>%1의 현재 비밀번호: </translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="194"/>
        <location filename="../cli/EolUserCommand.cpp" line="216"/>
        <source>New password for %1: </source>
        <translation>%1의 새 비밀번호: </translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="203"/>
        <source>user %1 added as %2</source>
        <translation>사용자 %1을(를) %2(으)로 추가했습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="211"/>
        <source>user %1 disabled</source>
        <translation>사용자 %1을(를) 비활성화했습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="221"/>
        <source>password of %1 changed</source>
        <translation>%1의 비밀번호를 변경했습니다</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="230"/>
        <source>error: %1; nothing was changed</source>
        <translation>오류: %1. 아무것도 변경하지 않았습니다</translation>
    </message>
</context>
<context>
    <name>opentop::ExitActions</name>
    <message>
        <location filename="../model/run/ExitActions.cpp" line="50"/>
        <source>Machine number %1: left in communication priority, as it was not confirmed stopped</source>
        <translation>국번 %1: 정지가 확인되지 않아 통신 우선으로 남겨 두었습니다</translation>
    </message>
    <message>
        <location filename="../model/run/ExitActions.cpp" line="75"/>
        <source>The stop broadcast to the %1 drives failed: %2</source>
        <translation>드라이버 %1대에 보낸 정지 브로드캐스트가 실패했습니다: %2</translation>
    </message>
    <message>
        <location filename="../model/run/ExitActions.cpp" line="81"/>
        <source>Machine number %1: STILL RUNNING (%2) %3</source>
        <translation>국번 %1: 아직 운전 중 (%2) %3</translation>
    </message>
    <message>
        <location filename="../model/run/ExitActions.cpp" line="86"/>
        <source>Machine number %1: NO ANSWER, not confirmed stopped %2</source>
        <translation>국번 %1: 응답 없음, 정지 확인 안 됨 %2</translation>
    </message>
    <message>
        <location filename="../model/run/ExitActions.cpp" line="111"/>
        <source>Machine number %1: no way to give control back to its inputs is known</source>
        <translation>국번 %1: 입력 단자로 제어를 되돌리는 방법을 알 수 없습니다</translation>
    </message>
    <message>
        <location filename="../model/run/ExitActions.cpp" line="123"/>
        <source>Machine number %1: %2</source>
        <translation>국번 %1: %2</translation>
    </message>
</context>
<context>
    <name>opentop::ExitCheck</name>
    <message>
        <location filename="../model/run/ExitCheck.cpp" line="20"/>
        <source>in communication priority (its own inputs cannot start or stop it)</source>
        <translation>통신 우선 상태(자체 입력 단자로 기동·정지할 수 없음)</translation>
    </message>
    <message>
        <location filename="../model/run/ExitCheck.cpp" line="21"/>
        <source>Machine number %1 (%2): %3</source>
        <translation>국번 %1 (%2): %3</translation>
    </message>
</context>
<context>
    <name>opentop::ExitGuard</name>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="99"/>
        <source>Cancel</source>
        <translation>취소</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="134"/>
        <source>Stopping the drives, then giving control back to their inputs…</source>
        <translation>드라이버를 정지한 뒤 입력 단자로 제어를 되돌리는 중…</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="135"/>
        <source>Stopping the drives…</source>
        <translation>드라이버를 정지하는 중…</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="132"/>
        <source>Giving control back to the drives&apos; inputs…</source>
        <translation>드라이버 입력 단자로 제어를 되돌리는 중…</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="159"/>
        <source>Not every drive is safe</source>
        <translation>안전하지 않은 드라이버가 있습니다</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="160"/>
        <source>Could not %1 every drive:</source>
        <translation>모든 드라이버의 %1에 성공하지 못했습니다:</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="162"/>
        <source>Stay connected</source>
        <translation>연결 유지</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="163"/>
        <source>Go on anyway</source>
        <translation>그래도 계속</translation>
    </message>
</context>
<context>
    <name>opentop::ExitPlan</name>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="55"/>
        <source>Stop and give control back</source>
        <translation>정지 후 제어 반환</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="56"/>
        <source>Stop the drives</source>
        <translation>드라이버 정지</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="56"/>
        <source>Give control back (I/O priority)</source>
        <translation>제어 반환 (I/O 우선)</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="58"/>
        <source>Give control back only</source>
        <translation>제어 반환만</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="60"/>
        <source>Leave them running</source>
        <translation>운전 상태로 두기</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="60"/>
        <source>Leave them so</source>
        <translation>그대로 두기</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="70"/>
        <location filename="../model/run/ExitPlan.cpp" line="73"/>
        <source>give control back to</source>
        <translation>제어 반환</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="71"/>
        <source>stop</source>
        <translation>정지</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="71"/>
        <source>stop and give control back to</source>
        <translation>정지 및 제어 반환</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="82"/>
        <source>Drives are running</source>
        <translation>운전 중인 드라이버가 있습니다</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="82"/>
        <source>Drives left in communication priority</source>
        <translation>통신 우선으로 남아 있는 드라이버</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="88"/>
        <source>Before you %1: these drives are left in communication priority.</source>
        <translation>%1하기 전에: 다음 드라이버가 통신 우선으로 남아 있습니다.</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="89"/>
        <source>Before you %1: these drives are running or left in communication priority.</source>
        <translation>%1하기 전에: 다음 드라이버가 운전 중이거나 통신 우선으로 남아 있습니다.</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="101"/>
        <source>left as it is: it runs from its own inputs (I/O priority), which a stop over the bus does not override</source>
        <translation>그대로 둠: 자체 입력 단자로 운전 중(I/O 우선)이며, 버스로 보낸 정지 명령으로는 바꿀 수 없습니다</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="104"/>
        <source>stopped (confirmed by reading it), then given back to its own inputs (I/O priority, read back)</source>
        <translation>정지(읽어서 확인) 후 자체 입력 단자로 제어 반환(I/O 우선, 다시 읽기로 확인)</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="107"/>
        <source>stopped (confirmed by reading it); its family has no I/O priority setting, so it stays under the bus&apos;s control</source>
        <translation>정지(읽어서 확인). 이 제품군에는 I/O 우선 설정이 없으므로 계속 버스로 제어됩니다</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="110"/>
        <source>stopped (confirmed by reading it)</source>
        <translation>정지(읽어서 확인)</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="112"/>
        <source>given back to its own inputs (I/O priority, read back)</source>
        <translation>자체 입력 단자로 제어 반환(I/O 우선, 다시 읽기로 확인)</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="114"/>
        <source>left as it is: no way to give control back to its inputs is known</source>
        <translation>그대로 둠: 입력 단자로 제어를 되돌리는 방법을 알 수 없습니다</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="115"/>
        <source>   → %1</source>
        <translation>   → %1</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="122"/>
        <source>In communication priority a drive takes run and stop only from the bus: once OpenTOP lets go, only another bus master or switching its power off stops it.</source>
        <translation>통신 우선에서는 드라이버가 버스로만 운전·정지 명령을 받습니다: OpenTOP이 연결을 놓으면 다른 버스 마스터나 전원 차단으로만 정지할 수 있습니다.</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="126"/>
        <source>Stopping broadcasts every family&apos;s stop command to the whole bus and checks that each drive above has stopped; a drive that has not stopped is not given back to its inputs.</source>
        <translation>정지는 모든 제품군의 정지 명령을 버스 전체에 브로드캐스트하고 위의 각 드라이버가 정지했는지 확인합니다. 정지하지 않은 드라이버는 입력 단자로 제어를 되돌리지 않습니다.</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="131"/>
        <source>&quot;Give control back only&quot; sets I/O priority without a stop: the machine&apos;s own inputs decide at once whether the drives run.</source>
        <translation>&quot;제어 반환만&quot;은 정지하지 않고 I/O 우선으로 설정합니다: 드라이버의 운전 여부는 즉시 설비 자체의 입력 단자가 정합니다.</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="135"/>
        <source>&quot;Give control back&quot; sets I/O priority, so the machine&apos;s own inputs run the drives again.</source>
        <translation>&quot;제어 반환&quot;은 I/O 우선으로 설정하여 설비 자체의 입력 단자로 드라이버를 다시 운전하게 합니다.</translation>
    </message>
</context>
<context>
    <name>opentop::FaultInjector</name>
    <message>
        <location filename="../sim/FaultInjector.cpp" line="30"/>
        <source>fault &apos;%1&apos; must be NAME=VALUE; names: %2</source>
        <translation>결함 &apos;%1&apos;은(는) NAME=VALUE 형식이어야 합니다. 이름: %2</translation>
    </message>
    <message>
        <location filename="../sim/FaultInjector.cpp" line="38"/>
        <source>late_ms must be a whole number of milliseconds 1..60000, got &apos;%1&apos;</source>
        <translation>late_ms는 1..60000 밀리초의 정수여야 합니다. 입력값: &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../sim/FaultInjector.cpp" line="52"/>
        <source>unknown fault &apos;%1&apos;; allowed: %2</source>
        <translation>알 수 없는 결함 &apos;%1&apos;; 허용: %2</translation>
    </message>
    <message>
        <location filename="../sim/FaultInjector.cpp" line="57"/>
        <source>fault rate %1 must be a number 0..1, got &apos;%2&apos;</source>
        <translation>결함 비율 %1은(는) 0..1의 숫자여야 합니다. 입력값: &apos;%2&apos;</translation>
    </message>
    <message>
        <location filename="../sim/FaultInjector.cpp" line="64"/>
        <source>the fault rates add up to more than 1</source>
        <translation>결함 비율의 합이 1을 넘습니다</translation>
    </message>
</context>
<context>
    <name>opentop::FileActions</name>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="22"/>
        <source>OpenTOP backups (*.json);;All files (*)</source>
        <translation>OpenTOP 백업 (*.json);;모든 파일 (*)</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="38"/>
        <location filename="../ui/files/FileActions.cpp" line="94"/>
        <source>&amp;Back up selected drive…</source>
        <translation>선택한 드라이버 백업(&amp;B)…</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="44"/>
        <source>Back up &amp;whole bus…</source>
        <translation>버스 전체 백업(&amp;W)…</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="50"/>
        <source>Save the settings of every identified drive to one file</source>
        <translation>식별된 모든 드라이버의 설정을 파일 하나에 저장합니다</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="52"/>
        <source>&amp;Open backup file…</source>
        <translation>백업 파일 열기(&amp;O)…</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="54"/>
        <source>Show the drives and settings a backup file holds</source>
        <translation>백업 파일에 들어 있는 드라이버와 설정을 표시합니다</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="55"/>
        <source>Co&amp;mpare…</source>
        <translation>비교(&amp;M)…</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="58"/>
        <source>Compare drives and backup files side by side, or against factory defaults</source>
        <translation>드라이버와 백업 파일을 나란히 비교하거나 공장 출하값과 비교합니다</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="59"/>
        <source>&amp;Restore from file…</source>
        <translation>파일에서 복원(&amp;R)…</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="60"/>
        <source>Preview, then write a backup&apos;s settings back to drives</source>
        <translation>백업의 설정을 미리 본 뒤 드라이버에 다시 씁니다</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="93"/>
        <source>&amp;Back up selected drives…</source>
        <translation>선택한 드라이버 백업(&amp;B)…</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="96"/>
        <source>Select an identified drive in the bus list first</source>
        <translation>먼저 버스 목록에서 식별된 드라이버를 선택하십시오</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="97"/>
        <source>Save the settings of the selected drive(s) to a file</source>
        <translation>선택한 드라이버의 설정을 파일로 저장합니다</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="108"/>
        <source>Back up to file</source>
        <translation>파일로 백업</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="120"/>
        <source>Open backup file</source>
        <translation>백업 파일 열기</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="141"/>
        <source>Restore from backup file</source>
        <translation>백업 파일에서 복원</translation>
    </message>
</context>
<context>
    <name>opentop::FileCommandSupport</name>
    <message>
        <location filename="../cli/FileCommandSupport.cpp" line="29"/>
        <source>no such file</source>
        <translation>파일이 없습니다</translation>
    </message>
    <message>
        <location filename="../cli/FileCommandSupport.cpp" line="31"/>
        <source>is a directory; name a backup file</source>
        <translation>디렉터리입니다. 백업 파일을 지정하십시오</translation>
    </message>
    <message>
        <location filename="../cli/FileCommandSupport.cpp" line="33"/>
        <source>is not a regular file (a device, FIFO or socket); name a backup file</source>
        <translation>일반 파일이 아닙니다(장치, FIFO 또는 소켓). 백업 파일을 지정하십시오</translation>
    </message>
    <message>
        <location filename="../cli/FileCommandSupport.cpp" line="35"/>
        <source>error: %1: %2</source>
        <translation>오류: %1: %2</translation>
    </message>
    <message>
        <location filename="../cli/FileCommandSupport.cpp" line="43"/>
        <source>error: %1 refused: %2</source>
        <translation>오류: %1 거부됨: %2</translation>
    </message>
</context>
<context>
    <name>opentop::FixedLineHint</name>
    <message>
        <location filename="../model/bus/FixedLineHint.cpp" line="41"/>
        <source>A DC controller in potentiometer/analog control mode talks only at %1 bit/s, 8%2%3, address %4.</source>
        <translation>포텐셔미터/아날로그 제어 모드의 DC 컨트롤러는 %1 bit/s, 8%2%3, 국번 %4로만 통신합니다.</translation>
    </message>
    <message>
        <location filename="../model/bus/FixedLineHint.cpp" line="60"/>
        <source>%1 8%2%3, address %4</source>
        <translation>%1 8%2%3, 국번 %4</translation>
    </message>
</context>
<context>
    <name>opentop::GainDesign</name>
    <message>
        <location filename="../model/tuning/GainDesign.cpp" line="21"/>
        <source>the model has no ultimate point</source>
        <translation>모델에 한계점이 없습니다</translation>
    </message>
    <message>
        <location filename="../model/tuning/GainDesign.cpp" line="55"/>
        <source>no gains from the %1 rule settle within %2 ms with at most %3 % overshoot on the motor&apos;s model, even with P at a tenth of the rule&apos;s</source>
        <translation>P를 규칙 값의 1/10까지 낮춰도 모터 모델에서 %1 규칙의 게인이 오버슈트 %3 % 이하로 %2 ms 안에 정정되지 않습니다</translation>
    </message>
    <message>
        <location filename="../model/tuning/GainDesign.cpp" line="60"/>
        <source>Try a rule that allows more overshoot or a smaller step (a lower operating speed), or raise the drive&apos;s current limit if the motor allows it.</source>
        <translation>오버슈트를 더 허용하는 규칙이나 더 작은 스텝(더 낮은 운전 속도)을 시도하거나, 모터가 허용하면 드라이버의 전류 한계값을 올리십시오.</translation>
    </message>
</context>
<context>
    <name>opentop::GetCommand</name>
    <message>
        <location filename="../cli/GetCommand.cpp" line="44"/>
        <source>Read parameters by name in engineering units (or registers with --raw)</source>
        <translation>파라미터를 이름으로 읽어 공학 단위로 표시합니다(--raw를 주면 레지스터)</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="50"/>
        <source>Read every parameter of a group (see params).</source>
        <translation>그룹의 모든 파라미터를 읽습니다(params 참조).</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="50"/>
        <source>GROUP</source>
        <translation>GROUP</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="51"/>
        <source>Read every readable parameter.</source>
        <translation>읽을 수 있는 모든 파라미터를 읽습니다.</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="53"/>
        <source>Read registers by address: ADDR or ADDR:COUNT (0x.. or decimal).</source>
        <translation>주소로 레지스터를 읽습니다: ADDR 또는 ADDR:COUNT (0x.. 또는 10진수).</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="53"/>
        <source>ADDR</source>
        <translation>ADDR</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="55"/>
        <source>Function code for --raw: 3 (holding) or 4 (input) to read, 6 or 16 to write.</source>
        <translation>--raw의 기능 코드: 읽기는 3(holding) 또는 4(input), 쓰기는 6 또는 16.</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="56"/>
        <source>FC</source>
        <translation>FC</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="64"/>
        <source>error: give one machine number first: get ID NAME...</source>
        <translation>오류: 먼저 국번 하나를 지정하십시오: get ID NAME...</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="72"/>
        <source>error: name parameters, or give exactly one of --group, --all, --raw</source>
        <translation>오류: 파라미터 이름을 지정하거나 --group, --all, --raw 중 정확히 하나를 주십시오</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="80"/>
        <location filename="../cli/GetCommand.cpp" line="210"/>
        <source>error: %1</source>
        <translation>오류: %1</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="91"/>
        <source>error: %1 has no group &quot;%2&quot;; groups: %3</source>
        <translation>오류: %1에 그룹 &quot;%2&quot;이(가) 없습니다. 그룹: %3</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="109"/>
        <source>error: %1 is a write-only command and cannot be read</source>
        <translation>오류: %1은(는) 쓰기 전용 명령이라 읽을 수 없습니다</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="110"/>
        <source>error: %1 has no parameter &quot;%2&quot;; see &quot;opentop-cli params --family %1&quot;</source>
        <translation>오류: %1에 파라미터 &quot;%2&quot;이(가) 없습니다. &quot;opentop-cli params --family %1&quot;을 참조하십시오</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="124"/>
        <source>interrupted</source>
        <translation>중단됨</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="154"/>
        <source>Parameter</source>
        <translation>파라미터</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="154"/>
        <source>Value</source>
        <translation>값</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="154"/>
        <source>Raw</source>
        <translation>원시값</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="154"/>
        <source>Label</source>
        <translation>표시 이름</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="159"/>
        <source>(failed: %1)</source>
        <translation>(실패: %1)</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="161"/>
        <source>  ! outside the profile&apos;s allowed values</source>
        <translation>  ! 프로파일의 허용 값 밖</translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/GetCommand.cpp" line="168"/>
        <source>error: %n parameter(s) could not be read</source>
        <translation>
            <numerusform>오류: 파라미터 %n개를 읽을 수 없습니다</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="191"/>
        <source>error: --raw needs ADDR or ADDR:COUNT (address 0x0000–0xFFFF, count 1–125) and --fc 3 or 4</source>
        <translation>오류: --raw에는 ADDR 또는 ADDR:COUNT(주소 0x0000–0xFFFF, 개수 1–125)와 --fc 3 또는 4가 필요합니다</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="223"/>
        <source>Address</source>
        <translation>주소</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="223"/>
        <source>Hex</source>
        <translation>16진수</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="223"/>
        <source>Decimal</source>
        <translation>10진수</translation>
    </message>
</context>
<context>
    <name>opentop::GoldenLimits</name>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="67"/>
        <source>the golden unit did not pass its own test (%1): no limits can come from it</source>
        <translation>기준 제품이 자체 검사에 합격하지 못했습니다(%1): 이 제품으로는 한계값을 정할 수 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="75"/>
        <source>machine number %1: unknown family &quot;%2&quot;</source>
        <translation>국번 %1: 알 수 없는 제품군 &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="94"/>
        <source>machine number %1: unknown parameter &quot;%2&quot;</source>
        <translation>국번 %1: 알 수 없는 파라미터 &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="104"/>
        <source>machine number %1: the golden unit&apos;s %2 was not measured</source>
        <translation>국번 %1: 기준 제품의 %2을(를) 측정하지 못했습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="129"/>
        <source>Hold limits measured on the golden unit on %1: the measured value ± %2 % (at least %3 % of full scale), never wider than the default limits.</source>
        <translation>유지 단계의 한계값은 %1에 기준 제품에서 측정: 측정값 ± %2 % (최소 풀스케일의 %3 %), 기본 한계값보다 넓지 않음.</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="140"/>
        <source>%1–%2%3</source>
        <translation>%1–%2%3</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="142"/>
        <source>≤ %1%2</source>
        <translation>≤ %1%2</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="144"/>
        <source>≥ %1%2</source>
        <translation>≥ %1%2</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="145"/>
        <source>no limit</source>
        <translation>한계값 없음</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="153"/>
        <source>%1 %2 (kept: measured %3)</source>
        <translation>%1 %2 (유지: 측정값 %3)</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="155"/>
        <source>%1 %2 (default %3, measured %4)</source>
        <translation>%1 %2 (기본 %3, 측정값 %4)</translation>
    </message>
</context>
<context>
    <name>opentop::GoldenMeasure</name>
    <message>
        <location filename="../model/eol/GoldenMeasure.cpp" line="31"/>
        <source>machine number %1 (%2): runs its motor for about %3 s: %4</source>
        <translation>국번 %1 (%2): 모터를 약 %3 s 운전합니다: %4</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenMeasure.cpp" line="43"/>
        <source>golden unit</source>
        <translation>기준 제품</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenMeasure.cpp" line="44"/>
        <source>recipe from a golden unit</source>
        <translation>기준 제품으로 만드는 레시피</translation>
    </message>
</context>
<context>
    <name>opentop::GoldenMeasureButton</name>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="36"/>
        <source>Measure limits…</source>
        <translation>한계값 측정…</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="42"/>
        <source>Run the golden unit on the bus through the recipe&apos;s steps once and take the hold limits from what it measures: the measured value ± 25 % (at least 5 % of full scale), never wider than the limits before</source>
        <translation>버스의 기준 제품을 레시피 단계대로 한 번 운전하고 측정값으로 유지 단계의 한계값을 정합니다: 측정값 ± 25 % (최소 풀스케일의 5 %), 기존 한계값보다 넓지 않음</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="52"/>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="87"/>
        <source>Measure limits on the golden unit</source>
        <translation>기준 제품으로 한계값 측정</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="60"/>
        <source>The recipe has no positions.</source>
        <translation>레시피에 위치가 없습니다.</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="61"/>
        <source>The recipe cannot be read: %1</source>
        <translation>레시피를 읽을 수 없습니다: %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="65"/>
        <source>Machine number %1 is not a drive on the bus: connect to the golden unit and scan first.</source>
        <translation>국번 %1은(는) 버스에 있는 드라이버가 아닙니다: 먼저 기준 제품에 연결하고 스캔하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="70"/>
        <source>Run the golden unit through the recipe&apos;s steps? These motors turn:</source>
        <translation>기준 제품을 레시피 단계대로 운전하시겠습니까? 다음 모터가 회전합니다:</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="76"/>
        <source>Run the motors</source>
        <translation>모터 운전</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="90"/>
        <source>The bus is not connected.</source>
        <translation>버스가 연결되어 있지 않습니다.</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="95"/>
        <source>Measuring the golden unit…</source>
        <translation>기준 제품 측정 중…</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="95"/>
        <source>Stop</source>
        <translation>정지</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="102"/>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="104"/>
        <source>stopped by the user</source>
        <translation>사용자가 정지함</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="108"/>
        <source>Machine number %1: %2</source>
        <translation>국번 %1: %2</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="120"/>
        <source>%1 is not confirmed stopped.</source>
        <translation>%1의 정지가 확인되지 않았습니다.</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="122"/>
        <source>No limits were taken: %1</source>
        <translation>한계값을 정하지 않았습니다: %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="129"/>
        <source>Machine number %1, step %2: %3</source>
        <translation>국번 %1, 단계 %2: %3</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="135"/>
        <source>The hold limits now follow the golden unit. Check them, then save the recipe.</source>
        <translation>유지 단계의 한계값을 기준 제품에 맞췄습니다. 확인한 뒤 레시피를 저장하십시오.</translation>
    </message>
</context>
<context>
    <name>opentop::GoldenRecipeSource</name>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="39"/>
        <source>New recipe from %1: check the settings and the test steps&apos; limits, then save it.</source>
        <translation>%1에서 새 레시피를 만들었습니다: 설정과 검사 단계의 한계값을 확인한 뒤 저장하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="55"/>
        <source>machine number %1 is not a known drive on the bus; scan the bus first</source>
        <translation>국번 %1은(는) 버스에 알려진 드라이버가 아닙니다. 먼저 버스를 스캔하십시오</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="64"/>
        <source>Reading the golden unit&apos;s settings…</source>
        <translation>기준 제품의 설정을 읽는 중…</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="64"/>
        <source>Cancel</source>
        <translation>취소</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="73"/>
        <source>machine number %1 is not on the bus</source>
        <translation>국번 %1이(가) 버스에 없습니다</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="86"/>
        <source>cancelled: no recipe was made</source>
        <translation>취소됨: 레시피를 만들지 않았습니다</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="98"/>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="103"/>
        <source>New recipe</source>
        <translation>새 레시피</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="98"/>
        <source>Product name:</source>
        <translation>제품 이름:</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="103"/>
        <source>Revision:</source>
        <translation>개정:</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="111"/>
        <source>Golden unit&apos;s backup file</source>
        <translation>기준 제품의 백업 파일</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="112"/>
        <source>Backups (*.json)</source>
        <translation>백업 (*.json)</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="124"/>
        <source>No drives on the bus: connect and scan first.</source>
        <translation>버스에 드라이버가 없습니다: 먼저 연결하고 스캔하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="132"/>
        <source>New recipe from drives</source>
        <translation>드라이버로 새 레시피 만들기</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="133"/>
        <source>Machine numbers of the golden unit&apos;s drives (found: %1):</source>
        <translation>기준 제품 드라이버의 국번 (발견: %1):</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="143"/>
        <source>&quot;%1&quot; is not a machine number (1–247)</source>
        <translation>&quot;%1&quot;은(는) 국번(1–247)이 아닙니다</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="152"/>
        <source>New recipe from the drives on the bus: check the settings and the test steps&apos; limits, then save it.</source>
        <translation>버스의 드라이버로 새 레시피를 만들었습니다: 설정과 검사 단계의 한계값을 확인한 뒤 저장하십시오.</translation>
    </message>
</context>
<context>
    <name>opentop::GroupCheck</name>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="65"/>
        <location filename="../cli/GroupCheck.cpp" line="131"/>
        <source>error: %1</source>
        <translation>오류: %1</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="73"/>
        <source>note: --no-group-check: drives in communication group %1 (which also execute what is sent to %1) were not looked for</source>
        <translation>참고: --no-group-check: 통신 그룹 %1의 드라이버(%1에 보낸 것을 함께 실행)는 찾지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="79"/>
        <source>error: the drives on this bus are not known, so drives in communication group %1 (which also execute what is sent to %1, without replying) cannot be named; nothing was sent</source>
        <translation>오류: 이 버스의 드라이버를 알 수 없어 통신 그룹 %1의 드라이버(%1에 보낸 것을 응답 없이 함께 실행)를 밝힐 수 없습니다. 아무것도 보내지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="84"/>
        <source>scan the bus first (opentop-cli scan), name its drives with --bus-drives LIST, or add --no-group-check to send it without looking</source>
        <translation>먼저 버스를 스캔하거나(opentop-cli scan), --bus-drives LIST로 드라이버를 지정하거나, 확인 없이 보내려면 --no-group-check를 추가하십시오</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="109"/>
        <source>warning: the communication group of %1 could not be read</source>
        <translation>경고: %1의 통신 그룹을 읽을 수 없습니다</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="119"/>
        <source>note: the drives on the bus are %1, from %2; drives added since are not known until the next scan</source>
        <translation>참고: 버스의 드라이버는 %1이며 %2에서 가져왔습니다. 그 후 추가된 드라이버는 다음 스캔까지 알 수 없습니다</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="131"/>
        <source>note: %1</source>
        <translation>참고: %1</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="134"/>
        <source>add --yes to send it to all of %1 and %2; nothing was sent</source>
        <translation>%1과(와) %2 모두에 보내려면 --yes를 추가하십시오. 아무것도 보내지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="169"/>
        <source>not readable</source>
        <translation>읽을 수 없음</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="193"/>
        <source>Read back from the drives of the group:</source>
        <translation>그룹 드라이버에서 다시 읽은 값:</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="194"/>
        <source>Drive</source>
        <translation>드라이버</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="194"/>
        <source>Parameter</source>
        <translation>파라미터</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="194"/>
        <source>Value</source>
        <translation>값</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="194"/>
        <source>Result</source>
        <translation>결과</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="197"/>
        <source>(not read: %1)</source>
        <translation>(읽지 않음: %1)</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="198"/>
        <source>verified</source>
        <translation>확인됨</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="199"/>
        <source>DIFFERS from what was written</source>
        <translation>쓴 값과 다름</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="200"/>
        <source>not verified</source>
        <translation>확인 안 됨</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="248"/>
        <source>off</source>
        <translation>사용 안 함</translation>
    </message>
</context>
<context>
    <name>opentop::GroupFollowers</name>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="78"/>
        <source>could not be read</source>
        <translation>읽을 수 없음</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="109"/>
        <source>its control priority could not be read</source>
        <translation>제어 우선순위를 읽을 수 없었습니다</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="111"/>
        <source>it is in %1: it takes run commands only from its input terminals and ignores them over the bus</source>
        <translation>%1 상태입니다: 운전 명령은 입력 단자에서만 받고 통신으로 온 명령은 무시합니다</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="115"/>
        <source>an alarm is active: it runs only once the alarm is cleared</source>
        <translation>알람이 발생해 있습니다: 알람이 해제되어야 운전합니다</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="129"/>
        <source>error code %1h</source>
        <translation>오류 코드 %1h</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="154"/>
        <source>Machine number %1 follows it.</source>
        <translation>국번 %1은(는) 따릅니다.</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="155"/>
        <source>Machine number %1 follows it (%2).</source>
        <translation>국번 %1은(는) 따릅니다(%2).</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="158"/>
        <source>Machine number %1: not known whether it follows: %2.</source>
        <translation>국번 %1: 따를지 알 수 없습니다: %2.</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="160"/>
        <source>Machine number %1 does NOT follow it: %2. To run it with this drive, set its control priority to communication priority; otherwise it shows E2h &quot;Cannot execute command&quot;.</source>
        <translation>국번 %1은(는) 따르지 않습니다: %2. 이 드라이버와 함께 운전하려면 제어 우선순위를 통신 우선으로 설정하십시오. 그렇지 않으면 E2h &quot;명령 실행 불가&quot;를 표시합니다.</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="174"/>
        <source>Machine number %1: its run state could not be read.</source>
        <translation>국번 %1: 운전 상태를 읽을 수 없었습니다.</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="176"/>
        <source>Machine number %1 runs.</source>
        <translation>국번 %1 운전 중.</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="177"/>
        <source>Machine number %1 runs (%2).</source>
        <translation>국번 %1 운전 중(%2).</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="179"/>
        <source>Machine number %1 does not run: %2.</source>
        <translation>국번 %1은(는) 운전하지 않습니다: %2.</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="181"/>
        <source>Machine number %1 does not run.</source>
        <translation>국번 %1은(는) 운전하지 않습니다.</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="183"/>
        <source>It shows %1</source>
        <translation>표시: %1</translation>
    </message>
</context>
<context>
    <name>opentop::GroupWriteCheck</name>
    <message>
        <location filename="../ui/groups/GroupWriteCheck.cpp" line="50"/>
        <source>Machine number %1: %2</source>
        <translation>국번 %1: %2</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupWriteCheck.cpp" line="59"/>
        <source>Communication group</source>
        <translation>통신 그룹</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupWriteCheck.cpp" line="64"/>
        <source>Their values are read back afterwards.</source>
        <translation>이후 값을 다시 읽습니다.</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupWriteCheck.cpp" line="65"/>
        <source>Send, also to %1</source>
        <translation>보내기 (%1에도)</translation>
    </message>
</context>
<context>
    <name>opentop::GroupsView</name>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="34"/>
        <source>Read &amp;groups again</source>
        <translation>그룹 다시 읽기(&amp;G)</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="35"/>
        <source>&amp;Write plan…</source>
        <translation>계획 쓰기(&amp;W)…</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="38"/>
        <source>A drive whose communication group is another drive&apos;s machine number is that drive&apos;s child: it executes every write and command sent to its parent, without replying. Plan the groups in the last column and write them; every drive&apos;s group is then read back.</source>
        <translation>통신 그룹이 다른 드라이버의 국번으로 설정된 드라이버는 그 드라이버의 자식입니다: 부모에게 보낸 모든 쓰기와 명령을 응답 없이 실행합니다. 마지막 열에서 그룹을 계획하고 쓰십시오. 쓴 뒤에는 모든 드라이버의 그룹을 다시 읽습니다.</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="49"/>
        <source>Machine number</source>
        <translation>국번</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="49"/>
        <source>Model</source>
        <translation>모델</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="49"/>
        <source>Group</source>
        <translation>그룹</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="50"/>
        <source>Follows / followed by</source>
        <translation>따르는 대상 / 따르는 드라이버</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="50"/>
        <source>Problem</source>
        <translation>문제</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="50"/>
        <source>Plan</source>
        <translation>계획</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="51"/>
        <source>Read back</source>
        <translation>다시 읽은 값</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="57"/>
        <source>Read every drive&apos;s communication group from the drive</source>
        <translation>모든 드라이버에서 통신 그룹을 읽습니다</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="58"/>
        <source>Write the planned groups (asks first), then read every drive&apos;s group back</source>
        <translation>계획한 그룹을 쓰고(먼저 확인), 모든 드라이버의 그룹을 다시 읽습니다</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="79"/>
        <location filename="../ui/groups/GroupsView.cpp" line="145"/>
        <source>Disabled</source>
        <translation>사용 안 함</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="146"/>
        <source>Planned group of machine number %1</source>
        <translation>국번 %1의 계획 그룹</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="147"/>
        <source>The group machine number %1 should have: its own number makes it a parent, another drive&apos;s number its child; Disabled: no group</source>
        <translation>국번 %1에 줄 그룹: 자기 국번이면 부모, 다른 드라이버의 국번이면 그 자식; 사용 안 함: 그룹 없음</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="166"/>
        <source>child and parent</source>
        <translation>자식이면서 부모</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="167"/>
        <source>no drive %1</source>
        <translation>드라이버 %1 없음</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="176"/>
        <source>not read</source>
        <translation>읽지 않음</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="198"/>
        <source>No problem found in the groups as read from the drives.</source>
        <translation>드라이버에서 읽은 그룹에 문제가 없습니다.</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="199"/>
        <source>Problems:</source>
        <translation>문제:</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="206"/>
        <source>%1: %2 → %3</source>
        <translation>%1: %2 → %3</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="213"/>
        <source>The plan is what the drives hold.</source>
        <translation>계획이 드라이버에 있는 값과 같습니다.</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="214"/>
        <source>Plan changes: %1.</source>
        <translation>계획 변경: %1.</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="216"/>
        <source>After it: %1</source>
        <translation>변경 후: %1</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="242"/>
        <source>Reading every drive&apos;s group…</source>
        <translation>모든 드라이버의 그룹을 읽는 중…</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/groups/GroupsView.cpp" line="248"/>
        <source>%n drive(s) did not answer</source>
        <translation>
            <numerusform>드라이버 %n대가 응답하지 않았습니다</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="263"/>
        <source>Machine number %1: group %2 → %3.</source>
        <translation>국번 %1: 그룹 %2 → %3.</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="268"/>
        <source>This also reaches %1 (its children), which are written again after it.</source>
        <translation>이 내용은 %1(자식)에도 전달되므로, 그 후에 자식을 다시 씁니다.</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="277"/>
        <source>Warning: %1</source>
        <translation>경고: %1</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="279"/>
        <source>Write communication groups</source>
        <translation>통신 그룹 쓰기</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/groups/GroupsView.cpp" line="280"/>
        <source>Write the planned communication group to %n drive(s)?</source>
        <translation>
            <numerusform>계획한 통신 그룹을 드라이버 %n대에 쓰시겠습니까?</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="284"/>
        <source>Drives with children are written last; every drive&apos;s group is read back afterwards.</source>
        <translation>자식이 있는 드라이버는 마지막에 씁니다. 쓴 뒤에는 모든 드라이버의 그룹을 다시 읽습니다.</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="286"/>
        <source>&amp;Write groups</source>
        <translation>그룹 쓰기(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="317"/>
        <source>Writing group %1 to machine number %2…</source>
        <translation>국번 %2에 그룹 %1 쓰는 중…</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="326"/>
        <source>write failed: %1</source>
        <translation>쓰기 실패: %1</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="340"/>
        <source>Reading every drive&apos;s group back…</source>
        <translation>모든 드라이버의 그룹을 다시 읽는 중…</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="353"/>
        <source>write failed</source>
        <translation>쓰기 실패</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="354"/>
        <source>✓ %1</source>
        <translation>✓ %1</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="355"/>
        <source>✗ %1, planned %2</source>
        <translation>✗ %1, 계획 %2</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="365"/>
        <source>Proved: every drive read back holds its planned group.</source>
        <translation>확인됨: 다시 읽은 모든 드라이버가 계획한 그룹을 가지고 있습니다.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/groups/GroupsView.cpp" line="366"/>
        <source>Not as planned: %1 (read back; %n drive(s) did not answer).</source>
        <translation>
            <numerusform>계획과 다름: %1 (다시 읽음; 드라이버 %n대 응답 없음).</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::HelpActions</name>
    <message>
        <location filename="../ui/help/HelpActions.cpp" line="18"/>
        <source>&amp;User guide</source>
        <translation>사용자 가이드(&amp;U)</translation>
    </message>
    <message>
        <location filename="../ui/help/HelpActions.cpp" line="21"/>
        <source>&amp;Keyboard shortcuts</source>
        <translation>단축키(&amp;K)</translation>
    </message>
    <message>
        <location filename="../ui/help/HelpActions.cpp" line="25"/>
        <source>&amp;About OpenTOP</source>
        <translation>OpenTOP 정보(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/help/HelpActions.cpp" line="28"/>
        <source>About &amp;Qt</source>
        <translation>Qt 정보(&amp;Q)</translation>
    </message>
</context>
<context>
    <name>opentop::IdentityDialog</name>
    <message>
        <location filename="../ui/eol/IdentityDialog.cpp" line="23"/>
        <source>Who is it?</source>
        <translation>누구십니까?</translation>
    </message>
    <message>
        <location filename="../ui/eol/IdentityDialog.cpp" line="25"/>
        <source>To %1 this station needs the %2 role or higher. Log in with your user name and password.</source>
        <translation>%1 작업에는 이 스테이션에서 %2 이상의 역할이 필요합니다. 사용자 이름과 비밀번호로 로그인하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/eol/IdentityDialog.cpp" line="42"/>
        <source>User name:</source>
        <translation>사용자 이름:</translation>
    </message>
    <message>
        <location filename="../ui/eol/IdentityDialog.cpp" line="43"/>
        <source>Password:</source>
        <translation>비밀번호:</translation>
    </message>
    <message>
        <location filename="../ui/eol/IdentityDialog.cpp" line="62"/>
        <source>Refused: %1</source>
        <translation>거부됨: %1</translation>
    </message>
</context>
<context>
    <name>opentop::InputFile</name>
    <message>
        <location filename="../model/io/InputFile.cpp" line="13"/>
        <source>cannot read %1: %2</source>
        <translation>%1을(를) 읽을 수 없습니다: %2</translation>
    </message>
</context>
<context>
    <name>opentop::IoTerminalsPage</name>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="31"/>
        <source>Not functioning: the drive ignores this input.</source>
        <translation>기능 없음: 드라이버가 이 입력을 무시합니다.</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="33"/>
        <source>RUN/STOP: ON runs the motor, OFF stops it.</source>
        <translation>RUN/STOP: ON이면 모터 운전, OFF면 정지.</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="35"/>
        <source>CW/CCW: the running direction, OFF clockwise, ON counter-clockwise.</source>
        <translation>CW/CCW: 회전 방향, OFF면 CW(시계 방향), ON이면 CCW(반시계 방향).</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="38"/>
        <source>CW/STOP: ON runs the motor clockwise, OFF stops it.</source>
        <translation>CW/STOP: ON이면 모터 CW 운전, OFF면 정지.</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="40"/>
        <source>CCW/STOP: ON runs the motor counter-clockwise, OFF stops it.</source>
        <translation>CCW/STOP: ON이면 모터 CCW 운전, OFF면 정지.</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="43"/>
        <source>Alarm-Reset: clears an alarm (alarm erase method Alarm-Reset).</source>
        <translation>Alarm-Reset: 알람을 해제합니다(알람 해제 방법이 Alarm-Reset일 때).</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="51"/>
        <source>M%1: bit %1 of the running data selection (M2 M1 M0 = 000–111 select SPno1–SPno8).</source>
        <translation>M%1: 운전 데이터 선택의 비트 %1 (M2 M1 M0 = 000–111로 SPno1–SPno8 선택).</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="56"/>
        <source>Ext-Error (EX-Er): an external interrupt that stops the motor; the only input still active in communication priority.</source>
        <translation>Ext-Error (EX-Er): 모터를 정지시키는 외부 인터럽트. 통신 우선에서도 동작하는 유일한 입력.</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="61"/>
        <source>H-Free: releases the motor&apos;s holding force while stopped.</source>
        <translation>H-Free: 정지 중 모터의 유지력(여자)을 해제합니다.</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="63"/>
        <source>Code %1 is not a known input function.</source>
        <translation>코드 %1은(는) 알려진 입력 기능이 아닙니다.</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="71"/>
        <source>Not functioning: the output stays off.</source>
        <translation>기능 없음: 출력은 계속 OFF입니다.</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="73"/>
        <source>Alarm-Out: switches when an alarm stops the motor.</source>
        <translation>Alarm-Out: 알람으로 모터가 정지하면 전환됩니다.</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="75"/>
        <source>Reach Speed-Out: switches when the motor reaches the target speed.</source>
        <translation>Reach Speed-Out: 모터가 목표 속도에 도달하면 전환됩니다.</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="78"/>
        <source>VA-Out: switches before the target speed, at the target speed minus the VA speed.</source>
        <translation>VA-Out: 목표 속도에서 VA 속도를 뺀 속도, 즉 목표 속도 도달 전에 전환됩니다.</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="81"/>
        <source>Speed-Out: speed pulses, 24 per motor revolution.</source>
        <translation>Speed-Out: 속도 펄스, 모터 1회전당 24펄스.</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="83"/>
        <source>Warning-Out: switches on a warning; the motor keeps running.</source>
        <translation>Warning-Out: 경고 시 전환됩니다. 모터는 계속 운전합니다.</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="86"/>
        <source>Move-Out: switches while the motor is turning.</source>
        <translation>Move-Out: 모터가 회전하는 동안 전환됩니다.</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="88"/>
        <source>Code %1 is not a known output function.</source>
        <translation>코드 %1은(는) 알려진 출력 기능이 아닙니다.</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="102"/>
        <source>I/O terminals</source>
        <translation>I/O 단자</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="118"/>
        <source>Control</source>
        <translation>제어</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="123"/>
        <source>Control &amp;mode:</source>
        <translation>제어 모드(&amp;M):</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="124"/>
        <source>Mode1 uses RUN/STOP and CW/CCW inputs (like UBD, SBD, DBD); Mode2 uses CW/STOP and CCW/STOP inputs (like DB, BMD). The input function codes differ: switching the mode disables the other mode&apos;s input functions, so every input X0–X3 needs a function of the new mode.</source>
        <translation>Mode1은 RUN/STOP, CW/CCW 입력을 사용합니다(UBD, SBD, DBD와 같음). Mode2는 CW/STOP, CCW/STOP 입력을 사용합니다(DB, BMD와 같음). 입력 기능 코드가 다르므로 모드를 바꾸면 다른 모드의 입력 기능은 무효가 됩니다. 따라서 모든 입력 X0–X3에 새 모드의 기능을 지정해야 합니다.</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="136"/>
        <source>Control &amp;priority:</source>
        <translation>제어 우선순위(&amp;P):</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="137"/>
        <source>In I/O priority the input terminals run the motor. In communication priority the drive runs from bus commands and of the inputs only EX-Er (external error) acts.</source>
        <translation>I/O 우선에서는 입력 단자로 모터를 운전합니다. 통신 우선에서는 드라이버가 버스 명령으로 운전하며, 입력 중에서는 EX-Er(외부 오류)만 동작합니다.</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="146"/>
        <source>Inputs — CN5</source>
        <translation>입력 — CN5</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="148"/>
        <source>COM0: input common (external supply)</source>
        <translation>COM0: 입력 공통(외부 전원)</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="151"/>
        <source>COM1: input common (internal supply)</source>
        <translation>COM1: 입력 공통(내부 전원)</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="156"/>
        <source>Outputs — CN6</source>
        <translation>출력 — CN6</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="174"/>
        <source>Give each flagged input the default function of the new mode (pending, not written)</source>
        <translation>표시된 각 입력에 새 모드의 기본 기능을 지정합니다(쓰기 대기, 아직 쓰지 않음)</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="203"/>
        <source>Connector pin %1</source>
        <translation>커넥터 핀 %1</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="208"/>
        <source>Terminal %1 function</source>
        <translation>단자 %1 기능</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="235"/>
        <source>unknown</source>
        <translation>알 수 없음</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="261"/>
        <source>Not read yet.</source>
        <translation>아직 읽지 않음.</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="268"/>
        <source>Not valid in %1: choose again</source>
        <translation>%1에서 무효: 다시 선택하십시오</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="296"/>
        <source>The mode changes from %1 to %2 when written; Write page writes the mode first, then the terminals.</source>
        <translation>쓰면 모드가 %1에서 %2(으)로 바뀝니다. 페이지 쓰기는 모드를 먼저 쓰고 그다음 단자를 씁니다.</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="306"/>
        <source>Not valid in %1: %2. Choose their functions again before writing.</source>
        <translation>%1에서 무효: %2. 쓰기 전에 기능을 다시 선택하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="309"/>
        <source>Use %1 defaults</source>
        <translation>%1 기본값 사용</translation>
    </message>
</context>
<context>
    <name>opentop::JsonReader</name>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="29"/>
        <location filename="../model/profile/JsonReader.cpp" line="44"/>
        <location filename="../model/profile/JsonReader.cpp" line="89"/>
        <location filename="../model/profile/JsonReader.cpp" line="100"/>
        <location filename="../model/profile/JsonReader.cpp" line="116"/>
        <source>&quot;%1&quot; is missing</source>
        <translation>&quot;%1&quot;이(가) 없습니다</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="33"/>
        <source>&quot;%1&quot; must be a string</source>
        <translation>&quot;%1&quot;은(는) 문자열이어야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="48"/>
        <source>&quot;%1&quot; must be a number</source>
        <translation>&quot;%1&quot;은(는) 숫자여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="59"/>
        <source>%1 must be a whole number</source>
        <translation>%1은(는) 정수여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="64"/>
        <source>%1 is out of range</source>
        <translation>%1이(가) 범위를 벗어났습니다</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="80"/>
        <source>%1 must be an integer or a &quot;0x...&quot; string</source>
        <translation>%1은(는) 정수 또는 &quot;0x...&quot; 문자열이어야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="104"/>
        <source>&quot;%1&quot; must be an array</source>
        <translation>&quot;%1&quot;은(는) 배열이어야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="120"/>
        <source>&quot;%1&quot; must be an object</source>
        <translation>&quot;%1&quot;은(는) 객체여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="130"/>
        <source>%1: unknown key &quot;%2&quot;</source>
        <translation>%1: 알 수 없는 키 &quot;%2&quot;</translation>
    </message>
</context>
<context>
    <name>opentop::Language</name>
    <message>
        <location filename="../model/i18n/Language.cpp" line="140"/>
        <source>unknown language &apos;%1&apos;; available: %2</source>
        <translation>알 수 없는 언어 &apos;%1&apos;; 사용 가능: %2</translation>
    </message>
    <message>
        <location filename="../model/i18n/Language.cpp" line="167"/>
        <source>the %1 translation is missing from this build</source>
        <translation>이 빌드에 %1 번역이 없습니다</translation>
    </message>
</context>
<context>
    <name>opentop::LanguageMenu</name>
    <message>
        <location filename="../ui/i18n/LanguageMenu.cpp" line="10"/>
        <source>&amp;Language</source>
        <translation>언어(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/i18n/LanguageMenu.cpp" line="16"/>
        <source>System language (%1)</source>
        <translation>시스템 언어(%1)</translation>
    </message>
</context>
<context>
    <name>opentop::LimitCheck</name>
    <message>
        <location filename="../model/eol/LimitCheck.cpp" line="35"/>
        <source>%1 could not be read</source>
        <translation>%1을(를) 읽을 수 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/LimitCheck.cpp" line="50"/>
        <source>%1 %2 %3, %4</source>
        <translation>%1 %2 %3, %4</translation>
    </message>
    <message>
        <location filename="../model/eol/LimitCheck.cpp" line="73"/>
        <source>allowed %1–%2 %3</source>
        <translation>허용 %1–%2 %3</translation>
    </message>
    <message>
        <location filename="../model/eol/LimitCheck.cpp" line="75"/>
        <source>allowed at most %1 %2</source>
        <translation>허용 최대 %1 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/LimitCheck.cpp" line="77"/>
        <source>allowed at least %1 %2</source>
        <translation>허용 최소 %1 %2</translation>
    </message>
</context>
<context>
    <name>opentop::LineFormat</name>
    <message>
        <location filename="../transport/LineFormat.cpp" line="37"/>
        <source>Baud rate %1 is not supported: use 1200–115200.</source>
        <translation>통신 속도 %1은(는) 지원되지 않습니다. 1200–115200을 쓰십시오.</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="39"/>
        <source>Parity &apos;%1&apos; is not supported: use N (none), E (even) or O (odd).</source>
        <translation>패리티 &apos;%1&apos;은(는) 지원되지 않습니다. N(없음), E(짝수), O(홀수)를 쓰십시오.</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="42"/>
        <source>%1 data bits are not supported: use 7 or 8.</source>
        <translation>데이터 비트 %1개는 지원되지 않습니다. 7 또는 8을 쓰십시오.</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="44"/>
        <source>%1 stop bits are not supported: use 1 or 2.</source>
        <translation>스톱 비트 %1개는 지원되지 않습니다. 1 또는 2를 쓰십시오.</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="66"/>
        <source>&quot;%1&quot; is not a line format: write DATA BITS, PARITY and STOP BITS as 8N1, 8E1, 8O1 or 8N2, with the baud rate before it if it differs from the port&apos;s (9600:8E1)</source>
        <translation>&quot;%1&quot;은(는) 통신 형식이 아닙니다. 데이터 비트, 패리티, 스톱 비트를 8N1, 8E1, 8O1, 8N2처럼 쓰고, 통신 속도가 포트와 다르면 앞에 쓰십시오(9600:8E1)</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="81"/>
        <source>&quot;%1&quot;: %2</source>
        <translation>&quot;%1&quot;: %2</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="98"/>
        <source>&quot;%1&quot;: write MACHINE NUMBER=FORMAT, e.g. 7=9600:8E1 or 7=8N2 (machine numbers 1–247)</source>
        <translation>&quot;%1&quot;: 국번=형식으로 쓰십시오. 예: 7=9600:8E1 또는 7=8N2 (국번 1–247)</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="107"/>
        <source>machine number %1: %2</source>
        <translation>국번 %1: %2</translation>
    </message>
</context>
<context>
    <name>opentop::LineFormatHint</name>
    <message>
        <location filename="../model/bus/LineFormatHint.cpp" line="72"/>
        <source>%1: %2 from the factory (it can be set to %3).</source>
        <translation>%1: 공장 출하 시 %2 (%3(으)로 설정 가능).</translation>
    </message>
    <message>
        <location filename="../model/bus/LineFormatHint.cpp" line="77"/>
        <source>Drives set to another line format than %1 do not answer it. %2</source>
        <translation>%1이(가) 아닌 통신 형식으로 설정된 드라이브는 응답하지 않습니다. %2</translation>
    </message>
</context>
<context>
    <name>opentop::LinkLoss</name>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="31"/>
        <source>Machine number %1 (%2): state never read</source>
        <translation>국번 %1 (%2): 상태를 한 번도 읽지 못했습니다</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="46"/>
        <source>The connection to %1 was lost at %2.</source>
        <translation>%1 연결이 %2에 끊겼습니다.</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="54"/>
        <source>• %1 — last answer %2 (%3 when the link dropped)</source>
        <translation>• %1 — 마지막 응답 %2 (연결이 끊겼을 때 %3)</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="61"/>
        <source>By the last values read, no drive was running or in communication priority.</source>
        <translation>마지막으로 읽은 값으로는 운전 중이거나 통신 우선인 드라이버가 없었습니다.</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="62"/>
        <source>When the link dropped, by the last values read:</source>
        <translation>연결이 끊겼을 때, 마지막으로 읽은 값으로는:</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="70"/>
        <source>OpenTOP cannot stop these drives or give control back to their inputs until the link is back: nothing is sent over a lost link. A drive in communication priority keeps its last command. Check on the machine: each drive&apos;s own STOP input, the emergency stop, and the drives&apos; power.</source>
        <translation>연결이 복구될 때까지 OpenTOP은 이 드라이버들을 정지하거나 입력 단자로 제어를 되돌릴 수 없습니다: 끊긴 연결로는 아무것도 보내지 않습니다. 통신 우선인 드라이버는 마지막 명령을 유지합니다. 설비에서 확인하십시오: 각 드라이버 자체의 정지 입력 단자, 비상 정지, 드라이버 전원.</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="78"/>
        <source>Before you %1: the connection to %2 was lost at %3, and OpenTOP cannot reach these drives.</source>
        <translation>%1하기 전에: %2 연결이 %3에 끊겨 OpenTOP이 이 드라이버들에 접근할 수 없습니다.</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="96"/>
        <source>Running when it dropped, by the last values read: machine number %1.</source>
        <translation>끊겼을 때 마지막으로 읽은 값으로 운전 중: 국번 %1.</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="99"/>
        <source>In communication priority: machine number %1.</source>
        <translation>통신 우선: 국번 %1.</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/run/LinkLoss.cpp" line="102"/>
        <source>%n drive(s) never read.</source>
        <translation>
            <numerusform>한 번도 읽지 못한 드라이버 %n대.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="104"/>
        <source>OpenTOP cannot stop them until the link is back: check each drive&apos;s STOP input, the emergency stop and the power on the machine.</source>
        <translation>연결이 복구될 때까지 OpenTOP은 이들을 정지할 수 없습니다: 설비에서 각 드라이버의 정지 입력 단자, 비상 정지, 전원을 확인하십시오.</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="118"/>
        <source>Machine number %1 (%2): no answer, its state is not known</source>
        <translation>국번 %1 (%2): 응답 없음, 상태를 알 수 없음</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="126"/>
        <source>Every drive read again: none is running or in communication priority.</source>
        <translation>모든 드라이버를 다시 읽었습니다: 운전 중이거나 통신 우선인 드라이버가 없습니다.</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="127"/>
        <source>Read again just now:</source>
        <translation>방금 다시 읽음:</translation>
    </message>
</context>
<context>
    <name>opentop::MainMenus</name>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="35"/>
        <source>&amp;Bus</source>
        <translation>버스(&amp;B)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="36"/>
        <source>Main</source>
        <translation>메인</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="39"/>
        <source>&amp;Connect…</source>
        <translation>연결(&amp;C)…</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="41"/>
        <source>Choose the serial port, gateway or simulated bus (Ctrl+K)</source>
        <translation>시리얼 포트, 게이트웨이 또는 시뮬레이션 버스를 선택합니다(Ctrl+K)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="45"/>
        <source>&amp;Scan bus</source>
        <translation>버스 스캔(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="51"/>
        <source>&amp;Disconnect</source>
        <translation>연결 해제(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="57"/>
        <source>Communication &amp;groups…</source>
        <translation>통신 그룹(&amp;G)…</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="62"/>
        <source>&amp;Export alarm histories…</source>
        <translation>알람 이력 내보내기(&amp;E)…</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="64"/>
        <source>&amp;Quit</source>
        <translation>종료(&amp;Q)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="67"/>
        <source>&amp;Files</source>
        <translation>파일(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="72"/>
        <source>&amp;Drive</source>
        <translation>드라이버(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="75"/>
        <source>&amp;Write all pending</source>
        <translation>쓰기 대기 모두 쓰기(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="77"/>
        <source>&amp;Re-read all</source>
        <translation>모두 다시 읽기(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="79"/>
        <source>Write a setting to the selected drives…</source>
        <translation>선택한 드라이버에 설정 하나 쓰기…</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="85"/>
        <source>&amp;Next page</source>
        <translation>다음 페이지(&amp;N)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="91"/>
        <source>&amp;Previous page</source>
        <translation>이전 페이지(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="107"/>
        <source>&amp;View</source>
        <translation>보기(&amp;V)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="113"/>
        <source>&amp;Traffic log</source>
        <translation>통신 로그(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="114"/>
        <source>Bus &amp;overview</source>
        <translation>버스 개요(&amp;O)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="116"/>
        <source>T&amp;rends</source>
        <translation>트렌드(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="117"/>
        <source>Communication &amp;groups</source>
        <translation>통신 그룹(&amp;G)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="130"/>
        <source>Language</source>
        <translation>언어</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="131"/>
        <source>OpenTOP will be in %1 the next time it starts.</source>
        <translation>OpenTOP은 다음에 시작할 때 %1(으)로 표시됩니다.</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="137"/>
        <source>&amp;End of line</source>
        <translation>출하 검사(&amp;E)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="139"/>
        <source>&amp;Help</source>
        <translation>도움말(&amp;H)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="155"/>
        <source>connect elsewhere</source>
        <translation>다른 곳에 연결</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="165"/>
        <source>Export alarm histories</source>
        <translation>알람 이력 내보내기</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="166"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV 파일 (*.csv)</translation>
    </message>
</context>
<context>
    <name>opentop::MainWindow</name>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="58"/>
        <source>OpenTOP</source>
        <translation>OpenTOP</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="127"/>
        <source>connect elsewhere</source>
        <translation>다른 곳에 연결</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="141"/>
        <source>Connecting to %1… (still connected to %2)</source>
        <translation>%1에 연결하는 중… (%2에 아직 연결되어 있음)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="158"/>
        <source>Connected: %1 (the new connection failed: %2)</source>
        <translation>연결됨: %1 (새 연결 실패: %2)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="161"/>
        <location filename="../ui/main/MainWindow.cpp" line="175"/>
        <source>Cannot connect</source>
        <translation>연결할 수 없음</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="162"/>
        <source>%1

Still connected to %2; nothing was changed.</source>
        <translation>%1

%2에 아직 연결되어 있습니다. 아무것도 변경하지 않았습니다.</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="165"/>
        <location filename="../ui/main/MainWindow.cpp" line="242"/>
        <source>Not connected: %1</source>
        <translation>연결 안 됨: %1</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="217"/>
        <location filename="../ui/main/MainWindow.cpp" line="219"/>
        <source>Connection lost: %1</source>
        <translation>연결 끊김: %1</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="224"/>
        <source>OpenTOP — SIMULATED BUS (no hardware) — %1</source>
        <translation>OpenTOP — 시뮬레이션 버스 (실제 하드웨어 없음) — %1</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="225"/>
        <source>OpenTOP — %1</source>
        <translation>OpenTOP — %1</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="226"/>
        <source>Connecting to %1…</source>
        <translation>%1에 연결하는 중…</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="241"/>
        <source>Connected: %1</source>
        <translation>연결됨: %1</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="248"/>
        <source>Connected: %1 (simulated, no hardware)</source>
        <translation>연결됨: %1 (시뮬레이션, 실제 하드웨어 없음)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="276"/>
        <source>The drive does not report its variant; %1 is the configured one.</source>
        <translation>드라이버가 기종을 알려주지 않습니다. %1은(는) 설정된 기종입니다.</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="293"/>
        <location filename="../ui/main/MainWindow.cpp" line="303"/>
        <source>disconnect</source>
        <translation>연결 해제</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="300"/>
        <source>Not connected (disconnected)</source>
        <translation>연결 안 됨(연결 해제함)</translation>
    </message>
</context>
<context>
    <name>opentop::MissingValues</name>
    <message>
        <location filename="../model/session/MissingValues.cpp" line="18"/>
        <source>cannot check the value: reading %1 failed: %2</source>
        <translation>값을 검사할 수 없습니다: %1 읽기 실패: %2</translation>
    </message>
    <message>
        <location filename="../model/session/MissingValues.cpp" line="41"/>
        <source>reading %1 failed: %2</source>
        <translation>%1 읽기 실패: %2</translation>
    </message>
</context>
<context>
    <name>opentop::MonitorCommand</name>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="47"/>
        <source>Watch speed, load, state, inputs and alarms live (Ctrl-C ends)</source>
        <translation>속도, 부하, 상태, 입력, 알람을 실시간으로 봅니다(Ctrl-C로 종료)</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="54"/>
        <source>Time between samples of a drive in ms, %1–%2 (default 500).</source>
        <translation>드라이버당 샘플 간격(ms), %1–%2 (기본값 500).</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="57"/>
        <source>MS</source>
        <translation>MS</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="58"/>
        <source>Stop after N samples per drive (default: until Ctrl-C).</source>
        <translation>드라이버당 N개 샘플 후 멈춥니다(기본값: Ctrl-C까지).</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="59"/>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="61"/>
        <source>Also write every sample to FILE (CSV with a header; a row with a note where the link was lost and where it came back).</source>
        <translation>모든 샘플을 FILE에도 저장합니다(헤더가 있는 CSV; 연결이 끊긴 곳과 다시 연결된 곳에 메모 행).</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="63"/>
        <source>FILE</source>
        <translation>FILE</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="65"/>
        <source>When the link to the bus is lost, exit 1 if it is not back within SECONDS (default: reconnect by itself, 0.5 s to 5 s apart, until Ctrl-C).</source>
        <translation>버스 연결이 끊겼을 때 SECONDS초 안에 다시 연결되지 않으면 1로 끝냅니다(기본값: Ctrl-C까지 0.5초~5초 간격으로 자동 재연결).</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="67"/>
        <source>SECONDS</source>
        <translation>SECONDS</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="79"/>
        <source>error: usage: %1</source>
        <translation>오류: 사용법: %1</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="89"/>
        <source>error: --interval must be %1–%2 ms, got &quot;%3&quot;</source>
        <translation>오류: --interval은 %1–%2 ms여야 합니다. 입력값: &quot;%3&quot;</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="102"/>
        <source>error: --count must be a whole number of samples, 1 or more, got &quot;%1&quot;</source>
        <translation>오류: --count는 1 이상의 샘플 수(정수)여야 합니다. 입력값: &quot;%1&quot;</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="113"/>
        <source>error: --give-up must be a number of seconds, more than 0 and at most %1, got &quot;%2&quot;</source>
        <translation>오류: --give-up은 0보다 크고 %1 이하인 초 단위 숫자여야 합니다. 받은 값: &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="125"/>
        <source>error: cannot write %1: %2</source>
        <translation>오류: %1에 쓸 수 없습니다: %2</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="134"/>
        <source>error: %1</source>
        <translation>오류: %1</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="154"/>
        <source>warning: machine number %1: %2; speeds are shown in r/min only</source>
        <translation>경고: 국번 %1: %2; 속도는 r/min으로만 표시합니다</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="194"/>
        <source>error: cannot write %1: %2; monitoring stopped</source>
        <translation>오류: %1에 쓸 수 없습니다: %2; 모니터링을 멈췄습니다</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="233"/>
        <source>%1 link lost: %2 (%3); reconnecting for up to %4 s (Ctrl-C ends)</source>
        <translation>%1 연결 끊김: %2 (%3); 최대 %4초 동안 다시 연결합니다(Ctrl-C로 끝냄)</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="237"/>
        <source>%1 link lost: %2 (%3); reconnecting until it is back (Ctrl-C ends)</source>
        <translation>%1 연결 끊김: %2 (%3); 다시 연결될 때까지 재연결합니다(Ctrl-C로 끝냄)</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="246"/>
        <source>%1 link back after %2 s: %3; monitoring goes on</source>
        <translation>%1 %2초 후 연결 복구: %3; 모니터링을 계속합니다</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="261"/>
        <source>error: the link to %1 was lost at %2 and is not back after %3 s (--give-up %4): %5; monitoring stopped</source>
        <translation>오류: %1 연결이 %2에 끊긴 뒤 %3초가 지나도 복구되지 않았습니다(--give-up %4): %5; 모니터링을 멈췄습니다</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="303"/>
        <source>%1 error: %2</source>
        <translation>%1 오류: %2</translation>
    </message>
</context>
<context>
    <name>opentop::MonitorCsv</name>
    <message>
        <location filename="../cli/MonitorCsv.cpp" line="33"/>
        <source>link lost</source>
        <translation>연결 끊김</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCsv.cpp" line="38"/>
        <source>link back</source>
        <translation>연결 복구</translation>
    </message>
</context>
<context>
    <name>opentop::MonitorDetails</name>
    <message>
        <location filename="../ui/monitor/MonitorDetails.cpp" line="81"/>
        <location filename="../ui/monitor/MonitorDetails.cpp" line="88"/>
        <source>not read</source>
        <translation>읽지 않음</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorDetails.cpp" line="110"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>opentop::MonitorOutput</name>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="118"/>
        <source>Target shown</source>
        <translation>표시 목표값</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="118"/>
        <source>Speed shown</source>
        <translation>표시 속도</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="128"/>
        <source>Active alarm</source>
        <translation>발생 중인 알람</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="170"/>
        <source>none</source>
        <translation>없음</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="173"/>
        <source>code %1</source>
        <translation>코드 %1</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="173"/>
        <source>active</source>
        <translation>발생 중</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="180"/>
        <source>Time</source>
        <translation>시각</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="181"/>
        <source>ID</source>
        <translation>ID</translation>
    </message>
</context>
<context>
    <name>opentop::MonitorPage</name>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="191"/>
        <source>Live values</source>
        <translation>실시간 값</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="199"/>
        <source>Speed</source>
        <translation>속도</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="215"/>
        <source>State</source>
        <translation>상태</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="280"/>
        <source>%1 %2 on the drive&apos;s display</source>
        <translation>드라이버 표시부에 %1 %2</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="289"/>
        <source>Alarm %1 %2 — %3</source>
        <translation>알람 %1 %2 — %3</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="292"/>
        <source>Alarm active (reading which one…)</source>
        <translation>알람 발생 중 (어떤 알람인지 읽는 중…)</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="347"/>
        <source>No live state: %1</source>
        <translation>실시간 상태 없음: %1</translation>
    </message>
</context>
<context>
    <name>opentop::MonitorPollBar</name>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="30"/>
        <source>Poll every</source>
        <translation>폴링 주기</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="32"/>
        <source>%1 ms (%2 Hz)</source>
        <translation>%1 ms (%2 Hz)</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="33"/>
        <source>How often every monitored drive is read. Commands you give always go first; the drives share what is left of the bus in turn.</source>
        <translation>모니터링하는 각 드라이버를 읽는 주기. 사용자가 내린 명령이 항상 먼저 처리되고, 남은 버스 시간을 드라이버들이 차례로 나눠 씁니다.</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="45"/>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="53"/>
        <source>Resume polling</source>
        <translation>폴링 재개</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="53"/>
        <source>Pause polling</source>
        <translation>폴링 일시 정지</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="67"/>
        <source>Polling paused: the values shown are the last ones read (%1).</source>
        <translation>폴링 일시 정지됨: 표시된 값은 마지막으로 읽은 값입니다(%1).</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="69"/>
        <source>Polling waits for the bus scan: %1.</source>
        <translation>폴링이 버스 스캔을 기다리는 중: %1.</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="71"/>
        <source>Connection lost — not live: %1.</source>
        <translation>연결 끊김 — 실시간 아님: %1.</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="73"/>
        <source>Not live: %1.</source>
        <translation>실시간 아님: %1.</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="74"/>
        <source>The drive does not answer (%1) — not live: %2.</source>
        <translation>드라이버가 응답하지 않습니다(%1) — 실시간 아님: %2.</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="77"/>
        <source>Values %1 · %2 samples/s</source>
        <translation>값 %1 · 초당 샘플 %2개</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="81"/>
        <source>Not read yet.</source>
        <translation>아직 읽지 않음.</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="82"/>
        <source>Cannot read the drive: %1</source>
        <translation>드라이버를 읽을 수 없습니다: %1</translation>
    </message>
</context>
<context>
    <name>opentop::MotionPriorityBox</name>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="34"/>
        <source>Switch to communication priority…</source>
        <translation>통신 우선으로 전환…</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="59"/>
        <source>Machine number %1 is in &quot;%2&quot; (%3): it takes run, stop, direction and speed selection from its input terminals and refuses motion commands over the bus, so the test run is disabled.

Switching to &quot;%4&quot; hands these commands to the bus: the input terminals no longer start or stop the motor, and the machine&apos;s own controls stay without effect until you switch back to &quot;%2&quot;.</source>
        <translation>국번 %1은(는) &quot;%2&quot;(%3) 상태입니다: 운전, 정지, 방향, 속도 선택을 입력 단자로 받고 버스를 통한 운전 명령은 거부하므로 시운전을 할 수 없습니다.

&quot;%4&quot;(으)로 전환하면 이 명령들을 버스가 맡게 됩니다: 입력 단자로는 더 이상 모터를 기동·정지할 수 없고, &quot;%2&quot;(으)로 되돌릴 때까지 설비 자체의 조작은 효과가 없습니다.</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="85"/>
        <source>Switch to communication priority</source>
        <translation>통신 우선으로 전환</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="86"/>
        <source>Machine number %1 will take run, stop, direction and speed selection from the bus (%2 = &quot;%3&quot;). Its input terminals then no longer start or stop the motor.</source>
        <translation>국번 %1이(가) 운전, 정지, 방향, 속도 선택을 버스로 받게 됩니다(%2 = &quot;%3&quot;). 그러면 입력 단자로는 더 이상 모터를 기동·정지할 수 없습니다.</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="92"/>
        <source>Switch</source>
        <translation>전환</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="101"/>
        <source>Switching to communication priority…</source>
        <translation>통신 우선으로 전환하는 중…</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="109"/>
        <source>Machine number %1 takes motion commands over the bus now.</source>
        <translation>국번 %1이(가) 이제 버스로 운전 명령을 받습니다.</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="111"/>
        <source>Cannot switch the control priority: %1</source>
        <translation>제어 우선순위를 전환할 수 없습니다: %1</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="121"/>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="127"/>
        <source>Return to I/O priority</source>
        <translation>I/O 우선으로 복귀</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="122"/>
        <source>Machine number %1 will take run, stop, direction and speed selection from its input terminals again, and refuse motion commands over the bus. If an input says run, the motor runs.</source>
        <translation>국번 %1이(가) 다시 입력 단자로 운전, 정지, 방향, 속도 선택을 받고, 버스를 통한 운전 명령은 거부합니다. 입력이 운전 상태이면 모터가 운전합니다.</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="130"/>
        <source>Returning to I/O priority…</source>
        <translation>I/O 우선으로 복귀하는 중…</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="139"/>
        <source>Machine number %1 follows its input terminals again.</source>
        <translation>국번 %1이(가) 다시 입력 단자를 따릅니다.</translation>
    </message>
</context>
<context>
    <name>opentop::MotorSpeedBox</name>
    <message>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="23"/>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="49"/>
        <source>Motor speed</source>
        <translation>모터 속도</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="33"/>
        <source>not set</source>
        <translation>설정 안 됨</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="34"/>
        <source>Commutations per motor revolution (a motor property, see its data sheet). r/min = %1 ÷ this × 60.</source>
        <translation>모터 1회전당 정류 횟수(모터 특성, 데이터시트 참조). r/min = %1 ÷ 이 값 × 60.</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="38"/>
        <source>Commutations per revolution</source>
        <translation>1회전당 정류 횟수</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="79"/>
        <source>set the commutations per revolution</source>
        <translation>1회전당 정류 횟수를 설정하십시오</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="83"/>
        <source>%1 r/min</source>
        <translation>%1 r/min</translation>
    </message>
</context>
<context>
    <name>opentop::MultiDriveWriteDialog</name>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="39"/>
        <source>&amp;Write to all</source>
        <translation>모두에 쓰기(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="41"/>
        <source>Write one setting to several drives</source>
        <translation>설정 하나를 여러 드라이버에 쓰기</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="58"/>
        <source>Machine number</source>
        <translation>국번</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="58"/>
        <source>Model</source>
        <translation>모델</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="58"/>
        <source>Current value</source>
        <translation>현재 값</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="59"/>
        <source>Result</source>
        <translation>결과</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="77"/>
        <source>Not written: another family (%1)</source>
        <translation>쓰지 않음: 다른 제품군(%1)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="78"/>
        <source>Not written: not identified (%1)</source>
        <translation>쓰지 않음: 식별 안 됨(%1)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="83"/>
        <source>&amp;Setting:</source>
        <translation>설정(&amp;S):</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="89"/>
        <source>New &amp;value:</source>
        <translation>새 값(&amp;V):</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="162"/>
        <source>cannot be read</source>
        <translation>읽을 수 없음</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="165"/>
        <source>reading…</source>
        <translation>읽는 중…</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="193"/>
        <source>read failed: %1</source>
        <translation>읽기 실패: %1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="218"/>
        <source>Drive %1: %2 is not known yet, and the allowed values depend on it.</source>
        <translation>드라이버 %1: %2을(를) 아직 알 수 없는데, 허용 값이 이 값에 따라 달라집니다.</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="222"/>
        <source>drive %1: %2</source>
        <translation>드라이버 %1: %2</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="228"/>
        <source>The unit differs between the drives (%1); write them one at a time.</source>
        <translation>드라이버마다 단위가 다릅니다(%1). 하나씩 쓰십시오.</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="237"/>
        <source>Not allowed on drive %1 (%2): %3</source>
        <translation>드라이버 %1에서 허용되지 않음(%2): %3</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="244"/>
        <source>Not allowed on the communication group of drive %1: %2</source>
        <translation>드라이버 %1의 통신 그룹에서 허용되지 않습니다: %2</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="249"/>
        <source>None of the selected drives is identified.</source>
        <translation>선택한 드라이버 중 식별된 것이 없습니다.</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="263"/>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="315"/>
        <source>Drive %1: %2</source>
        <translation>드라이버 %1: %2</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="266"/>
        <source>Allowed on %1</source>
        <translation>%1에서 허용</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="274"/>
        <source>Warning: %1</source>
        <translation>경고: %1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="275"/>
        <source>Allowed on %1.</source>
        <translation>%1에서 허용.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="323"/>
        <source>Set it on %n drive(s) anyway?</source>
        <translation>
            <numerusform>그래도 드라이버 %n대에 설정하시겠습니까?</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="324"/>
        <source>&amp;Set it</source>
        <translation>설정(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="344"/>
        <source>Write %1 to machine number(s) %2</source>
        <translation>%1을(를) 국번 %2에 쓰기</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="346"/>
        <source>Nothing was written.</source>
        <translation>아무것도 쓰지 않았습니다.</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="351"/>
        <source>waiting…</source>
        <translation>대기 중…</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="353"/>
        <source>Writing %1 to %n drive(s)…</source>
        <translation>
            <numerusform>%1을(를) 드라이버 %n대에 쓰는 중…</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="365"/>
        <source>Written and verified on %1 of %n drive(s).</source>
        <translation>
            <numerusform>드라이버 %n대 중 %1대에 쓰기 및 검증 완료.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="374"/>
        <source>writing…</source>
        <translation>쓰는 중…</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="391"/>
        <source>Written and verified</source>
        <translation>쓰기 및 검증 완료</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="393"/>
        <source>Written, not verified: %1</source>
        <translation>쓰기 완료, 확인 안 됨: %1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="394"/>
        <source>Written, not verified (cannot be read back)</source>
        <translation>쓰기 완료, 검증 안 됨(다시 읽을 수 없음)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="395"/>
        <source>Failed: %1</source>
        <translation>실패: %1</translation>
    </message>
</context>
<context>
    <name>opentop::NameCommand</name>
    <message>
        <location filename="../cli/NameCommand.cpp" line="39"/>
        <source>Name a machine (&quot;Infeed conveyor 3&quot;) or show the names of the bus</source>
        <translation>기계에 이름 지정(&quot;Infeed conveyor 3&quot;) 또는 버스의 이름 표시</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="45"/>
        <source>error: name takes a machine number and one name; put a name with spaces in quotes: name 1 &quot;Infeed conveyor 3&quot;</source>
        <translation>오류: name에는 국번 하나와 이름 하나를 줍니다. 공백이 있는 이름은 따옴표로 묶으십시오: name 1 &quot;Infeed conveyor 3&quot;</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="53"/>
        <source>error: %1</source>
        <translation>오류: %1</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="63"/>
        <source>No machine of this bus has a name yet; give one with: name ID &quot;TEXT&quot;</source>
        <translation>이 버스의 기계에는 아직 이름이 없습니다. 다음으로 지정하십시오: name ID &quot;TEXT&quot;</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="67"/>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="67"/>
        <source>name</source>
        <translation>이름</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="78"/>
        <source>error: &quot;%1&quot; is not a machine number 1–247</source>
        <translation>오류: &quot;%1&quot;은(는) 1–247의 국번이 아닙니다</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="88"/>
        <source>Machine number %1 has no name.</source>
        <translation>국번 %1에는 이름이 없습니다.</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="94"/>
        <source>error: %1 Nothing was changed.</source>
        <translation>오류: %1 아무것도 바꾸지 않았습니다.</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="107"/>
        <source>Machine number %1 has no name now.</source>
        <translation>국번 %1은(는) 이제 이름이 없습니다.</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="108"/>
        <source>%1 is named now; messages, files and scans show it.</source>
        <translation>%1에 이름을 붙였습니다. 메시지, 파일, 스캔에 표시됩니다.</translation>
    </message>
</context>
<context>
    <name>opentop::OutputFile</name>
    <message>
        <location filename="../model/io/OutputFile.cpp" line="24"/>
        <source>cannot write %1: it is a directory; name a file</source>
        <translation>%1에 쓸 수 없습니다: 디렉터리입니다. 파일을 지정하십시오</translation>
    </message>
    <message>
        <location filename="../model/io/OutputFile.cpp" line="26"/>
        <source>cannot write %1: the folder %2 does not exist</source>
        <translation>%1에 쓸 수 없습니다: 폴더 %2이(가) 없습니다</translation>
    </message>
    <message>
        <location filename="../model/io/OutputFile.cpp" line="35"/>
        <source>cannot write %1: %2</source>
        <translation>%1에 쓸 수 없습니다: %2</translation>
    </message>
    <message>
        <location filename="../model/io/OutputFile.cpp" line="40"/>
        <source>it is a directory; name a file</source>
        <translation>디렉터리입니다. 파일을 지정하십시오</translation>
    </message>
</context>
<context>
    <name>opentop::PanelMirror</name>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="20"/>
        <source>speed</source>
        <translation>속도</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="22"/>
        <source>machine number</source>
        <translation>국번</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="24"/>
        <source>running data No.</source>
        <translation>운전 데이터 번호</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="26"/>
        <source>countdown</source>
        <translation>카운트다운</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="28"/>
        <source>load rate</source>
        <translation>부하율</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="47"/>
        <source>Alarm %1 %2</source>
        <translation>알람 %1 %2</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="48"/>
        <source>Alarm (code not read yet)</source>
        <translation>알람 (코드 아직 읽지 않음)</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="59"/>
        <source>Current speed %1 %2</source>
        <translation>현재 속도 %1 %2</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="63"/>
        <source>Current speed: no finite value in %1</source>
        <translation>현재 속도: %1에 유한한 값이 없습니다</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="70"/>
        <source>Current speed %1 r/min</source>
        <translation>현재 속도 %1 r/min</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="70"/>
        <source>Speed not read</source>
        <translation>속도 읽지 않음</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="76"/>
        <source>Machine number %1</source>
        <translation>국번 %1</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="83"/>
        <source>Running data SPno%1</source>
        <translation>운전 데이터 SPno%1</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="86"/>
        <source>Running data not read</source>
        <translation>운전 데이터 읽지 않음</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="96"/>
        <source>Countdown set to %1 d %2 h %3 min %4 s (the drive does not report the time left)</source>
        <translation>카운트다운 설정 %1일 %2시간 %3분 %4초 (드라이버는 남은 시간을 알려주지 않음)</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="110"/>
        <source>Load rate %1 %</source>
        <translation>부하율 %1 %</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="113"/>
        <source>Load rate not read</source>
        <translation>부하율 읽지 않음</translation>
    </message>
</context>
<context>
    <name>opentop::PanelMirrorView</name>
    <message>
        <location filename="../ui/monitor/PanelMirrorView.cpp" line="21"/>
        <source>Drive panel</source>
        <translation>드라이버 패널</translation>
    </message>
    <message>
        <location filename="../ui/monitor/PanelMirrorView.cpp" line="51"/>
        <source>Not read yet</source>
        <translation>아직 읽지 않음</translation>
    </message>
    <message>
        <location filename="../ui/monitor/PanelMirrorView.cpp" line="64"/>
        <source>%1 (more digits than the panel has)</source>
        <translation>%1 (패널 자릿수 초과)</translation>
    </message>
    <message>
        <location filename="../ui/monitor/PanelMirrorView.cpp" line="68"/>
        <source>Panel set to show the %1 while running.</source>
        <translation>운전 중 패널에 %1을(를) 표시하도록 설정되어 있습니다.</translation>
    </message>
    <message>
        <location filename="../ui/monitor/PanelMirrorView.cpp" line="69"/>
        <source>Drive panel shows %1</source>
        <translation>드라이버 패널 표시: %1</translation>
    </message>
    <message>
        <location filename="../ui/monitor/PanelMirrorView.cpp" line="80"/>
        <source>not live</source>
        <translation>실시간 아님</translation>
    </message>
</context>
<context>
    <name>opentop::ParameterField</name>
    <message>
        <location filename="../ui/workspace/ParameterField.cpp" line="217"/>
        <source>%1 (not valid now)</source>
        <translation>%1 (현재 무효)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterField.cpp" line="246"/>
        <source>not read</source>
        <translation>읽지 않음</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterField.cpp" line="255"/>
        <source>Allowed: %1</source>
        <translation>허용: %1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterField.cpp" line="258"/>
        <source>On the drive: %1</source>
        <translation>드라이버 값: %1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterField.cpp" line="289"/>
        <source>Not accepted: %1</source>
        <translation>받아들일 수 없음: %1</translation>
    </message>
</context>
<context>
    <name>opentop::ParameterInitBox</name>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="40"/>
        <source>Parameter initialisation</source>
        <translation>파라미터 초기화</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="50"/>
        <source>Returns every setting of drive %1 to its factory default, including the communication settings: afterwards the drive may answer only at the default rate, and control priority goes back to its input terminals. The motor must be stopped. The consequences for this drive are listed before anything is sent.</source>
        <translation>드라이버 %1의 모든 설정을 통신 설정까지 포함하여 공장 출하값으로 되돌립니다: 그 후 드라이버는 기본 통신 속도로만 응답할 수 있고, 제어 우선순위는 입력 단자로 돌아갑니다. 모터는 정지해 있어야 합니다. 무엇이든 보내기 전에 이 드라이버에 미치는 영향을 먼저 표시합니다.</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="58"/>
        <source>&amp;Initialise all parameters of drive %1…</source>
        <translation>드라이버 %1의 모든 파라미터 초기화(&amp;I)…</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="60"/>
        <source>Asks first, naming the drive and what changes</source>
        <translation>드라이버와 변경 내용을 표시하고 먼저 확인합니다</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="88"/>
        <source>Reading what the initialisation would change…</source>
        <translation>초기화로 변경될 내용을 읽는 중…</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="112"/>
        <source>Afterwards:</source>
        <translation>이후:</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="117"/>
        <source>Your %n unwritten edit(s) of this drive are discarded.</source>
        <translation>
            <numerusform>이 드라이버에서 쓰지 않은 편집 %n개는 버려집니다.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="123"/>
        <source>Sent: %1 to machine %2 only.</source>
        <translation>보냄: %1, 국번 %2에만.</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="124"/>
        <source>Sent: %1 to machine %2.</source>
        <translation>보냄: %1, 국번 %2.</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="128"/>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="133"/>
        <source>Initialise drive %1</source>
        <translation>드라이버 %1 초기화</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="129"/>
        <source>Reset every setting of %1 to its factory defaults?</source>
        <translation>%1의 모든 설정을 공장 기본값으로 되돌리시겠습니까?</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="143"/>
        <source>Cancelled; nothing was sent.</source>
        <translation>취소됨. 아무것도 보내지 않았습니다.</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="151"/>
        <source>Initialising drive %1…</source>
        <translation>드라이버 %1 초기화 중…</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="160"/>
        <source>Drive %1 did not confirm the initialisation: %2</source>
        <translation>드라이버 %1이(가) 초기화를 확인하지 않았습니다: %2</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="161"/>
        <source>Nothing was sent: %1</source>
        <translation>아무것도 보내지 않았습니다: %1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="174"/>
        <source>&amp;Reconnect at %1 bit/s after the power-up</source>
        <translation>전원 투입 후 %1 bit/s로 다시 연결(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="178"/>
        <source>Drive %1 initialised; reading its values again…</source>
        <translation>드라이버 %1 초기화 완료. 값을 다시 읽는 중…</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="184"/>
        <source>Drive %1 initialised; %n value(s) could not be read back (it may answer only at the default communication settings now).</source>
        <translation>
            <numerusform>드라이버 %1 초기화 완료. 값 %n개를 다시 읽을 수 없습니다(이제 기본 통신 설정으로만 응답할 수 있음).</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="188"/>
        <source>Drive %1 initialised to its factory defaults; values read again.</source>
        <translation>드라이버 %1을(를) 공장 출하값으로 초기화하고 값을 다시 읽었습니다.</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="214"/>
        <source>Reconnecting at %1 bit/s in %2 s…</source>
        <translation>%2 s 후 %1 bit/s로 다시 연결합니다…</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="227"/>
        <source>Reconnect at %1 bit/s from the Bus menu.</source>
        <translation>버스 메뉴에서 %1 bit/s로 다시 연결하십시오.</translation>
    </message>
</context>
<context>
    <name>opentop::ParameterInitialiser</name>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="65"/>
        <source>%1 drives have no parameter initialisation.</source>
        <translation>%1 드라이버에는 파라미터 초기화가 없습니다.</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="68"/>
        <source>%1 = %2 (register %3)</source>
        <translation>%1 = %2 (레지스터 %3)</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="76"/>
        <source>Drive %1 is running. Stop the motor first: parameter initialisation is only sent to a drive at standstill.</source>
        <translation>드라이버 %1이(가) 운전 중입니다. 먼저 모터를 정지하십시오: 파라미터 초기화는 정지 상태의 드라이버에만 보냅니다.</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="80"/>
        <source>Whether drive %1 is running could not be read (%2), so nothing was sent.</source>
        <translation>드라이버 %1의 운전 여부를 읽을 수 없어(%2) 아무것도 보내지 않았습니다.</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="94"/>
        <source>Every setting of drive %1 returns to its factory default: %2. Values set for this machine are lost; save a backup first to keep them.</source>
        <translation>드라이버 %1의 모든 설정이 공장 출하값으로 돌아갑니다: %2. 이 설비에 맞춰 설정한 값은 사라지므로, 유지하려면 먼저 백업을 저장하십시오.</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="111"/>
        <source>%1 could not be read; it returns to %2. %3</source>
        <translation>%1을(를) 읽을 수 없습니다. %2(으)로 돌아갑니다. %3</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="114"/>
        <source>%1 goes from %2 back to %3. %4</source>
        <translation>%1이(가) %2에서 %3(으)로 돌아갑니다. %4</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="119"/>
        <source>%1 stays %2 (already the default).</source>
        <translation>%1은(는) %2 그대로입니다(이미 기본값).</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="123"/>
        <source>%1 bit/s, parity %2, %3 stop bit(s)</source>
        <translation>%1 bit/s, 패리티 %2, 스톱 비트 %3</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="131"/>
        <source>The link to the drive is lost from its next power-up: it answers only at the factory line settings, %1.</source>
        <translation>다음 전원 투입부터 드라이버와의 연결이 끊깁니다: 드라이버는 공장 출하 통신 설정(%1)으로만 응답합니다.</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="142"/>
        <source>To reach drive %1 again: switch it off and on, wait %2 s after power-on, then reconnect at %3.</source>
        <translation>드라이버 %1에 다시 연결하려면: 전원을 껐다 켜고, 전원 투입 후 %2 s 기다린 다음 %3(으)로 다시 연결하십시오.</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="159"/>
        <source>Bus control is lost: the drive follows its input terminals again and refuses start, stop and speed commands over the bus; an input that is on may start the motor, with the factory input functions.</source>
        <translation>버스 제어가 해제됩니다: 드라이버가 다시 입력 단자를 따르며 버스를 통한 기동·정지·속도 명령을 거부합니다. ON인 입력이 있으면 공장 출하 입력 기능으로 모터가 기동할 수 있습니다.</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="168"/>
        <source>To control the motor over the bus again, set %1 to %2.</source>
        <translation>버스로 모터를 다시 제어하려면 %1을(를) %2(으)로 설정하십시오.</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="150"/>
        <source>The drive no longer follows writes sent to its group&apos;s parent, and drives that followed it no longer do.</source>
        <translation>드라이버가 더 이상 그룹 부모로 보낸 쓰기를 따르지 않으며, 이 드라이버를 따르던 드라이버도 더 이상 따르지 않습니다.</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="173"/>
        <source>The machine number %1 is not a setting and does not change.</source>
        <translation>국번 %1은(는) 설정이 아니므로 바뀌지 않습니다.</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="175"/>
        <source>The motor must stand still: drive %1 reports it stopped now, and this is read again just before the command is sent.</source>
        <translation>모터가 정지해 있어야 합니다: 드라이버 %1은(는) 지금 정지 상태이며, 명령을 보내기 직전에 다시 확인합니다.</translation>
    </message>
</context>
<context>
    <name>opentop::ParameterPage</name>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="26"/>
        <location filename="../ui/workspace/ParameterPage.cpp" line="149"/>
        <source>&amp;Write page</source>
        <translation>페이지 쓰기(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="27"/>
        <source>Re&amp;vert</source>
        <translation>되돌리기(&amp;V)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="28"/>
        <source>Re-&amp;read</source>
        <translation>다시 읽기(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="48"/>
        <source>Write this page&apos;s pending edits to the drive and verify them by reading back</source>
        <translation>이 페이지의 쓰기 대기 편집을 드라이버에 쓰고 다시 읽어 검증합니다</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="49"/>
        <source>Discard this page&apos;s pending edits</source>
        <translation>이 페이지의 쓰기 대기 편집을 버립니다</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="50"/>
        <source>Read this page&apos;s values from the drive again (edits stay)</source>
        <translation>이 페이지의 값을 드라이버에서 다시 읽습니다(편집 내용은 유지)</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterPage.cpp" line="137"/>
        <source>Every field is accepted now. Nothing has been written yet: Write page sends %n value(s).</source>
        <translation>
            <numerusform>이제 모든 필드가 허용됩니다. 아직 아무것도 쓰지 않았습니다: 페이지 쓰기가 값 %n개를 보냅니다.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="150"/>
        <source>&amp;Write page (%1)</source>
        <translation>페이지 쓰기(&amp;W) (%1)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="163"/>
        <source>Reading…</source>
        <translation>읽는 중…</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterPage.cpp" line="167"/>
        <source>%n value(s) could not be read</source>
        <translation>
            <numerusform>값 %n개를 읽을 수 없습니다</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterPage.cpp" line="116"/>
        <source>Nothing was written: %n field(s) not accepted. %1</source>
        <translation>
            <numerusform>아무것도 쓰지 않았습니다: 받아들일 수 없는 항목 %n개. %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterPage.cpp" line="208"/>
        <source>Write %n value(s) of the page %1 to machine number %2</source>
        <translation>
            <numerusform>페이지 %1의 값 %n개를 국번 %2에 쓰기</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="182"/>
        <location filename="../ui/workspace/ParameterPage.cpp" line="203"/>
        <location filename="../ui/workspace/ParameterPage.cpp" line="212"/>
        <source>Nothing was written.</source>
        <translation>아무것도 쓰지 않았습니다.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterPage.cpp" line="217"/>
        <source>Writing %n value(s)…</source>
        <translation>
            <numerusform>값 %n개 쓰는 중…</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::ParameterReader</name>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="55"/>
        <source>entry</source>
        <translation>항목</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="63"/>
        <source>name must be lower-case dotted words: [a-z0-9_] separated by dots</source>
        <translation>name은 점으로 구분한 소문자 단어여야 합니다: [a-z0-9_]를 점으로 구분</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="72"/>
        <source>&quot;label&quot; is empty</source>
        <translation>&quot;label&quot;이 비어 있습니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="74"/>
        <source>group &quot;%1&quot; is not declared in &quot;groups&quot;</source>
        <translation>그룹 &quot;%1&quot;이(가) &quot;groups&quot;에 선언되어 있지 않습니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="76"/>
        <source>kind must be one of %1</source>
        <translation>kind는 %1 중 하나여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="82"/>
        <source>address must be 0x0000–0xFFFF</source>
        <translation>address는 0x0000–0xFFFF여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="89"/>
        <source>read must be 3 (holding) or 4 (input)</source>
        <translation>read는 3(holding) 또는 4(input)여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="91"/>
        <source>write must be 6 or 16</source>
        <translation>write는 6 또는 16이어야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="95"/>
        <source>input registers (read 4) cannot be written</source>
        <translation>입력 레지스터(read 4)에는 쓸 수 없습니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="97"/>
        <source>neither readable nor writable</source>
        <translation>읽을 수도 쓸 수도 없습니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="105"/>
        <source>type must be u16, s16, u32, s32, f32, string or bits</source>
        <translation>type은 u16, s16, u32, s32, f32, string 또는 bits여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="114"/>
        <source>string parameters need &quot;count&quot; 1–125 registers</source>
        <translation>string 파라미터에는 &quot;count&quot; 1–125 레지스터가 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="119"/>
        <source>bits parameters have &quot;count&quot; 1 or 2</source>
        <translation>bits 파라미터의 &quot;count&quot;는 1 또는 2입니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="124"/>
        <source>%1 takes %2 register(s), not %3</source>
        <translation>%1은(는) 레지스터 %3개가 아니라 %2개를 차지합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="129"/>
        <source>&quot;wordOrder&quot; is for 2-register numbers and bit fields only</source>
        <translation>&quot;wordOrder&quot;는 2레지스터 숫자와 비트 필드에만 쓸 수 있습니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="133"/>
        <source>&quot;wordOrder&quot; must be &quot;high-first&quot; or &quot;low-first&quot;</source>
        <translation>&quot;wordOrder&quot;는 &quot;high-first&quot; 또는 &quot;low-first&quot;여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="136"/>
        <source>a %1-register value cannot be written with function 06; use 16</source>
        <translation>레지스터 %1개짜리 값은 기능 06으로 쓸 수 없습니다. 16을 사용하십시오</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="141"/>
        <source>safety must be one of %1</source>
        <translation>safety는 %1 중 하나여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="143"/>
        <source>commands need a &quot;safety&quot; class</source>
        <translation>명령에는 &quot;safety&quot; 등급이 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="146"/>
        <source>code table &quot;%1&quot; is not declared</source>
        <translation>코드 표 &quot;%1&quot;이(가) 선언되어 있지 않습니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="157"/>
        <source>a setting needs &quot;allowed&quot; or &quot;enum&quot;</source>
        <translation>설정에는 &quot;allowed&quot; 또는 &quot;enum&quot;이 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="160"/>
        <source>a writable parameter needs &quot;allowed&quot; or &quot;enum&quot;</source>
        <translation>쓸 수 있는 파라미터에는 &quot;allowed&quot; 또는 &quot;enum&quot;이 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="165"/>
        <source>bits parameters need &quot;bits&quot;</source>
        <translation>bits 파라미터에는 &quot;bits&quot;가 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="173"/>
        <source>&quot;backup&quot; must be true or false</source>
        <translation>&quot;backup&quot;은 true 또는 false여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="178"/>
        <source>only readable and writable parameters can be backed up</source>
        <translation>읽기·쓰기가 모두 가능한 파라미터만 백업할 수 있습니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="191"/>
        <source>%1 needs &quot;address&quot; and &quot;count&quot;</source>
        <translation>%1에는 &quot;address&quot;와 &quot;count&quot;가 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="193"/>
        <source>%1: the parameter is not writable</source>
        <translation>%1: 이 파라미터는 쓸 수 없습니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="196"/>
        <source>%1: address 0x0000–0xFFFF and count 1–%2 (limits.maxWriteRegisters)</source>
        <translation>%1: address는 0x0000–0xFFFF, count는 1–%2여야 합니다(limits.maxWriteRegisters)</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="205"/>
        <source>%1: tail values are registers, 0–65535</source>
        <translation>%1: tail 값은 레지스터 값(0–65535)입니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="213"/>
        <source>%1: the parameter&apos;s registers must lie in the block, before its tail</source>
        <translation>%1: 파라미터의 레지스터는 블록 안, tail 앞에 있어야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="221"/>
        <source>scale must be positive</source>
        <translation>scale은 양수여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="233"/>
        <source>decimals must be 0–9</source>
        <translation>decimals는 0–9여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="257"/>
        <source>recommended[%1] is not inside one of the &quot;allowed&quot; intervals</source>
        <translation>recommended[%1]이(가) &quot;allowed&quot; 구간 중 어디에도 속하지 않습니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="275"/>
        <source>default %1 is not a whole number of steps of %2</source>
        <translation>기본값 %1이(가) %2 단위의 정수배가 아닙니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="284"/>
        <source>default must be a number (or &quot;0x...&quot; code)</source>
        <translation>기본값은 숫자(또는 &quot;0x...&quot; 코드)여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="287"/>
        <source>default must be a number or a string</source>
        <translation>기본값은 숫자 또는 문자열이어야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="298"/>
        <source>%1 must be an object {&quot;min&quot;:…, &quot;max&quot;:…}</source>
        <translation>%1은(는) 객체 {&quot;min&quot;:…, &quot;max&quot;:…}여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="305"/>
        <source>%1 needs numeric min and max</source>
        <translation>%1에는 숫자 min과 max가 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="311"/>
        <source>%1: %2 is not a whole number of steps of %3</source>
        <translation>%1: %2이(가) %3 단위의 정수배가 아닙니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="319"/>
        <source>%1: min is greater than max</source>
        <translation>%1: min이 max보다 큽니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="333"/>
        <source>%1 must be an object {&quot;value&quot;:…, &quot;label&quot;:…}</source>
        <translation>%1은(는) 객체 {&quot;value&quot;:…, &quot;label&quot;:…}여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="349"/>
        <source>%1 has no label</source>
        <translation>%1에 label이 없습니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="351"/>
        <source>%1 repeats a code or label</source>
        <translation>%1에 코드 또는 label이 중복됩니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="362"/>
        <source>&quot;bits&quot; only belongs to type bits</source>
        <translation>&quot;bits&quot;는 type bits에만 쓸 수 있습니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="386"/>
        <source>%1.appliesWhen needs &quot;param&quot; and &quot;equals&quot;</source>
        <translation>%1.appliesWhen에는 &quot;param&quot;과 &quot;equals&quot;가 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="391"/>
        <source>%1 lies outside the %2-bit register</source>
        <translation>%1이(가) %2비트 레지스터 범위를 벗어납니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="393"/>
        <source>%1 needs a unique name</source>
        <translation>%1에는 고유한 이름이 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="407"/>
        <source>%1 must be an object</source>
        <translation>%1은(는) 객체여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="419"/>
        <source>%1 needs either &quot;variant&quot; or &quot;param&quot;</source>
        <translation>%1에는 &quot;variant&quot; 또는 &quot;param&quot;이 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="422"/>
        <source>%1: variant &quot;%2&quot; is not declared</source>
        <translation>%1: variant &quot;%2&quot;이(가) 선언되어 있지 않습니다</translation>
    </message>
</context>
<context>
    <name>opentop::ParamsCommand</name>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="82"/>
        <source>List every parameter of the device profiles</source>
        <translation>장치 프로파일의 모든 파라미터를 나열합니다</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="162"/>
        <source>error: params takes no arguments; use --family F</source>
        <translation>오류: params는 인수를 받지 않습니다. --family F를 사용하십시오</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="170"/>
        <source>error: unknown family &quot;%1&quot;; known: %2</source>
        <translation>오류: 알 수 없는 제품군 &quot;%1&quot;; 알려진 제품군: %2</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="192"/>
        <source>Name</source>
        <translation>이름</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="192"/>
        <source>Label</source>
        <translation>표시 이름</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="192"/>
        <source>Address</source>
        <translation>주소</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="192"/>
        <source>FC</source>
        <translation>FC</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="192"/>
        <source>Type</source>
        <translation>형식</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="192"/>
        <source>Unit</source>
        <translation>단위</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="193"/>
        <source>Allowed</source>
        <translation>허용</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="193"/>
        <source>Default</source>
        <translation>기본값</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="193"/>
        <source>Access</source>
        <translation>접근</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="193"/>
        <source>Group</source>
        <translation>그룹</translation>
    </message>
</context>
<context>
    <name>opentop::PasswordHash</name>
    <message>
        <location filename="../model/access/PasswordHash.cpp" line="52"/>
        <source>a password needs at least %1 characters</source>
        <translation>비밀번호는 %1자 이상이어야 합니다</translation>
    </message>
</context>
<context>
    <name>opentop::PidGains</name>
    <message>
        <location filename="../model/tuning/PidGains.cpp" line="9"/>
        <source>P %1, I %2, D %3, D period %4 ms</source>
        <translation>P %1, I %2, D %3, D 주기 %4 ms</translation>
    </message>
</context>
<context>
    <name>opentop::PlantModel</name>
    <message>
        <location filename="../model/tuning/PlantModel.cpp" line="18"/>
        <source>the relay test gives no usable model (K·Ku = %1, Tu = %2 ms)</source>
        <translation>릴레이 시험으로 쓸 수 있는 모델을 얻지 못했습니다(K·Ku = %1, Tu = %2 ms)</translation>
    </message>
</context>
<context>
    <name>opentop::PortsCommand</name>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="16"/>
        <source>List serial ports and USB adapters</source>
        <translation>시리얼 포트와 USB 어댑터를 나열합니다</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="23"/>
        <source>error: ports takes no arguments</source>
        <translation>오류: ports는 인수를 받지 않습니다</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="43"/>
        <source>No serial ports found.</source>
        <translation>시리얼 포트가 없습니다.</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="47"/>
        <source>Port</source>
        <translation>포트</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="48"/>
        <source>Adapter</source>
        <translation>어댑터</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="49"/>
        <source>Manufacturer</source>
        <translation>제조사</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="50"/>
        <source>Serial no.</source>
        <translation>시리얼 번호</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="51"/>
        <source>VID:PID</source>
        <translation>VID:PID</translation>
    </message>
</context>
<context>
    <name>opentop::ProbeJournal</name>
    <message>
        <location filename="../model/session/ProbeJournal.cpp" line="33"/>
        <source>%1 is not a probe journal (%2): ignored; a probe interrupted before may have left its value on a drive</source>
        <translation>%1은(는) 확인 기록 파일이 아닙니다(%2): 무시합니다. 이전에 중단된 확인이 드라이버에 값을 남겼을 수 있습니다</translation>
    </message>
    <message>
        <location filename="../model/session/ProbeJournal.cpp" line="42"/>
        <source>cannot create the folder of %1</source>
        <translation>%1의 폴더를 만들 수 없습니다</translation>
    </message>
    <message>
        <location filename="../model/session/ProbeJournal.cpp" line="78"/>
        <location filename="../model/session/ProbeJournal.cpp" line="92"/>
        <source>%1 is locked by another program</source>
        <translation>%1을(를) 다른 프로그램이 잠그고 있습니다</translation>
    </message>
</context>
<context>
    <name>opentop::ProductionMode</name>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="39"/>
        <source>&amp;Production mode (end of line)</source>
        <translation>생산 모드(&amp;P) (출하 검사)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="42"/>
        <source>The operator screen of an end-of-line station; no parameter editing until you switch back (Ctrl+Shift+P)</source>
        <translation>출하 검사 스테이션의 작업자 화면. 다시 전환할 때까지 파라미터 편집 불가(Ctrl+Shift+P)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="45"/>
        <source>&amp;Full screen</source>
        <translation>전체 화면(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="54"/>
        <source>&amp;Station name…</source>
        <translation>스테이션 이름(&amp;S)…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="55"/>
        <source>The name this end-of-line station records with every unit</source>
        <translation>이 출하 검사 스테이션이 모든 유닛에 기록하는 이름</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="64"/>
        <source>%1

No unit can be tested until results can be recorded. The station tries again by itself.</source>
        <translation>%1

결과를 기록할 수 있을 때까지 어떤 제품도 검사할 수 없습니다. 스테이션이 자동으로 다시 시도합니다.</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="83"/>
        <location filename="../ui/eol/ProductionMode.cpp" line="91"/>
        <source>Station name</source>
        <translation>스테이션 이름</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="84"/>
        <source>The name this station records with every unit (each station of a line needs its own):</source>
        <translation>이 스테이션이 모든 유닛에 기록하는 이름(한 라인의 각 스테이션은 고유한 이름이 필요합니다):</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="92"/>
        <source>A station needs a name.</source>
        <translation>스테이션에는 이름이 필요합니다.</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="93"/>
        <source>A unit is being tested: change the name once it is finished.</source>
        <translation>유닛을 검사 중입니다: 완료된 후 이름을 변경하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="110"/>
        <source>Production mode</source>
        <translation>생산 모드</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="111"/>
        <source>A unit is being tested. Cancel it (Esc) or let it finish before switching back to engineering mode.</source>
        <translation>제품 검사 중입니다. 엔지니어링 모드로 돌아가기 전에 검사를 취소(Esc)하거나 끝날 때까지 기다리십시오.</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="63"/>
        <source>Results database</source>
        <translation>결과 데이터베이스</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="124"/>
        <source>leave production mode</source>
        <translation>생산 모드 종료</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="171"/>
        <source>A unit is being tested</source>
        <translation>제품 검사 중</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="172"/>
        <source>Unit %1 is being tested. Cancel it and %2? Its motors are stopped first; the unit is recorded as aborted.</source>
        <translation>제품 %1을(를) 검사 중입니다. 검사를 취소하고 %2하시겠습니까? 먼저 모터를 정지하며, 제품은 중지됨으로 기록됩니다.</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="184"/>
        <source>cancelled to %1</source>
        <translation>%1하기 위해 취소함</translation>
    </message>
</context>
<context>
    <name>opentop::ProductionOptions</name>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="32"/>
        <source>Start in production mode (end-of-line station) with this recipe.</source>
        <translation>이 레시피로 생산 모드(출하 검사 스테이션)로 시작합니다.</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="33"/>
        <source>RECIPE</source>
        <translation>RECIPE</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="34"/>
        <source>Per-unit values (CSV by serial number) for production mode.</source>
        <translation>생산 모드용 제품별 값(시리얼 번호별 CSV).</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="34"/>
        <source>CSV</source>
        <translation>CSV</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="36"/>
        <source>Results database for production mode: an SQLite file or postgresql://user@host/db.</source>
        <translation>생산 모드용 결과 데이터베이스: SQLite 파일 또는 postgresql://user@host/db.</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="37"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="39"/>
        <source>This station&apos;s name in the results (default: as set in the program, else the computer&apos;s name); not saved.</source>
        <translation>결과에 기록되는 이 스테이션의 이름(기본값: 프로그램에서 설정한 이름, 없으면 컴퓨터 이름). 저장되지 않습니다.</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="41"/>
        <source>NAME</source>
        <translation>이름</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="42"/>
        <source>Start full screen.</source>
        <translation>전체 화면으로 시작합니다.</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="50"/>
        <source>--units, --results-db and --station go with --production RECIPE</source>
        <translation>--units, --results-db, --station은 --production RECIPE와 함께 사용합니다</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="59"/>
        <source>--station needs a name</source>
        <translation>--station에는 이름이 필요합니다</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="64"/>
        <source>%1 cannot be run:
  %2</source>
        <translation>%1을(를) 실행할 수 없습니다:
  %2</translation>
    </message>
</context>
<context>
    <name>opentop::ProductionView</name>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="56"/>
        <source>Open recipe…</source>
        <translation>레시피 열기…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="57"/>
        <source>Per-unit values…</source>
        <translation>제품별 값…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="63"/>
        <source>Recipe:</source>
        <translation>레시피:</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="84"/>
        <source>Drive</source>
        <translation>드라이버</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="84"/>
        <source>Now</source>
        <translation>현재</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="161"/>
        <source>Unit %1: %2…</source>
        <translation>제품 %1: %2…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="195"/>
        <source>Recipe not usable</source>
        <translation>레시피 사용 불가</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="196"/>
        <source>%1 cannot be run; nothing will be sent:

%2</source>
        <translation>%1을(를) 실행할 수 없습니다. 아무것도 보내지 않습니다:

%2</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="217"/>
        <source>open another recipe</source>
        <translation>다른 레시피 열기</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="220"/>
        <source>Open recipe</source>
        <translation>레시피 열기</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="220"/>
        <source>Recipes (*.json)</source>
        <translation>레시피 (*.json)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="228"/>
        <location filename="../ui/eol/ProductionView.cpp" line="234"/>
        <source>Per-unit values</source>
        <translation>제품별 값</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="229"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV 파일 (*.csv)</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/eol/ProductionView.cpp" line="242"/>
        <source>&lt;b&gt;%1&lt;/b&gt; rev. %2 — %n drive(s)</source>
        <translation>
            <numerusform>&lt;b&gt;%1&lt;/b&gt; 개정 %2 — 드라이버 %n대</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="246"/>
        <source>&lt;i&gt;none: open the product&apos;s recipe&lt;/i&gt;</source>
        <translation>&lt;i&gt;없음: 제품의 레시피를 여십시오&lt;/i&gt;</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="247"/>
        <source>Station %1 · results: %2 · per-unit values: %3</source>
        <translation>스테이션 %1 · 결과: %2 · 제품별 값: %3</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="250"/>
        <source>loaded</source>
        <translation>불러옴</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="250"/>
        <source>none</source>
        <translation>없음</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="118"/>
        <source>Unit %1: making the station&apos;s drives safe first…</source>
        <translation>유닛 %1: 먼저 스테이션의 드라이브를 안전 상태로 만드는 중…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="287"/>
        <source>drive %1</source>
        <translation>드라이버 %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="288"/>
        <source>drive %1 (%2)</source>
        <translation>드라이버 %1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="289"/>
        <source>waiting</source>
        <translation>대기 중</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="294"/>
        <source>Unit %1 — attempt %2</source>
        <translation>제품 %1 — %2회차</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="316"/>
        <source>Kept on this station: the results server did not answer. It is sent by itself when the server answers.</source>
        <translation>이 스테이션에 보관됨: 결과 서버가 응답하지 않았습니다. 서버가 응답하면 자동으로 전송됩니다.</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="361"/>
        <source>%1
Recorded at %2, after the results database came back.</source>
        <translation>%1
결과 데이터베이스가 복구된 뒤 %2에 기록했습니다.</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="161"/>
        <location filename="../ui/eol/ProductionView.cpp" line="295"/>
        <location filename="../ui/eol/ProductionView.cpp" line="314"/>
        <location filename="../ui/eol/ProductionView.cpp" line="362"/>
        <source>Unit %1</source>
        <translation>제품 %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="341"/>
        <source>Unit %1 ended %2, but its result is not in the results database: %3
Nothing is tested until it is recorded. The station tries again by itself (next try at %4); keep the unit aside.</source>
        <translation>제품 %1 검사가 %2(으)로 끝났지만 결과가 결과 데이터베이스에 기록되지 않았습니다: %3
기록될 때까지 검사하지 않습니다. 스테이션이 자동으로 다시 시도합니다(다음 시도 %4). 이 제품은 따로 두십시오.</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="322"/>
        <source>Motor not confirmed stopped</source>
        <translation>모터 정지 확인 안 됨</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="323"/>
        <source>These motors may still be turning; stop them before touching the unit:

%1</source>
        <translation>다음 모터가 아직 회전 중일 수 있습니다. 제품을 만지기 전에 정지하십시오:

%1</translation>
    </message>
</context>
<context>
    <name>opentop::ProfileCrossCheck</name>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="49"/>
        <source>%1: storeWith &quot;%2&quot; is not a command parameter</source>
        <translation>%1: storeWith &quot;%2&quot;은(는) 명령 파라미터가 아닙니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="52"/>
        <source>%1: the default is not among its allowed values</source>
        <translation>%1: 기본값이 허용 값에 포함되지 않습니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="56"/>
        <source>%1: bit field &quot;%2&quot;: function &quot;%3&quot; is not a readable parameter</source>
        <translation>%1: 비트 필드 &quot;%2&quot;: 기능 &quot;%3&quot;은(는) 읽을 수 있는 파라미터가 아닙니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="63"/>
        <source>%1: condition on unknown parameter &quot;%2&quot;</source>
        <translation>%1: 알 수 없는 파라미터 &quot;%2&quot;에 대한 조건</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="65"/>
        <source>%1: the default is not allowed when %2</source>
        <translation>%1: %2일 때는 기본값이 허용되지 않습니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="75"/>
        <source>%1 runs past address 0xFFFF</source>
        <translation>%1이(가) 주소 0xFFFF를 넘어갑니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="78"/>
        <source>%1 overlaps &quot;%2&quot; at 0x%3 (%4 registers)</source>
        <translation>%1이(가) 0x%3에서 &quot;%2&quot;와(과) 겹칩니다(레지스터 %4개)</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="107"/>
        <source>identify: &quot;%1&quot; must be a parameter inside the identify read</source>
        <translation>identify: &quot;%1&quot;은(는) identify 읽기 범위 안의 파라미터여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="110"/>
        <source>identify.nameMatch is not a valid regular expression</source>
        <translation>identify.nameMatch가 올바른 정규식이 아닙니다</translation>
    </message>
</context>
<context>
    <name>opentop::ProfileLoader</name>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="345"/>
        <source>not valid JSON at offset %1: %2</source>
        <translation>오프셋 %1에서 올바른 JSON이 아닙니다: %2</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="349"/>
        <source>the top level must be a JSON object</source>
        <translation>최상위는 JSON 객체여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="360"/>
        <source>&quot;parameters&quot; is empty</source>
        <translation>&quot;parameters&quot;가 비어 있습니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="371"/>
        <source>must be an object</source>
        <translation>객체여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="373"/>
        <source>name repeated</source>
        <translation>이름이 중복됩니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="384"/>
        <source>texts: {setting:…} names no parameter (%1)</source>
        <translation>texts: {setting:…}이(가) 가리키는 파라미터가 없습니다(%1)</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="393"/>
        <source>%1: cannot open: %2</source>
        <translation>%1: 열 수 없습니다: %2</translation>
    </message>
</context>
<context>
    <name>opentop::ProfileTranslation</name>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="79"/>
        <source>%1 is larger than %2 MB, the most a profile translation may hold</source>
        <translation>%1이(가) 프로파일 번역의 최대 크기인 %2 MB보다 큽니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="97"/>
        <source>larger than %1 MB, the most a profile translation may hold</source>
        <translation>프로파일 번역의 최대 크기인 %1 MB보다 큽니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="102"/>
        <source>not valid JSON at offset %1: %2</source>
        <translation>오프셋 %1에서 올바른 JSON이 아닙니다: %2</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="106"/>
        <source>the top level must be a JSON object</source>
        <translation>최상위는 JSON 객체여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="109"/>
        <source>&quot;format&quot; must be &quot;%1&quot;</source>
        <translation>&quot;format&quot;은(는) &quot;%1&quot;이어야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="112"/>
        <source>&quot;formatVersion&quot; must be %1</source>
        <translation>&quot;formatVersion&quot;은(는) %1이어야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="118"/>
        <source>&quot;family&quot; is &quot;%1&quot;, but the profile is &quot;%2&quot;</source>
        <translation>&quot;family&quot;가 &quot;%1&quot;이지만 프로파일은 &quot;%2&quot;입니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="120"/>
        <source>&quot;language&quot; is &quot;%1&quot;, expected &quot;%2&quot;</source>
        <translation>&quot;language&quot;가 &quot;%1&quot;이지만 &quot;%2&quot;여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="123"/>
        <source>&quot;texts&quot; must be an object of key → text</source>
        <translation>&quot;texts&quot;는 키 → 텍스트 객체여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="127"/>
        <source>texts &quot;%1&quot; must be a non-empty string</source>
        <translation>texts &quot;%1&quot;은(는) 비어 있지 않은 문자열이어야 합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="144"/>
        <source>%1 key(s) of the profile missing: %2</source>
        <translation>프로파일의 키 %1개가 없습니다: %2</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="148"/>
        <source>%1 key(s) the profile does not have: %2</source>
        <translation>프로파일에 없는 키 %1개: %2</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="156"/>
        <source>texts &quot;%1&quot;: the panel codes must stay as in the English (%2), found (%3)</source>
        <translation>texts &quot;%1&quot;: 패널 코드는 영어와 같아야 합니다(%2). 실제: (%3)</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="161"/>
        <source>texts &quot;%1&quot;: the placeholders must stay as in the English (%2), found (%3)</source>
        <translation>texts &quot;%1&quot;: 자리 표시자는 영어와 같아야 합니다(%2). 실제: (%3)</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="168"/>
        <source>texts &quot;%1&quot;: the settings named ({setting:…}) must stay as in the English (%2), found (%3)</source>
        <translation>texts &quot;%1&quot;: 가리키는 설정({setting:…})은 영어와 같아야 합니다(%2). 실제: (%3)</translation>
    </message>
</context>
<context>
    <name>opentop::ProposalFlow</name>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="57"/>
        <source>Proposal rejected; the drive&apos;s gains were not changed.</source>
        <translation>제안값을 거부했습니다. 드라이버의 게인은 바뀌지 않았습니다.</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="60"/>
        <source>Proposal rejected</source>
        <translation>제안값 거부됨</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="71"/>
        <source>The accepted gains failed the check: %1. Reject them, or store them only after looking at the step.</source>
        <translation>수락한 게인이 확인을 통과하지 못했습니다: %1. 거부하거나, 스텝을 확인한 뒤에만 저장하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="85"/>
        <source>no step test ran after Accept</source>
        <translation>수락 후 스텝 시험을 실행하지 않았습니다</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="87"/>
        <source>Store gains that failed the check?</source>
        <translation>확인을 통과하지 못한 게인을 저장하시겠습니까?</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="88"/>
        <source>The gains accepted on %1 did not pass the check after Accept.</source>
        <translation>%1에서 수락한 게인이 수락 후 확인을 통과하지 못했습니다.</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="90"/>
        <source>Stored, they stay after a power cycle and the motor may oscillate or overshoot as measured. Reject writes back the gains the drive had.</source>
        <translation>저장하면 전원을 다시 켜도 유지되며, 모터가 측정된 대로 진동하거나 오버슈트할 수 있습니다. 거부하면 드라이버의 이전 게인을 다시 씁니다.</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="95"/>
        <source>Reject the gains</source>
        <translation>게인 거부</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="96"/>
        <source>Store anyway</source>
        <translation>그래도 저장</translation>
    </message>
</context>
<context>
    <name>opentop::PtySimServer</name>
    <message>
        <location filename="../sim/PtySimServer.cpp" line="66"/>
        <source>cannot open a pseudo-terminal: %1</source>
        <translation>가상 터미널을 열 수 없습니다: %1</translation>
    </message>
    <message>
        <location filename="../sim/PtySimServer.cpp" line="112"/>
        <source>%1 is in use by another simulator (PID %2); stop it first, or choose another path for --pty</source>
        <translation>%1은(는) 다른 시뮬레이터(PID %2)가 사용 중입니다. 먼저 그것을 중지하거나 --pty에 다른 경로를 지정하십시오</translation>
    </message>
    <message>
        <location filename="../sim/PtySimServer.cpp" line="121"/>
        <source>cannot create the lock file %1: %2</source>
        <translation>잠금 파일 %1을(를) 만들 수 없습니다: %2</translation>
    </message>
    <message>
        <location filename="../sim/PtySimServer.cpp" line="80"/>
        <source>%1 exists and is not a symlink; refusing to replace it</source>
        <translation>%1이(가) 이미 있고 심볼릭 링크가 아닙니다. 교체하지 않습니다</translation>
    </message>
    <message>
        <location filename="../sim/PtySimServer.cpp" line="83"/>
        <source>cannot create the symlink %1 -&gt; %2</source>
        <translation>심볼릭 링크 %1 -&gt; %2을(를) 만들 수 없습니다</translation>
    </message>
    <message>
        <location filename="../sim/PtySimServer.cpp" line="162"/>
        <source>the port is plugged in: %1</source>
        <translation>포트가 연결되었습니다: %1</translation>
    </message>
    <message>
        <location filename="../sim/PtySimServer_win.cpp" line="29"/>
        <source>a simulated serial line needs a pseudo-terminal, which Windows does not have: serve Modbus TCP with --tcp PORT (e.g. --tcp 5020) and connect with --tcp 127.0.0.1:5020</source>
        <translation>시뮬레이션 직렬 회선에는 가상 터미널이 필요하지만 Windows에는 없습니다: --tcp PORT(예: --tcp 5020)로 Modbus TCP를 제공하고 --tcp 127.0.0.1:5020으로 연결하십시오</translation>
    </message>
</context>
<context>
    <name>opentop::ReachedDrives</name>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="47"/>
        <source>%1, variant not known</source>
        <translation>%1, 기종 모름</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="62"/>
        <source>machine number %1 (%2) executes this write too (communication group %3), but has no such setting at 0x%4</source>
        <translation>국번 %1(%2)도 이 쓰기를 실행하지만(통신 그룹 %3), 0x%4에 해당 설정이 없습니다</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="86"/>
        <source>machine number %1 (%2) executes this write too (communication group %3) and does not allow it: %4</source>
        <translation>국번 %1(%2)도 이 쓰기를 실행하는데(통신 그룹 %3) 이 값을 허용하지 않습니다: %4</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="95"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="110"/>
        <source>%1 cannot be checked: %2</source>
        <translation>%1을(를) 확인할 수 없습니다: %2</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="150"/>
        <source>verification failed in communication group %1: %2</source>
        <translation>통신 그룹 %1에서 확인 실패: %2</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="209"/>
        <source>reading %1 of machine number %2, which executes this write too, failed: %3</source>
        <translation>이 쓰기를 함께 실행하는 국번 %2의 %1 읽기 실패: %3</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="245"/>
        <source>machine number %1: not verified (the setting cannot be read there)</source>
        <translation>국번 %1: 확인 안 됨(그 드라이버에서는 설정을 읽을 수 없음)</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="258"/>
        <source>machine number %1: not verified, reading it back failed: %2</source>
        <translation>국번 %1: 확인 안 됨, 다시 읽기 실패: %2</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="260"/>
        <source>the drive was removed</source>
        <translation>드라이버가 제거되었습니다</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="273"/>
        <source>machine number %1 holds %2</source>
        <translation>국번 %1의 값은 %2</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="274"/>
        <source>machine number %1 holds %2, not %3</source>
        <translation>국번 %1의 값은 %3이(가) 아니라 %2</translation>
    </message>
</context>
<context>
    <name>opentop::Recipe</name>
    <message>
        <location filename="../model/eol/Recipe.cpp" line="64"/>
        <source>position %1 (machine number %2)</source>
        <translation>위치 %1 (국번 %2)</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeApprovals</name>
    <message>
        <location filename="../model/access/RecipeApprovals.cpp" line="19"/>
        <source>recipe &quot;%1&quot; rev. %2 is a draft: this version (its checksum) is not approved, so it does not run. An engineer approves it (Approve… in the recipe editor, or opentop-cli eol recipe approve FILE --user NAME).</source>
        <translation>레시피 &quot;%1&quot; rev. %2는 초안입니다: 이 버전(체크섬)은 승인되지 않아 실행되지 않습니다. 엔지니어가 승인합니다(레시피 편집기의 승인… 또는 opentop-cli eol recipe approve FILE --user NAME).</translation>
    </message>
    <message>
        <location filename="../model/access/RecipeApprovals.cpp" line="56"/>
        <source>a recipe without a checksum cannot be approved: sign it first</source>
        <translation>체크섬이 없는 레시피는 승인할 수 없습니다: 먼저 서명하십시오</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeApproveButton</name>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="16"/>
        <source>Approve…</source>
        <translation>승인…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="21"/>
        <source>Approve the saved recipe for the line (an engineer): stations with users run only approved recipes</source>
        <translation>저장된 레시피를 라인용으로 승인(엔지니어): 사용자가 있는 스테이션은 승인된 레시피만 실행합니다</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="35"/>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="43"/>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="65"/>
        <source>Approve recipe</source>
        <translation>레시피 승인</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="37"/>
        <source>Save the recipe first: what is approved is the saved file&apos;s checksum.</source>
        <translation>먼저 레시피를 저장하십시오: 승인되는 것은 저장된 파일의 체크섬입니다.</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="39"/>
        <source>%1 cannot be approved: %2</source>
        <translation>%1을(를) 승인할 수 없습니다: %2</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="44"/>
        <source>This station has no users: an approval names its approver. Set up users with opentop-cli eol user add.</source>
        <translation>이 스테이션에는 사용자가 없습니다: 승인에는 승인자가 기록됩니다. opentop-cli eol user add로 사용자를 설정하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="50"/>
        <source>approve %1 rev. %2</source>
        <translation>%1 rev. %2 승인</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="66"/>
        <source>%1 rev. %2 is approved by %3: stations run it.</source>
        <translation>%1 rev. %2을(를) %3이(가) 승인했습니다: 스테이션에서 실행됩니다.</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeBuilder</name>
    <message>
        <location filename="../model/eol/RecipeBuilder.cpp" line="208"/>
        <source>%1: unknown family &quot;%2&quot;</source>
        <translation>%1: 알 수 없는 제품군 &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeBuilder.cpp" line="228"/>
        <source>%1: %2 holds a value the profile does not allow: %3</source>
        <translation>%1: %2에 프로파일이 허용하지 않는 값이 있습니다: %3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeBuilder.cpp" line="261"/>
        <source>no drive to make a recipe of</source>
        <translation>레시피를 만들 드라이버가 없습니다</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeChecker</name>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="62"/>
        <source> (for %1)</source>
        <translation> (%1용)</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="94"/>
        <source>the recipe names no product</source>
        <translation>레시피에 제품 이름이 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="96"/>
        <source>the recipe has no revision</source>
        <translation>레시피에 개정이 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="98"/>
        <source>the recipe names no drive</source>
        <translation>레시피에 드라이버가 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="111"/>
        <source>%1: machine number %2 is already position %3; every drive of a unit needs its own machine number</source>
        <translation>%1: 국번 %2은(는) 이미 위치 %3입니다. 제품의 각 드라이버에는 서로 다른 국번이 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="133"/>
        <source>%1: unknown family &quot;%2&quot;; known: %3</source>
        <translation>%1: 알 수 없는 제품군 &quot;%2&quot;; 알려진 제품군: %3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="139"/>
        <source>%1: a %2 takes machine numbers %3–%4</source>
        <translation>%1: %2의 국번은 %3–%4입니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="152"/>
        <source>%1: the %2 has no variant &quot;%3&quot;; known: %4</source>
        <translation>%1: %2에 기종 &quot;%3&quot;이(가) 없습니다. 알려진 기종: %4</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="154"/>
        <source>none</source>
        <translation>없음</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="156"/>
        <source>%1: variant &quot;%2&quot; is named twice</source>
        <translation>%1: 기종 &quot;%2&quot;이(가) 두 번 지정되었습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="164"/>
        <source>%1: variantProof &quot;%2&quot; is not known; use &quot;required&quot; or &quot;operator&quot; (or leave it out)</source>
        <translation>%1: variantProof &quot;%2&quot;은(는) 알 수 없습니다. &quot;required&quot; 또는 &quot;operator&quot;를 쓰십시오 (또는 생략)</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="169"/>
        <source>%1: variantProof &quot;operator&quot; needs exactly one allowed variant for the operator to confirm</source>
        <translation>%1: variantProof &quot;operator&quot;에는 작업자가 확인할 허용 기종이 정확히 하나 있어야 합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="181"/>
        <source>%1: firmware version &quot;%2&quot; is not a version as the drive reports it (major.minor, e.g. &quot;1.5&quot;)</source>
        <translation>%1: 펌웨어 버전 &quot;%2&quot;이(가) 드라이버가 알려주는 버전 형식이 아닙니다(major.minor, 예: &quot;1.5&quot;)</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="194"/>
        <source>the %1 has no setting &quot;%2&quot;</source>
        <translation>%1에 설정 &quot;%2&quot;이(가) 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="196"/>
        <source>%1 is not a setting a recipe can write</source>
        <translation>%1은(는) 레시피로 쓸 수 있는 설정이 아닙니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="198"/>
        <source>%1 decides how the drive communicates; a recipe cannot change it, or the station would lose the drive in the middle of the run</source>
        <translation>%1은(는) 드라이버의 통신 방식을 정합니다. 레시피로 바꿀 수 없습니다. 바꾸면 검사 도중 스테이션이 드라이버와 통신할 수 없게 됩니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="218"/>
        <source>%1: setting %2</source>
        <translation>%1: 설정 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="223"/>
        <location filename="../model/eol/RecipeChecker.cpp" line="288"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="229"/>
        <source>%1 is given twice</source>
        <translation>%1이(가) 두 번 지정되었습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="237"/>
        <source>%1: what it allows depends on %2, which the recipe does not set; add %2 to the settings</source>
        <translation>%1: 허용 범위가 %2에 따라 달라지는데 레시피가 이를 설정하지 않습니다. 설정에 %2을(를) 추가하십시오</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="246"/>
        <source>%1 decides what %2 allows; set %2 in the recipe too, or the drive may be left with a value that is no longer valid</source>
        <translation>%1은(는) %2의 허용 범위를 정합니다. 레시피에서 %2도 설정하십시오. 그렇지 않으면 드라이버에 더 이상 유효하지 않은 값이 남을 수 있습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="262"/>
        <location filename="../model/eol/RecipeChecker.cpp" line="330"/>
        <source>%1: unit &quot;%2&quot;, but the drive&apos;s value is in &quot;%3&quot;</source>
        <translation>%1: 단위가 &quot;%2&quot;이지만 드라이버 값의 단위는 &quot;%3&quot;입니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="283"/>
        <location filename="../model/eol/RecipeChecker.cpp" line="385"/>
        <source>%1: per-unit value %2</source>
        <translation>%1: 제품별 값 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="294"/>
        <source>%1 is given twice (as a setting or as a per-unit value)</source>
        <translation>%1이(가) 두 번 지정되었습니다(설정 또는 제품별 값으로)</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="300"/>
        <source>%1: the range&apos;s lowest value %2 is above its highest value %3</source>
        <translation>%1: 범위의 최솟값 %2이(가) 최댓값 %3보다 큽니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="321"/>
        <source>%1: what it allows depends on %2, which the recipe does not set</source>
        <translation>%1: 허용 범위가 레시피에서 설정하지 않는 %2에 따라 달라집니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="328"/>
        <source>%1 is not a number; a per-unit value needs a numeric setting</source>
        <translation>%1은(는) 숫자가 아닙니다. 제품별 값에는 숫자 설정이 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="334"/>
        <source>%1: range %2–%3%4</source>
        <translation>%1: 범위 %2–%3%4</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="340"/>
        <source>%1 is outside what the drive allows: %2%3</source>
        <translation>%1이(가) 드라이버 허용 범위를 벗어납니다: %2%3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="352"/>
        <source>%1 includes values the drive does not allow; allowed: %2%3</source>
        <translation>%1에 드라이버가 허용하지 않는 값이 포함되어 있습니다. 허용: %2%3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="378"/>
        <source>%1: per-unit value %2: %3%4 is outside the recipe&apos;s range %5–%6%4</source>
        <translation>%1: 제품별 값 %2: %3%4이(가) 레시피 범위 %5–%6%4을(를) 벗어납니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="389"/>
        <source>%1: the recipe has no per-unit value %2</source>
        <translation>%1: 레시피에 제품별 값 %2이(가) 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="392"/>
        <source>the recipe has no drive at machine number %1</source>
        <translation>레시피에 국번 %1의 드라이버가 없습니다</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeEditor</name>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="40"/>
        <source>Recipe editor</source>
        <translation>레시피 편집기</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="61"/>
        <source>Revision:</source>
        <translation>개정:</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="63"/>
        <source>Product:</source>
        <translation>제품:</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="64"/>
        <source>Description:</source>
        <translation>설명:</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="65"/>
        <source>Position:</source>
        <translation>위치:</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="108"/>
        <source>New from drives on the bus…</source>
        <translation>버스의 드라이버로 새로 만들기…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="109"/>
        <source>New from backup file…</source>
        <translation>백업 파일로 새로 만들기…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="110"/>
        <source>Open…</source>
        <translation>열기…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="111"/>
        <source>Save</source>
        <translation>저장</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="112"/>
        <source>Save as…</source>
        <translation>다른 이름으로 저장…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="160"/>
        <source>%1: %2%3</source>
        <translation>%1: %2%3</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="163"/>
        <source> — %1</source>
        <translation> — %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="234"/>
        <source>Make a recipe from a golden unit&apos;s drives on the bus or its backup file, or open one.</source>
        <translation>버스에 있는 기준 제품의 드라이버나 그 백업 파일로 레시피를 만들거나, 레시피를 여십시오.</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="238"/>
        <source>the recipe is empty</source>
        <translation>레시피가 비어 있습니다</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="249"/>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="253"/>
        <source>The recipe passes check: it can be saved and run.</source>
        <translation>레시피가 검사를 통과했습니다: 저장하고 실행할 수 있습니다.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/eol/RecipeEditor.cpp" line="256"/>
        <source>%n problem(s): the recipe cannot be saved until they are fixed.</source>
        <translation>
            <numerusform>문제 %n건: 수정할 때까지 레시피를 저장할 수 없습니다.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/eol/RecipeEditor.cpp" line="268"/>
        <source>the recipe does not pass check (%n problem(s)); nothing was saved</source>
        <translation>
            <numerusform>레시피가 검사를 통과하지 못했습니다(문제 %n건). 아무것도 저장하지 않았습니다</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="284"/>
        <source>cannot read %1: %2</source>
        <translation>%1을(를) 읽을 수 없습니다: %2</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="296"/>
        <source>%1 is not an OpenTOP recipe file</source>
        <translation>%1은(는) OpenTOP 레시피 파일이 아닙니다</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="303"/>
        <source>Opened %1</source>
        <translation>%1 열림</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="304"/>
        <source>Opened %1, which does not load as it is (%2). Saving checks it and signs it again.</source>
        <translation>%1을(를) 열었지만 그대로는 불러올 수 없습니다(%2). 저장하면 검사 후 다시 서명합니다.</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="325"/>
        <source>Open recipe</source>
        <translation>레시피 열기</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="326"/>
        <source>Recipes (*.json);;All files (*)</source>
        <translation>레시피 (*.json);;모든 파일 (*)</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="336"/>
        <source>Save recipe</source>
        <translation>레시피 저장</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="338"/>
        <source>Recipes (*.json)</source>
        <translation>레시피 (*.json)</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="343"/>
        <source>Saved and signed: %1</source>
        <translation>저장 및 서명 완료: %1</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeFile</name>
    <message>
        <location filename="../model/eol/RecipeFile.cpp" line="268"/>
        <source>%1 is larger than %2 MB, the most a recipe file may hold; not a recipe file</source>
        <translation>%1이(가) 레시피 파일의 최대 크기 %2 MB보다 큽니다. 레시피 파일이 아닙니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeFile.cpp" line="276"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeFromDrives</name>
    <message>
        <location filename="../model/eol/RecipeFromDrives.cpp" line="66"/>
        <source>machine number %1: %2; give its variant if you know it</source>
        <translation>국번 %1: %2; 기종을 알면 지정하십시오</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeFromDrives.cpp" line="74"/>
        <source>machine number %1: %2, %3 (%4)</source>
        <translation>국번 %1: %2, %3 (%4)</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeFromDrives.cpp" line="113"/>
        <source>Made from a golden unit; variants: %1.</source>
        <translation>기준 제품으로 만듦. 기종: %1.</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeLimitsTable</name>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="33"/>
        <source>Parameter</source>
        <translation>파라미터</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="33"/>
        <source>Statistic</source>
        <translation>통계</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="33"/>
        <source>Lower</source>
        <translation>하한</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="33"/>
        <source>Upper</source>
        <translation>상한</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="33"/>
        <source>Unit</source>
        <translation>단위</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="54"/>
        <source>Add limit</source>
        <translation>한계값 추가</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="55"/>
        <source>Remove limit</source>
        <translation>한계값 삭제</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="64"/>
        <source>Limits (measured over the hold):</source>
        <translation>한계값(유지 중 측정):</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="78"/>
        <source>(unknown: %1)</source>
        <translation>(알 수 없음: %1)</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeParser</name>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="48"/>
        <source>not a JSON file: %1 at byte %2</source>
        <translation>JSON 파일이 아닙니다: 바이트 %2에서 %1</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="52"/>
        <source>not an OpenTOP recipe file: the JSON is not an object</source>
        <translation>OpenTOP 레시피 파일이 아닙니다: JSON이 객체가 아닙니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="78"/>
        <source>&quot;positions&quot;: the recipe names no drive</source>
        <translation>&quot;positions&quot;: 레시피에 드라이버가 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="83"/>
        <source>%1: must be an object</source>
        <translation>%1: 객체여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="100"/>
        <source>not an OpenTOP recipe file (&quot;format&quot; is &quot;%1&quot;, not &quot;%2&quot;)</source>
        <translation>OpenTOP 레시피 파일이 아닙니다(&quot;format&quot;이 &quot;%2&quot;이(가) 아니라 &quot;%1&quot;입니다)</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="102"/>
        <source>not an OpenTOP recipe file (no &quot;format&quot;: &quot;%1&quot;)</source>
        <translation>OpenTOP 레시피 파일이 아닙니다(&quot;format&quot;: &quot;%1&quot; 없음)</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="107"/>
        <source>&quot;formatVersion&quot; must be a whole number from 1</source>
        <translation>&quot;formatVersion&quot;은 1 이상의 정수여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="109"/>
        <source>written by a newer OpenTOP (recipe format version %1); this version reads recipe format version %2</source>
        <translation>더 새로운 OpenTOP에서 저장한 파일입니다(레시피 형식 버전 %1). 이 버전은 레시피 형식 버전 %2을(를) 읽습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="115"/>
        <source>the recipe has no checksum (&quot;checksum&quot;: &quot;sha256:…&quot;); it was not written by OpenTOP or was changed afterwards</source>
        <translation>레시피에 체크섬이 없습니다(&quot;checksum&quot;: &quot;sha256:…&quot;). OpenTOP에서 저장한 파일이 아니거나 저장 후 변경되었습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="121"/>
        <source>the recipe was changed after it was written (checksum mismatch); open and save it with OpenTOP to accept the change</source>
        <translation>레시피가 저장된 후 변경되었습니다(체크섬 불일치). 변경을 승인하려면 OpenTOP에서 열어 저장하십시오</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="138"/>
        <source>%1: &quot;machineNumber&quot; must be a machine number 1–247</source>
        <translation>%1: &quot;machineNumber&quot;는 국번 1–247이어야 합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="140"/>
        <location filename="../model/eol/RecipeParser.cpp" line="217"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="185"/>
        <source>%1 (%2): &quot;value&quot; must be a number or a text</source>
        <translation>%1 (%2): &quot;value&quot;는 숫자 또는 텍스트여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="201"/>
        <source>%1 (%2): &quot;source&quot; must be &quot;csv&quot; or &quot;operator&quot;, not &quot;%3&quot;</source>
        <translation>%1 (%2): &quot;source&quot;는 &quot;%3&quot;이(가) 아니라 &quot;csv&quot; 또는 &quot;operator&quot;여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="214"/>
        <source>%1: unknown step type &quot;%2&quot;; known: %3</source>
        <translation>%1: 알 수 없는 단계 유형 &quot;%2&quot;; 알려진 유형: %3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="230"/>
        <source>%1: &quot;spno&quot; must be a running data number such as 2</source>
        <translation>%1: &quot;spno&quot;는 2와 같은 운전 데이터 번호여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="241"/>
        <source>%1: &quot;direction&quot; must be &quot;cw&quot; or &quot;ccw&quot;</source>
        <translation>%1: &quot;direction&quot;은 &quot;cw&quot; 또는 &quot;ccw&quot;여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="279"/>
        <source>%1: give either &quot;equals&quot; or limits, not both</source>
        <translation>%1: &quot;equals&quot;와 한계값 중 하나만 주십시오</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="285"/>
        <source>%1: unknown step</source>
        <translation>%1: 알 수 없는 단계</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="301"/>
        <source>%1: &quot;unit&quot; must be a text (&quot;&quot; for a value without a unit)</source>
        <translation>%1: &quot;unit&quot;은 텍스트여야 합니다(단위가 없는 값은 &quot;&quot;)</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="304"/>
        <source>%1: a limit needs &quot;lower&quot;, &quot;upper&quot; or both</source>
        <translation>%1: 한계값에는 &quot;lower&quot;, &quot;upper&quot; 또는 둘 다 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="325"/>
        <source>&quot;retest&quot; must be an object</source>
        <translation>&quot;retest&quot;는 객체여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="334"/>
        <source>retest: &quot;maxAttempts&quot; must be a whole number from 0 (no limit) to 100</source>
        <translation>retest: &quot;maxAttempts&quot;는 0(제한 없음)부터 100까지의 정수여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="344"/>
        <source>retest: &quot;passedSerial&quot; must be technician, refuse or allow, not &quot;%1&quot;</source>
        <translation>retest: &quot;passedSerial&quot;은 &quot;%1&quot;이(가) 아니라 technician, refuse 또는 allow여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="356"/>
        <source>%1: unknown key &quot;%2&quot;; allowed: %3</source>
        <translation>%1: 알 수 없는 키 &quot;%2&quot;; 허용: %3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="370"/>
        <source>%1&quot;%2&quot; must be a non-empty text</source>
        <translation>%1&quot;%2&quot;은(는) 비어 있지 않은 텍스트여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="371"/>
        <source>%1&quot;%2&quot; must be a text</source>
        <translation>%1&quot;%2&quot;은(는) 텍스트여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="383"/>
        <source>%1: &quot;%2&quot; must be a list of texts</source>
        <translation>%1: &quot;%2&quot;은(는) 텍스트 목록이어야 합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="386"/>
        <source>%1: &quot;%2&quot; must be a list of non-empty texts</source>
        <translation>%1: &quot;%2&quot;은(는) 비어 있지 않은 텍스트의 목록이어야 합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="396"/>
        <source>%1: &quot;%2&quot; must be a number</source>
        <translation>%1: &quot;%2&quot;은(는) 숫자여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="422"/>
        <source>%1&quot;%2&quot; must be a list</source>
        <translation>%1&quot;%2&quot;은(는) 목록이어야 합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="425"/>
        <source>%1&quot;%2&quot; has %3 entries; at most %4 are allowed</source>
        <translation>%1&quot;%2&quot;에 항목이 %3개 있습니다. 최대 %4개까지 허용됩니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="431"/>
        <source>%1&quot;%2&quot;: every entry must be an object</source>
        <translation>%1&quot;%2&quot;: 모든 항목은 객체여야 합니다</translation>
    </message>
</context>
<context>
    <name>opentop::RecipePositionForm</name>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="125"/>
        <source>every variant of the family, e.g. dbu200, dbu400</source>
        <translation>제품군의 모든 기종, 예: dbu200, dbu400</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="127"/>
        <source>any firmware, e.g. 1.5, 1.6</source>
        <translation>모든 펌웨어, 예: 1.5, 1.6</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="129"/>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="131"/>
        <source>Setting</source>
        <translation>설정</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="129"/>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="131"/>
        <source>Name</source>
        <translation>이름</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="129"/>
        <source>Value</source>
        <translation>값</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="129"/>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="131"/>
        <source>Unit</source>
        <translation>단위</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="131"/>
        <source>Min</source>
        <translation>최소</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="131"/>
        <source>Max</source>
        <translation>최대</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="131"/>
        <source>Source</source>
        <translation>출처</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="137"/>
        <source>Add per-unit value…</source>
        <translation>제품별 값 추가…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="137"/>
        <source>Add setting…</source>
        <translation>설정 추가…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="138"/>
        <source>Remove</source>
        <translation>제거</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="151"/>
        <source>Settings</source>
        <translation>설정</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="152"/>
        <source>Per-unit values</source>
        <translation>제품별 값</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="153"/>
        <source>Test steps</source>
        <translation>테스트 단계</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="156"/>
        <source>Machine number:</source>
        <translation>국번:</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="157"/>
        <source>Name:</source>
        <translation>이름:</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="158"/>
        <source>Family:</source>
        <translation>제품군:</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="159"/>
        <source>Allowed variants:</source>
        <translation>허용 기종:</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="160"/>
        <source>Allowed firmware:</source>
        <translation>허용 펌웨어:</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="186"/>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="337"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="228"/>
        <source>CSV file</source>
        <translation>CSV 파일</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="229"/>
        <source>typed by the operator</source>
        <translation>작업자 입력</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="279"/>
        <source>(unknown: %1)</source>
        <translation>(알 수 없음: %1)</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="342"/>
        <source>Add a per-unit value</source>
        <translation>제품별 값 추가</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="342"/>
        <source>Add a setting</source>
        <translation>설정 추가</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="343"/>
        <source>Setting:</source>
        <translation>설정:</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeStepChecker</name>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="22"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="40"/>
        <source>a %1 cannot do this step</source>
        <translation>%1에서는 이 단계를 할 수 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="53"/>
        <source>%1, step %2 (%3)</source>
        <translation>%1, 단계 %2 (%3)</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="63"/>
        <source>the drive takes motion commands only with communication priority; put a priority step before it</source>
        <translation>드라이버는 통신 우선일 때만 운전 명령을 받습니다. 앞에 우선순위 단계를 넣으십시오</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="71"/>
        <source>the motor is not running here; put a start step before it</source>
        <translation>여기서는 모터가 운전 중이 아닙니다. 앞에 기동 단계를 넣으십시오</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="82"/>
        <source>%1: the steps leave the motor running; end them with a stop step</source>
        <translation>%1: 단계가 끝나도 모터가 운전 중입니다. 마지막에 정지 단계를 넣으십시오</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="92"/>
        <source>%1 %2 s is not sane; give more than 0 s and at most %3 s</source>
        <translation>%1 %2 s은(는) 비정상적인 값입니다. 0 s보다 크고 %3 s 이하로 주십시오</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="105"/>
        <source>unit &quot;%1&quot;, but %2 is measured in &quot;%3&quot;</source>
        <translation>단위가 &quot;%1&quot;이지만 %2은(는) &quot;%3&quot;(으)로 측정됩니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="129"/>
        <source>the profile&apos;s selection parameter is missing</source>
        <translation>프로파일의 선택 파라미터가 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="131"/>
        <source>running data %1: %2</source>
        <translation>운전 데이터 %1: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="146"/>
        <source>what %1 means depends on %2, which the recipe does not set; add it to the settings</source>
        <translation>%1의 의미가 %2에 따라 달라지는데 레시피가 이를 설정하지 않습니다. 설정에 추가하십시오</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="154"/>
        <source>a speed of 0 stops the motor; use a stop step</source>
        <translation>속도 0은 모터를 정지시킵니다. 정지 단계를 사용하십시오</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="168"/>
        <source>unit &quot;%1&quot;, but with these settings %2 is in &quot;%3&quot;</source>
        <translation>단위가 &quot;%1&quot;이지만 이 설정에서는 %2의 단위가 &quot;%3&quot;입니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="185"/>
        <source>a %1 does not report its target speed; give the target</source>
        <translation>%1은(는) 목표 속도를 알려주지 않습니다. 목표값을 주십시오</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="187"/>
        <source>the target speed must be above 0</source>
        <translation>목표 속도는 0보다 커야 합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="190"/>
        <source>the tolerance %1 must be above 0 and below the target speed</source>
        <translation>허용 오차 %1은(는) 0보다 크고 목표 속도보다 작아야 합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="194"/>
        <source>the time to reach the speed</source>
        <translation>속도 도달 시간</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="198"/>
        <source>the hold time</source>
        <translation>유지 시간</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="200"/>
        <source>the step measures nothing; give limits</source>
        <translation>이 단계는 아무것도 측정하지 않습니다. 한계값을 주십시오</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="208"/>
        <source>the margin</source>
        <translation>여유 시간</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="211"/>
        <source>a %1 has no deceleration time setting to wait for; give the deceleration (0 s when it brakes at once)</source>
        <translation>%1에는 기다릴 감속 시간 설정이 없습니다. 감속 시간을 주십시오(즉시 브레이크가 걸리면 0 s)</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="217"/>
        <source>the deceleration time %1 s is not sane; give 0–%2 s</source>
        <translation>감속 시간 %1 s은(는) 비정상적인 값입니다. 0–%2 s로 주십시오</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="232"/>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="274"/>
        <source>the %1 has no readable value &quot;%2&quot;</source>
        <translation>%1에 읽을 수 있는 값 &quot;%2&quot;이(가) 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="237"/>
        <source>%1 is not a number</source>
        <translation>%1은(는) 숫자가 아닙니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="247"/>
        <source>%1: &quot;%2&quot; is not a statistic; use min, mean or max</source>
        <translation>%1: &quot;%2&quot;은(는) 통계값이 아닙니다. min, mean 또는 max를 사용하십시오</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="254"/>
        <source>%1: the limit&apos;s unit is &quot;%2&quot;, but the value is measured in &quot;%3&quot;</source>
        <translation>%1: 한계값의 단위는 &quot;%2&quot;이지만 값은 &quot;%3&quot;(으)로 측정됩니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="261"/>
        <source>%1: the lower limit %2 %4 is above the upper limit %3 %4</source>
        <translation>%1: 하한값 %2 %4이(가) 상한값 %3 %4보다 큽니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="283"/>
        <source>%1 is a number; compare it with lower and upper limits</source>
        <translation>%1은(는) 숫자입니다. 하한값·상한값과 비교하십시오</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeStepKinds</name>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="29"/>
        <source>take communication priority</source>
        <translation>통신 우선으로 전환</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="32"/>
        <source>select running data</source>
        <translation>운전 데이터 선택</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="33"/>
        <source>Running data:</source>
        <translation>운전 데이터:</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="36"/>
        <source>set the speed command</source>
        <translation>속도 명령 설정</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="37"/>
        <source>Speed command:</source>
        <translation>속도 명령:</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="38"/>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="50"/>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="70"/>
        <source>Unit:</source>
        <translation>단위:</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="39"/>
        <source>the speed command&apos;s unit</source>
        <translation>속도 지령의 단위</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="42"/>
        <source>start</source>
        <translation>기동</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="43"/>
        <source>Direction:</source>
        <translation>회전 방향:</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="46"/>
        <source>wait for speed</source>
        <translation>속도 대기</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="47"/>
        <source>Target speed:</source>
        <translation>목표 속도:</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="48"/>
        <source>empty: the drive&apos;s own target speed</source>
        <translation>비워 두면: 드라이버 자체의 목표 속도</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="49"/>
        <source>Tolerance (±):</source>
        <translation>허용 오차(±):</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="50"/>
        <source>the speed&apos;s unit</source>
        <translation>속도의 단위</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="51"/>
        <source>Within:</source>
        <translation>제한 시간:</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="54"/>
        <source>hold and measure</source>
        <translation>유지 및 측정</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="55"/>
        <source>Duration:</source>
        <translation>유지 시간:</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="59"/>
        <source>stop</source>
        <translation>정지</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="60"/>
        <source>Deceleration time:</source>
        <translation>감속 시간:</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="61"/>
        <source>empty: the drive&apos;s setting</source>
        <translation>비워 두면: 드라이버의 설정값</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="62"/>
        <source>Margin:</source>
        <translation>여유 시간:</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="63"/>
        <source>check for alarms and warnings</source>
        <translation>알람·경고 확인</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="66"/>
        <source>read and compare</source>
        <translation>읽기 및 비교</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="67"/>
        <source>Parameter:</source>
        <translation>파라미터:</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="68"/>
        <source>Lower limit:</source>
        <translation>하한:</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="68"/>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="69"/>
        <source>empty: none</source>
        <translation>비워 두면: 없음</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="69"/>
        <source>Upper limit:</source>
        <translation>상한:</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="70"/>
        <source>the value&apos;s unit</source>
        <translation>값의 단위</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="71"/>
        <source>Or equals:</source>
        <translation>또는 일치:</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="72"/>
        <source>the expected text, instead of limits</source>
        <translation>한계값 대신 기대하는 텍스트</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="123"/>
        <source>SPno%1</source>
        <translation>SPno%1</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="125"/>
        <source>to %1</source>
        <translation>%1(으)로</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="129"/>
        <source>%1 ± %2 within %3 s</source>
        <translation>%3 s 이내에 %1 ± %2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="131"/>
        <source>the drive&apos;s target speed</source>
        <translation>드라이버의 목표 속도</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="134"/>
        <source>for %1 s; limits: %2</source>
        <translation>%1 s 동안; 한계값: %2개</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="139"/>
        <source>stopped within %1 s + %2 s</source>
        <translation>%1 s + %2 s 이내 정지</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="140"/>
        <source>stopped within the deceleration time + %1 s</source>
        <translation>감속 시간 + %1 s 이내 정지</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="144"/>
        <source>no value chosen to read yet</source>
        <translation>읽을 값이 아직 선택되지 않았습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="148"/>
        <source>%1 is &quot;%2&quot;</source>
        <translation>%1 = &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="149"/>
        <source>%1 between %2 and %3</source>
        <translation>%1: %2~%3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="150"/>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="151"/>
        <source>any</source>
        <translation>모두</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="163"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeStepsEditor</name>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="48"/>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="48"/>
        <source>Step</source>
        <translation>단계</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="48"/>
        <source>What it does</source>
        <translation>동작</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="56"/>
        <source>Add step</source>
        <translation>단계 추가</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="61"/>
        <source>Remove</source>
        <translation>삭제</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="62"/>
        <source>Move up</source>
        <translation>위로</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="63"/>
        <source>Move down</source>
        <translation>아래로</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="93"/>
        <source>(unknown step: %1)</source>
        <translation>(알 수 없는 단계: %1)</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="216"/>
        <source>No step selected</source>
        <translation>선택된 단계 없음</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="217"/>
        <source>Add a step, or select one to edit it.</source>
        <translation>단계를 추가하거나 편집할 단계를 선택하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="223"/>
        <source>Step %1: %2</source>
        <translation>단계 %1: %2</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="254"/>
        <source>CW</source>
        <translation>CW</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="255"/>
        <source>CCW</source>
        <translation>CCW</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="247"/>
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="281"/>
        <source>This step has no settings.</source>
        <translation>이 단계에는 설정 항목이 없습니다.</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="323"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="325"/>
        <source>(unknown: %1)</source>
        <translation>(알 수 없음: %1)</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="335"/>
        <source>Parameter:</source>
        <translation>파라미터:</translation>
    </message>
</context>
<context>
    <name>opentop::Reconnection</name>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="31"/>
        <source>&amp;Reconnect</source>
        <translation>다시 연결(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="38"/>
        <source>Open the last connection again, with the same drives and page (Ctrl+R)</source>
        <translation>같은 드라이버와 페이지로 마지막 연결을 다시 엽니다 (Ctrl+R)</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="92"/>
        <source>Reconnecting to %1…</source>
        <translation>%1에 다시 연결하는 중…</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="123"/>
        <source>Reconnected to %1: reading every drive again…</source>
        <translation>%1에 다시 연결했습니다: 모든 드라이버를 다시 읽는 중…</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="176"/>
        <source>Reconnected to %1.</source>
        <translation>%1에 다시 연결했습니다.</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="200"/>
        <source>Reconnecting failed: %1</source>
        <translation>다시 연결 실패: %1</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="218"/>
        <location filename="../ui/main/Reconnection.cpp" line="262"/>
        <source>Connection lost</source>
        <translation>연결 끊김</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="226"/>
        <location filename="../ui/main/Reconnection.cpp" line="267"/>
        <source>Reconnect</source>
        <translation>다시 연결</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="268"/>
        <source>Go on anyway</source>
        <translation>그래도 계속</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="269"/>
        <source>Cancel</source>
        <translation>취소</translation>
    </message>
</context>
<context>
    <name>opentop::RelayAnalysis</name>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="47"/>
        <source>no steady oscillation: %1 full cycles around %2, %3 needed</source>
        <translation>안정된 진동 없음: %2 부근에서 완전한 주기 %1회, %3회 필요</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="51"/>
        <source>Raise the relay amplitude, or choose an operating speed that leaves the output room on both sides.</source>
        <translation>릴레이 진폭을 키우거나, 출력 위아래에 여유가 남는 운전 속도를 고르십시오.</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="86"/>
        <source>the oscillation (±%1) is no larger than the hysteresis (%2)</source>
        <translation>진동(±%1)이 히스테리시스(%2)보다 크지 않습니다</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="89"/>
        <source>Raise the relay amplitude.</source>
        <translation>릴레이 진폭을 키우십시오.</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="97"/>
        <source>the oscillation&apos;s period, %1 ms, holds only %2 readings (one every %3 ms): at least %4 are needed, or its period and amplitude are the bus&apos;s rather than the motor&apos;s</source>
        <translation>진동 주기 %1 ms 동안 읽기가 %2회뿐입니다(%3 ms마다): 최소 %4회가 필요하며, 그렇지 않으면 주기와 진폭은 모터가 아니라 버스의 것입니다</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="104"/>
        <source>Raise the line rate (115200 bit/s if every drive on the bus allows it) or stop polling other drives on this bus during the test; a larger relay amplitude or another speed does not change this.</source>
        <translation>통신 속도를 올리거나(버스의 모든 드라이버가 지원하면 115200 bit/s), 시험 중에는 이 버스의 다른 드라이버 폴링을 멈추십시오. 릴레이 진폭이나 속도를 바꿔도 달라지지 않습니다.</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="110"/>
        <source>the oscillation is not steady: periods differ by %1 %, amplitudes by %2 % (at most %3 % and %4 %)</source>
        <translation>진동이 안정되지 않았습니다: 주기 차이 %1 %, 진폭 차이 %2 % (한계 %3 %, %4 %)</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="116"/>
        <source>Raise the relay amplitude so that the oscillation stands out of friction and load changes, keep the load steady during the test, and stop polling other drives on this bus meanwhile.</source>
        <translation>진동이 마찰과 부하 변동에 묻히지 않도록 릴레이 진폭을 키우고, 시험 중에는 부하를 일정하게 유지하며, 그동안 이 버스의 다른 드라이버 폴링을 멈추십시오.</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="123"/>
        <source>the oscillation is lopsided: its time above and below %1 differ by %2 % of the period (at most %3 %)</source>
        <translation>진동이 한쪽으로 치우쳤습니다: %1 위와 아래에 있는 시간이 주기의 %2 % 차이 납니다(한계 %3 %)</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="128"/>
        <source>The output for the operating speed was misjudged or the load changed: keep the load steady, choose an operating speed further from standstill and from full output, and repeat the test.</source>
        <translation>운전 속도에 필요한 출력을 잘못 추정했거나 부하가 바뀌었습니다. 부하를 일정하게 유지하고, 정지와 최대 출력 양쪽에서 먼 운전 속도를 골라 시험을 다시 하십시오.</translation>
    </message>
</context>
<context>
    <name>opentop::RelayAutotune</name>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="65"/>
        <source>the operating speed must be above 0 and below the test&apos;s speed limit %1 %2</source>
        <translation>운전 속도는 0보다 크고 시험 속도 한계값 %1 %2보다 작아야 합니다</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="72"/>
        <source>the relay amplitude must be 0–50 % of full output</source>
        <translation>릴레이 진폭은 최대 출력의 0–50 %여야 합니다</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="75"/>
        <source>Open loop: finding the output for %1 %2</source>
        <translation>개루프: %1 %2에 필요한 출력을 찾는 중</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="148"/>
        <source>the motor did not turn at %1 % output</source>
        <translation>출력 %1 %에서 모터가 돌지 않았습니다</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="180"/>
        <source>the operating speed needs %1 % output: no room for ±%2 % around it</source>
        <translation>운전 속도에 출력 %1 %가 필요합니다: 그 위아래로 ±%2 %의 여유가 없습니다</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="185"/>
        <source>Relay test around %1 %2 (output %3 % ± %4 %)</source>
        <translation>%1 %2 부근에서 릴레이 시험 중 (출력 %3 % ± %4 %)</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="224"/>
        <source>no steady oscillation within %1 s: %2</source>
        <translation>%1 s 이내에 안정된 진동이 없습니다: %2</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="226"/>
        <source>try a larger amplitude</source>
        <translation>진폭을 크게 해 보십시오</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="259"/>
        <source>the relay result was refused: %1</source>
        <translation>릴레이 시험 결과를 쓸 수 없습니다: %1</translation>
    </message>
</context>
<context>
    <name>opentop::RelayTuning</name>
    <message>
        <location filename="../model/tuning/RelayTuning.cpp" line="28"/>
        <source>Raise the relay amplitude.</source>
        <translation>릴레이 진폭을 키우십시오.</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayTuning.cpp" line="49"/>
        <source>the drive&apos;s own loop, as the model extrapolates it, would oscillate with a period of %1 ms, under %2 readings (one every %3 ms): the step after Accept could not show whether the gains work</source>
        <translation>모델로 외삽한 드라이버 자체 루프는 주기 %1 ms로 진동하여 읽기 %2회(%3 ms마다)에 못 미칩니다: 수락 후 스텝으로 게인이 통하는지 보여 줄 수 없습니다</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayTuning.cpp" line="55"/>
        <source>Raise the line rate (115200 bit/s if every drive on the bus allows it) or stop polling other drives on this bus during the test.</source>
        <translation>통신 속도를 올리거나(버스의 모든 드라이버가 지원하면 115200 bit/s), 시험 중에는 이 버스의 다른 드라이버 폴링을 멈추십시오.</translation>
    </message>
</context>
<context>
    <name>opentop::RestoreChoice</name>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="28"/>
        <source>Drive in file / setting</source>
        <translation>파일의 드라이버 / 설정</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="28"/>
        <source>Value in file</source>
        <translation>파일의 값</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="28"/>
        <source>Restore to</source>
        <translation>복원 대상</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="55"/>
        <source>(do not restore)</source>
        <translation>(복원 안 함)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="59"/>
        <source>Drive %1 (%2)</source>
        <translation>드라이버 %1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="121"/>
        <source>Two drives of the file would be restored to drive %1.</source>
        <translation>파일의 드라이버 두 대가 드라이버 %1에 복원됩니다.</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="126"/>
        <source>Drive %1 is not on the bus (or not identified).</source>
        <translation>드라이버 %1이(가) 버스에 없습니다(또는 식별되지 않음).</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="138"/>
        <source>Nothing chosen: tick at least one setting of a drive with a target.</source>
        <translation>선택한 항목 없음: 대상이 있는 드라이버의 설정을 하나 이상 체크하십시오.</translation>
    </message>
</context>
<context>
    <name>opentop::RestoreCommand</name>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="37"/>
        <source>Show what a backup file would change on its drives; with --yes write it, verified</source>
        <translation>백업 파일이 드라이버에서 바꿀 내용을 표시합니다. --yes를 주면 쓰고 검증합니다</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="42"/>
        <source>Restore only these drives of the file, e.g. 1,5-7.</source>
        <translation>파일에서 이 드라이버만 복원합니다. 예: 1,5-7.</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="43"/>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="44"/>
        <source>Read the drives and show the plan; write nothing.</source>
        <translation>드라이버를 읽고 계획을 표시합니다. 아무것도 쓰지 않습니다.</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="45"/>
        <source>Write the plan (without it restore only shows it).</source>
        <translation>계획을 씁니다(없으면 restore는 계획만 표시).</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="55"/>
        <source>%1: the drive&apos;s settings were not read; nothing compared, nothing written</source>
        <translation>%1: 드라이버 설정을 읽지 못했습니다. 비교하지 않았고 아무것도 쓰지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="61"/>
        <location filename="../cli/RestoreCommand.cpp" line="99"/>
        <source>note: %1</source>
        <translation>참고: %1</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="66"/>
        <source>parameter</source>
        <translation>파라미터</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="66"/>
        <source>file value</source>
        <translation>파일 값</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="66"/>
        <source>device value</source>
        <translation>장치 값</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="67"/>
        <source>result</source>
        <translation>결과</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="67"/>
        <source>action</source>
        <translation>동작</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="81"/>
        <source>%1 written and verified, %2 unchanged, %3 failed, %4 not attempted</source>
        <translation>쓰기 및 검증 %1, 변경 없음 %2, 실패 %3, 시도 안 함 %4</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="87"/>
        <source>, %1 not confirmed</source>
        <translation>, 확인 안 됨 %1</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="89"/>
        <source>; %1 of %2 store commands written</source>
        <translation>; 저장 명령 %2개 중 %1개 씀</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="124"/>
        <source>error: name one backup file: restore FILE [--ids LIST] [--yes]</source>
        <translation>오류: 백업 파일 하나를 지정하십시오: restore FILE [--ids LIST] [--yes]</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="138"/>
        <source>error: --ids: %1</source>
        <translation>오류: --ids: %1</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="144"/>
        <source>error: %1 holds no drive with machine number %2; it holds %3</source>
        <translation>오류: %1에 국번 %2인 드라이버가 없습니다. 포함된 드라이버: %3</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="165"/>
        <source>error: %1; nothing written</source>
        <translation>오류: %1; 아무것도 쓰지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="184"/>
        <source>error: %1: %2</source>
        <translation>오류: %1: %2</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="205"/>
        <source>%1: not attempted</source>
        <translation>%1: 시도 안 함</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="234"/>
        <source>dry run: nothing written</source>
        <translation>시험 실행(dry run): 아무것도 쓰지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="235"/>
        <source>nothing written; add --yes to write</source>
        <translation>아무것도 쓰지 않았습니다. 쓰려면 --yes를 추가하십시오</translation>
    </message>
</context>
<context>
    <name>opentop::RestoreDialog</name>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="38"/>
        <source>&amp;Preview</source>
        <translation>미리 보기(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="39"/>
        <source>&amp;Write to drives…</source>
        <translation>드라이버에 쓰기(&amp;W)…</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="40"/>
        <source>&amp;Cancel</source>
        <translation>취소(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="41"/>
        <source>&amp;Save report…</source>
        <translation>보고서 저장(&amp;S)…</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="43"/>
        <source>Restore from a backup file</source>
        <translation>백업 파일에서 복원</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="45"/>
        <source>No file chosen</source>
        <translation>선택한 파일 없음</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="46"/>
        <source>&amp;Choose file…</source>
        <translation>파일 선택(&amp;C)…</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="48"/>
        <source>File:</source>
        <translation>파일:</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="60"/>
        <source>Read the drives and show what would change; writes nothing</source>
        <translation>드라이버를 읽고 바뀔 내용을 표시합니다. 아무것도 쓰지 않습니다</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="61"/>
        <source>Write the previewed changes, each verified by reading it back</source>
        <translation>미리 본 변경 사항을 쓰고, 각각 다시 읽어 검증합니다</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="62"/>
        <source>Stop after the write in progress has been verified</source>
        <translation>진행 중인 쓰기의 검증이 끝나면 멈춥니다</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="63"/>
        <source>Save the report as text, or as CSV when the name ends in .csv</source>
        <translation>보고서를 텍스트로 저장합니다. 이름이 .csv로 끝나면 CSV로 저장합니다</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="64"/>
        <source>C&amp;lose</source>
        <translation>닫기(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="113"/>
        <source>%1: no such file</source>
        <translation>%1: 파일이 없습니다</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="118"/>
        <source>the file could not be read</source>
        <translation>파일을 읽을 수 없습니다</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="119"/>
        <location filename="../ui/files/RestoreDialog.cpp" line="179"/>
        <source>Refused, nothing will be written: %1</source>
        <translation>거부됨, 아무것도 쓰지 않습니다: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/RestoreDialog.cpp" line="124"/>
        <source>%n drive(s) in the file. Choose what to restore, then Preview.</source>
        <translation>
            <numerusform>파일에 드라이버 %n대가 있습니다. 복원할 항목을 선택한 뒤 미리 보기를 누르십시오.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="146"/>
        <source>Refused, nothing written:</source>
        <translation>거부됨, 아무것도 쓰지 않았습니다:</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="148"/>
        <source>Drive %1 from %2: %3</source>
        <translation>드라이버 %1 (%2에서): %3</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="178"/>
        <source>Choose a backup file first.</source>
        <translation>먼저 백업 파일을 선택하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="194"/>
        <source>Nothing was read or written: %1.</source>
        <translation>아무것도 읽거나 쓰지 않았습니다: %1.</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="86"/>
        <source>Reading drive %1…</source>
        <translation>드라이버 %1 읽는 중…</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="86"/>
        <source>Writing drive %1…</source>
        <translation>드라이버 %1 쓰는 중…</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="94"/>
        <source>drive %1: %2 (%v of %m)</source>
        <translation>드라이버 %1: %2 (%m 중 %v)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="229"/>
        <source>Stopping after the write in progress has been verified…</source>
        <translation>진행 중인 쓰기의 검증이 끝나면 멈추는 중…</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="244"/>
        <location filename="../ui/files/RestoreDialog.cpp" line="325"/>
        <location filename="../ui/files/RestoreDialog.cpp" line="330"/>
        <source>Drive %1: %2</source>
        <translation>드라이버 %1: %2</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/RestoreDialog.cpp" line="247"/>
        <source>%n setting(s) to write</source>
        <translation>
            <numerusform>쓸 설정 %n개</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="254"/>
        <source>  Note: %1</source>
        <translation>  참고: %1</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="257"/>
        <source>Nothing written yet. Write to drives to apply.</source>
        <translation>아직 아무것도 쓰지 않았습니다. 적용하려면 드라이버에 쓰기를 누르십시오.</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="258"/>
        <source>Nothing written.</source>
        <translation>아무것도 쓰지 않았습니다.</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="306"/>
        <source>Restore from backup file</source>
        <translation>백업 파일에서 복원</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="307"/>
        <source>OpenTOP backups (*.json);;All files (*)</source>
        <translation>OpenTOP 백업 (*.json);;모든 파일 (*)</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/RestoreDialog.cpp" line="333"/>
        <source>Write %n setting(s) to drive(s) %1, each verified by reading it back?</source>
        <translation>
            <numerusform>설정 %n개를 드라이버 %1에 쓰고 각각 다시 읽어 검증하시겠습니까?</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="338"/>
        <source>Write to drives</source>
        <translation>드라이버에 쓰기</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="338"/>
        <source>&amp;Write</source>
        <translation>쓰기(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="343"/>
        <source>Save restore report</source>
        <translation>복원 보고서 저장</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="344"/>
        <source>Text (*.txt);;CSV (*.csv)</source>
        <translation>텍스트 (*.txt);;CSV (*.csv)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="349"/>
        <source>Could not save %1: %2</source>
        <translation>%1을(를) 저장할 수 없습니다: %2</translation>
    </message>
</context>
<context>
    <name>opentop::RestorePlan</name>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="71"/>
        <source>the file holds a %1 drive (%2), but machine number %3 is a %4 drive; nothing written</source>
        <translation>파일에는 %1 드라이버(%2)가 있지만 국번 %3은(는) %4 드라이버입니다. 아무것도 쓰지 않았습니다</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="78"/>
        <source>the file is from a %1 (%2), but machine number %3 is a %4 (%5); their allowed values differ, nothing written</source>
        <translation>파일은 %1(%2)의 것이지만 국번 %3은(는) %4(%5)입니다. 허용 값이 다르므로 아무것도 쓰지 않았습니다</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="85"/>
        <source>the drive does not tell its variant: every value must suit all variants (name it with --variant to use its own ranges)</source>
        <translation>드라이버가 기종을 알려주지 않습니다: 모든 값이 모든 기종에 맞아야 합니다(해당 기종의 범위를 쓰려면 --variant로 지정)</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="143"/>
        <source>%1: the value cannot be written exactly</source>
        <translation>%1: 값을 정확하게 쓸 수 없습니다</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/files/RestorePlan.cpp" line="163"/>
        <source>%n value(s) of the file may not be written to this drive; nothing written</source>
        <translation>
            <numerusform>파일의 값 %n개는 이 드라이버에 쓸 수 없습니다. 아무것도 쓰지 않았습니다</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="245"/>
        <source>%1 sent after the writes, so that the settings written survive power-off</source>
        <translation>쓰기 후 %1을(를) 보내 쓴 설정이 전원을 꺼도 유지되게 합니다</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="248"/>
        <source>%1 sent: settings written to this drive earlier (by an interrupted restore, a page or the command line) are not stored yet</source>
        <translation>%1 전송: 이전에 이 드라이버에 쓴 설정(중단된 복원, 페이지 또는 명령줄)이 아직 저장되지 않았습니다</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="252"/>
        <source>%1 not sent: nothing it stores is written. What a drive has stored cannot be read back: if it loses settings at power-off, switch it off and on and restore again</source>
        <translation>%1 미전송: 이 명령이 저장하는 설정은 쓰지 않았습니다. 드라이버에 저장된 내용은 다시 읽을 수 없습니다. 전원을 끄면 설정이 없어진다면 전원을 껐다 켠 뒤 다시 복원하십시오</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="286"/>
        <source>keep</source>
        <translation>유지</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="288"/>
        <source>write</source>
        <translation>쓰기</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="290"/>
        <source>store</source>
        <translation>저장</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="301"/>
        <source>unchanged</source>
        <translation>변경 없음</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="304"/>
        <source>written, not verified: %1</source>
        <translation>쓰기 완료, 확인 안 됨: %1</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="305"/>
        <source>written</source>
        <translation>쓰기 완료</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="305"/>
        <source>written and verified</source>
        <translation>쓰기 및 검증 완료</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="307"/>
        <source>failed: %1</source>
        <translation>실패: %1</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="309"/>
        <source>not attempted</source>
        <translation>시도 안 함</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="311"/>
        <source>not confirmed (%1): the drive may or may not hold it; run the restore again to read it back</source>
        <translation>확인 안 됨(%1): 드라이버에 값이 들어갔는지 알 수 없습니다. 복원을 다시 실행하여 다시 읽으십시오</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="336"/>
        <source>planned</source>
        <translation>계획됨</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="338"/>
        <source>restored</source>
        <translation>복원됨</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="340"/>
        <source>refused</source>
        <translation>거부됨</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="342"/>
        <source>communication failure</source>
        <translation>통신 실패</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="344"/>
        <source>verification mismatch</source>
        <translation>검증 불일치</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="346"/>
        <source>interrupted</source>
        <translation>중단됨</translation>
    </message>
</context>
<context>
    <name>opentop::RestorePlanTable</name>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="14"/>
        <source>Drive</source>
        <translation>드라이버</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="14"/>
        <source>Parameter</source>
        <translation>파라미터</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="14"/>
        <source>Action</source>
        <translation>동작</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="14"/>
        <source>File value</source>
        <translation>파일 값</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="15"/>
        <source>Drive value before</source>
        <translation>이전 드라이버 값</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="15"/>
        <source>Result</source>
        <translation>결과</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="93"/>
        <source>&amp;Differences only</source>
        <translation>차이만(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="95"/>
        <source>Show only the settings that would be written (or were), and what went wrong</source>
        <translation>쓸(또는 쓴) 설정과 실패한 항목만 표시</translation>
    </message>
</context>
<context>
    <name>opentop::RestoreReport</name>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="18"/>
        <source>%1 written and verified, %2 unchanged, %3 failed, %4 not attempted</source>
        <translation>쓰기 및 검증 %1, 변경 없음 %2, 실패 %3, 시도 안 함 %4</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="24"/>
        <source>, %1 not confirmed</source>
        <translation>, 확인 안 됨 %1</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="26"/>
        <source>; %1 of %2 store commands written</source>
        <translation>; 저장 명령 %2개 중 %1개 씀</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="35"/>
        <source>OpenTOP restore report</source>
        <translation>OpenTOP 복원 보고서</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="35"/>
        <source>File: %1</source>
        <translation>파일: %1</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="36"/>
        <source>Date: %1 (UTC)</source>
        <translation>날짜: %1 (UTC)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="39"/>
        <source>Written to the drives</source>
        <translation>드라이버에 씀</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="39"/>
        <source>Preview only: nothing written</source>
        <translation>미리 보기만: 아무것도 쓰지 않음</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="42"/>
        <source>Machine number %1 from %2: %3</source>
        <translation>국번 %1 (%2에서): %3</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="53"/>
        <source>  %1: %2</source>
        <translation>  %1: %2</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="55"/>
        <source>  %1: file %2, drive %3: %4</source>
        <translation>  %1: 파일 %2, 드라이버 %3: %4</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="61"/>
        <source>  Note: %1</source>
        <translation>  참고: %1</translation>
    </message>
</context>
<context>
    <name>opentop::Restorer</name>
    <message>
        <location filename="../model/files/Restorer.cpp" line="51"/>
        <source>interrupted before anything was written</source>
        <translation>아무것도 쓰기 전에 중단됨</translation>
    </message>
    <message>
        <location filename="../model/files/Restorer.cpp" line="66"/>
        <source>reading the drive failed, nothing written (%1)</source>
        <translation>드라이버 읽기 실패, 아무것도 쓰지 않음(%1)</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/files/Restorer.cpp" line="119"/>
        <source>%n value(s) of the file may not be written to the drives of the communication group; nothing written</source>
        <translation>
            <numerusform>파일의 값 %n개는 통신 그룹의 드라이버에 쓸 수 없습니다. 아무것도 쓰지 않았습니다</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/files/Restorer.cpp" line="147"/>
        <source>interrupted after %1 of %2 writes; run the restore again to complete it</source>
        <translation>쓰기 %2건 중 %1건 후 중단됨. 완료하려면 복원을 다시 실행하십시오</translation>
    </message>
    <message>
        <location filename="../model/files/Restorer.cpp" line="183"/>
        <source>%1 not confirmed (%2): the drive may or may not hold it; run the restore again, it reads the drive back first</source>
        <translation>%1 확인 안 됨(%2): 드라이버에 값이 들어갔는지 알 수 없습니다. 복원을 다시 실행하십시오. 먼저 드라이버를 다시 읽습니다</translation>
    </message>
    <message>
        <location filename="../model/files/Restorer.cpp" line="217"/>
        <source>after storing, the drive holds %1</source>
        <translation>저장 후 드라이버 값은 %1입니다</translation>
    </message>
    <message>
        <location filename="../model/files/Restorer.cpp" line="222"/>
        <source>the settings could not be read back after storing</source>
        <translation>저장 후 설정을 다시 읽을 수 없습니다</translation>
    </message>
    <message>
        <location filename="../model/files/Restorer.cpp" line="255"/>
        <source>communication settings changed (%1): they take effect when the drive is next powered on; connect with the new settings after that</source>
        <translation>통신 설정이 변경되었습니다(%1): 다음에 드라이버 전원을 켤 때 적용됩니다. 그 후에는 새 설정으로 연결하십시오</translation>
    </message>
</context>
<context>
    <name>opentop::ResultDatabase</name>
    <message>
        <location filename="../model/eol/ResultDatabase.cpp" line="45"/>
        <source>results database %1: %2</source>
        <translation>결과 데이터베이스 %1: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultDatabase.cpp" line="49"/>
        <source>the Qt SQL driver %1 is not installed (Debian: %2)</source>
        <translation>Qt SQL 드라이버 %1이(가) 설치되어 있지 않습니다(Debian: %2)</translation>
    </message>
</context>
<context>
    <name>opentop::ResultQueries</name>
    <message>
        <location filename="../model/eol/ResultQueries.cpp" line="207"/>
        <source>no unit record %1</source>
        <translation>제품 기록 %1 없음</translation>
    </message>
</context>
<context>
    <name>opentop::ResultSchema</name>
    <message>
        <location filename="../model/eol/ResultSchema.cpp" line="242"/>
        <source>the results database has schema version %1, newer than this program knows (%2): update OpenTOP on this station; nothing was written</source>
        <translation>결과 데이터베이스의 스키마 버전 %1이(가) 이 프로그램이 아는 버전(%2)보다 새롭습니다: 이 스테이션의 OpenTOP을 업데이트하십시오. 아무것도 쓰지 않았습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultSchema.cpp" line="277"/>
        <source>the migration left a record pointing at no unit (table %1)</source>
        <translation>마이그레이션 후 어떤 제품도 가리키지 않는 기록이 남았습니다(테이블 %1)</translation>
    </message>
</context>
<context>
    <name>opentop::ResultSink</name>
    <message>
        <location filename="../model/eol/ResultSink.cpp" line="137"/>
        <source>the results database is not open</source>
        <translation>결과 데이터베이스가 열려 있지 않습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultSink.cpp" line="210"/>
        <source>the results database refuses unit %1 (serial %2): %3</source>
        <translation>결과 데이터베이스가 유닛 %1(일련번호 %2)을 거부합니다: %3</translation>
    </message>
</context>
<context>
    <name>opentop::ResultSpool</name>
    <message>
        <location filename="../model/eol/ResultSpool.cpp" line="67"/>
        <location filename="../model/eol/ResultSpool.cpp" line="103"/>
        <source>the station&apos;s spool %1: %2</source>
        <translation>스테이션 보관 파일 %1: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultSpool.cpp" line="71"/>
        <source>its folder cannot be made</source>
        <translation>폴더를 만들 수 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultSpool.cpp" line="131"/>
        <source>the station&apos;s spool %1: entry %2 cannot be read (%3)</source>
        <translation>스테이션 보관 파일 %1: 항목 %2을(를) 읽을 수 없습니다(%3)</translation>
    </message>
</context>
<context>
    <name>opentop::ResultStore</name>
    <message>
        <location filename="../model/eol/ResultStore.cpp" line="64"/>
        <source>interrupted: the station stopped before the unit was finished (killed, power lost or crashed); the unit was not proven</source>
        <translation>중단됨: 제품이 끝나기 전에 스테이션이 멈췄습니다(강제 종료, 정전 또는 비정상 종료). 제품은 검증되지 않았습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultStore.cpp" line="72"/>
        <source>a unit needs a serial number</source>
        <translation>제품에는 시리얼 번호가 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultStore.cpp" line="197"/>
        <source>a unit is finished with pass, fail, error or aborted, not %1</source>
        <translation>제품은 %1이(가) 아니라 pass, fail, error 또는 aborted로 끝나야 합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultStore.cpp" line="227"/>
        <source>unit %1 (serial %2) was never begun in the results database</source>
        <translation>제품 %1(시리얼 %2)은(는) 결과 데이터베이스에서 시작된 적이 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultStore.cpp" line="229"/>
        <source>unit %1 (serial %2) is already recorded as %3; its record is kept</source>
        <translation>제품 %1(시리얼 %2)은(는) 이미 %3(으)로 기록되어 있습니다. 기존 기록을 유지합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultStore.cpp" line="251"/>
        <source>unit %1 (serial %2) is not running in the results database: it was never begun, or was already finished or marked interrupted</source>
        <translation>제품 %1(시리얼 %2)은(는) 결과 데이터베이스에서 진행 중이 아닙니다: 시작된 적이 없거나, 이미 끝났거나, 중단됨으로 표시되었습니다</translation>
    </message>
</context>
<context>
    <name>opentop::ResultUrl</name>
    <message>
        <location filename="../model/eol/ResultUrl.cpp" line="45"/>
        <source>no database given: name a file or a postgresql:// URL</source>
        <translation>데이터베이스가 지정되지 않았습니다: 파일 또는 postgresql:// URL을 지정하십시오</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultUrl.cpp" line="53"/>
        <source>unknown database URL &quot;%1&quot;: use a file path, sqlite:PATH or postgresql://user@host/database</source>
        <translation>알 수 없는 데이터베이스 URL &quot;%1&quot;: 파일 경로, sqlite:PATH 또는 postgresql://user@host/database를 사용하십시오</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultUrl.cpp" line="57"/>
        <source>sqlite: needs a file path</source>
        <translation>sqlite:에는 파일 경로가 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultUrl.cpp" line="86"/>
        <source>the host in &quot;%1&quot; has no closing ]</source>
        <translation>&quot;%1&quot;의 호스트에 닫는 ]가 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultUrl.cpp" line="114"/>
        <source>unknown connection option &quot;%1&quot; in the database URL; known: %2</source>
        <translation>데이터베이스 URL에 알 수 없는 연결 옵션 &quot;%1&quot;; 알려진 옵션: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultUrl.cpp" line="137"/>
        <source>the port &quot;%1&quot; in the database URL is not a number from 1 to 65535</source>
        <translation>데이터베이스 URL의 포트 &quot;%1&quot;이(가) 1–65535의 숫자가 아닙니다</translation>
    </message>
</context>
<context>
    <name>opentop::ResultsBrowser</name>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="61"/>
        <source>End-of-line results</source>
        <translation>출하 검사 결과</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="64"/>
        <source>Started</source>
        <translation>시작</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="64"/>
        <source>Serial</source>
        <translation>시리얼</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="64"/>
        <source>Recipe</source>
        <translation>레시피</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="64"/>
        <source>Station</source>
        <translation>스테이션</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="65"/>
        <source>Operator</source>
        <translation>작업자</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="65"/>
        <source>Verdict</source>
        <translation>판정</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="65"/>
        <source>Time (s)</source>
        <translation>시간 (s)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="66"/>
        <source>First failure</source>
        <translation>첫 불합격 항목</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="84"/>
        <source>Export CSV…</source>
        <translation>CSV 내보내기…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="85"/>
        <source>Certificate PDF…</source>
        <translation>성적서 PDF…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="136"/>
        <source>There is no results database at %1 yet: a station makes it when it records its first unit.</source>
        <translation>%1에 아직 결과 데이터베이스가 없습니다: 스테이션이 첫 제품을 기록할 때 만들어집니다.</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="142"/>
        <source>Opening the results database %1…</source>
        <translation>결과 데이터베이스 %1을(를) 여는 중…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="154"/>
        <source>Results database %1</source>
        <translation>결과 데이터베이스 %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="178"/>
        <source>Searching…</source>
        <translation>검색하는 중…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="189"/>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="278"/>
        <source>the results database is not open</source>
        <translation>결과 데이터베이스가 열려 있지 않습니다</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="220"/>
        <source>%1 rev. %2</source>
        <translation>%1 개정 %2</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="224"/>
        <source>–</source>
        <translation>–</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/eol/ResultsBrowser.cpp" line="239"/>
        <source>%n unit(s): %1 passed, %2 failed, %3 station errors · %4</source>
        <translation>
            <numerusform>제품 %n대: 합격 %1, 불합격 %2, 스테이션 오류 %3 · %4</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="253"/>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="306"/>
        <source>no unit is selected</source>
        <translation>선택한 제품이 없습니다</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="258"/>
        <source>Reading unit %1…</source>
        <translation>제품 %1을(를) 읽는 중…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="307"/>
        <source>the unit&apos;s record is still being read</source>
        <translation>제품 기록을 아직 읽는 중입니다</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="316"/>
        <source>Export units as CSV</source>
        <translation>제품을 CSV로 내보내기</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="316"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV 파일 (*.csv)</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/eol/ResultsBrowser.cpp" line="321"/>
        <source>%n unit(s) written to %1</source>
        <translation>
            <numerusform>제품 %n대를 %1에 저장했습니다</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="332"/>
        <source>Save certificate</source>
        <translation>성적서 저장</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="333"/>
        <source>PDF files (*.pdf)</source>
        <translation>PDF 파일 (*.pdf)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="338"/>
        <source>Certificate written to %1</source>
        <translation>성적서를 %1에 저장했습니다</translation>
    </message>
</context>
<context>
    <name>opentop::ResultsFilterBar</name>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="21"/>
        <source>SQLite file or postgresql://user@host/database</source>
        <translation>SQLite 파일 또는 postgresql://user@host/database</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="22"/>
        <source>Open</source>
        <translation>열기</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="23"/>
        <source>File…</source>
        <translation>파일…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="30"/>
        <source>any; * and ? as wildcards (SN-10*)</source>
        <translation>전체. * 와 ? 를 와일드카드로 사용(SN-10*)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="32"/>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="34"/>
        <source>any</source>
        <translation>모두</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="36"/>
        <source>Today</source>
        <translation>오늘</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="37"/>
        <source>Last 24 hours</source>
        <translation>최근 24시간</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="38"/>
        <source>Last 7 days</source>
        <translation>최근 7일</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="39"/>
        <source>Last 30 days</source>
        <translation>최근 30일</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="40"/>
        <source>All</source>
        <translation>전체</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="43"/>
        <source>Any</source>
        <translation>모두</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="47"/>
        <source>Search</source>
        <translation>검색</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="51"/>
        <source>Serial:</source>
        <translation>시리얼:</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="52"/>
        <source>Recipe:</source>
        <translation>레시피:</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="53"/>
        <source>Station:</source>
        <translation>스테이션:</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="54"/>
        <source>Period:</source>
        <translation>기간:</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="55"/>
        <source>Verdict:</source>
        <translation>판정:</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="63"/>
        <source>Database:</source>
        <translation>데이터베이스:</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="105"/>
        <source>Open results database</source>
        <translation>결과 데이터베이스 열기</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="106"/>
        <source>SQLite databases (*.db *.sqlite);;All files (*)</source>
        <translation>SQLite 데이터베이스 (*.db *.sqlite);;모든 파일 (*)</translation>
    </message>
</context>
<context>
    <name>opentop::RetestPolicy</name>
    <message>
        <location filename="../model/eol/RetestPolicy.cpp" line="20"/>
        <source>serial %1 has passed already; this recipe never tests a passed unit again</source>
        <translation>시리얼 %1은(는) 이미 합격했습니다. 이 레시피는 합격한 제품을 다시 검사하지 않습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RetestPolicy.cpp" line="23"/>
        <source>serial %1 has passed already; testing it again needs a technician</source>
        <translation>시리얼 %1은(는) 이미 합격했습니다. 다시 검사하려면 기술자의 허가가 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RetestPolicy.cpp" line="29"/>
        <source>serial %1 was tested %2 times under this recipe, its limit; another attempt needs a technician</source>
        <translation>시리얼 %1은(는) 이 레시피로 %2회 검사되어 한도에 도달했습니다. 다시 검사하려면 기술자의 허가가 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RetestPolicy.cpp" line="50"/>
        <source>the results database is not open</source>
        <translation>결과 데이터베이스가 열려 있지 않습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/RetestPolicy.cpp" line="58"/>
        <source>earlier tests of %1 were not checked (%2): the result is kept in the station&apos;s spool</source>
        <translation>%1의 이전 검사 기록을 확인하지 못했습니다(%2). 결과는 스테이션 보관 파일에 보관됩니다</translation>
    </message>
</context>
<context>
    <name>opentop::RoleEvaluator</name>
    <message>
        <location filename="../model/profile/RoleEvaluator.cpp" line="102"/>
        <source>%1 = %2 (%3, function %4)</source>
        <translation>%1 = %2 (%3, 기능 %4)</translation>
    </message>
</context>
<context>
    <name>opentop::RunCommand</name>
    <message>
        <location filename="../cli/RunCommand.cpp" line="50"/>
        <source>Test run: start, stop, direction, running data, hold/free, speed (needs --yes)</source>
        <translation>시운전: 기동, 정지, 방향, 운전 데이터, hold/free, 속도 (--yes 필요)</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="55"/>
        <source>Send the command (it moves or stops a motor).</source>
        <translation>명령을 보냅니다(모터를 움직이거나 정지시킴).</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="65"/>
        <source>error: usage: %1 (one machine number; a negative speed after --)</source>
        <translation>오류: 사용법: %1 (국번 하나; 음수 속도는 -- 뒤에)</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="73"/>
        <location filename="../cli/RunCommand.cpp" line="78"/>
        <location filename="../cli/RunCommand.cpp" line="83"/>
        <location filename="../cli/RunCommand.cpp" line="145"/>
        <source>error: %1</source>
        <translation>오류: %1</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="88"/>
        <source>Would send to machine number %1: %2
This moves or stops a motor: add --yes to send it.</source>
        <translation>국번 %1에 보낼 명령: %2
모터를 움직이거나 정지시킵니다: 보내려면 --yes를 추가하십시오.</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="109"/>
        <source>note: %1</source>
        <translation>참고: %1</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="137"/>
        <source>Sent to machine number %1: %2</source>
        <translation>국번 %1에 보냄: %2</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="139"/>
        <source>Sent to machine number %1, executed also by %2 (communication group): %3</source>
        <translation>국번 %1에 보냄, %2에서도 실행됨(통신 그룹): %3</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="175"/>
        <source>(not read: %1)</source>
        <translation>(읽지 않음: %1)</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="184"/>
        <source>State of machine number %1:</source>
        <translation>국번 %1의 상태:</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="200"/>
        <source>Communication group of %1, read after the command:</source>
        <translation>%1의 통신 그룹, 명령 후 읽음:</translation>
    </message>
</context>
<context>
    <name>opentop::RunControl</name>
    <message>
        <location filename="../model/run/RunControl.cpp" line="59"/>
        <source>%1 needs one value, e.g. &quot;%1 %2&quot;</source>
        <translation>%1에는 값 하나가 필요합니다. 예: &quot;%1 %2&quot;</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="62"/>
        <source>%1 takes no value</source>
        <translation>%1은(는) 값을 받지 않습니다</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="70"/>
        <source>select needs a running data number, e.g. &quot;select 2&quot;; got &quot;%1&quot;</source>
        <translation>select에는 운전 데이터 번호가 필요합니다. 예: &quot;select 2&quot;; 입력값: &quot;%1&quot;</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="80"/>
        <source>unknown run command &quot;%1&quot;; use start, stop, cw, ccw, select N, hold, free, coast or speed VALUE</source>
        <translation>알 수 없는 운전 명령 &quot;%1&quot;; start, stop, cw, ccw, select N, hold, free, coast 또는 speed VALUE를 사용하십시오</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="127"/>
        <source>%1 drives have no &quot;%2&quot; command; they take: %3</source>
        <translation>%1 드라이버에는 &quot;%2&quot; 명령이 없습니다. 사용할 수 있는 명령: %3</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="148"/>
        <source>%1 has no selection codes</source>
        <translation>%1에는 선택 코드가 없습니다</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="149"/>
        <source>select %1: choose %2–%3 (%4 … %5)</source>
        <translation>select %1: %2–%3 중에서 선택하십시오(%4 … %5)</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="186"/>
        <source>cannot read %1 to check that the drive takes motion commands: %2</source>
        <translation>드라이버가 운전 명령을 받는지 확인하기 위해 %1을(를) 읽을 수 없습니다: %2</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="206"/>
        <source>machine number %1 is in &quot;%2&quot; (%3); nothing was sent</source>
        <translation>국번 %1은(는) &quot;%2&quot;(%3) 상태입니다. 아무것도 보내지 않았습니다</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="210"/>
        <source>In &quot;%1&quot; the drive takes run, stop, direction and speed selection from its input terminals and refuses motion commands over the bus. To test-run it from here, switch it to &quot;%2&quot;: opentop-cli set %3 %4=%5 (and back to &quot;%1&quot;, =%6, when the machine&apos;s own controls should run it again).</source>
        <translation>&quot;%1&quot;에서는 드라이버가 운전, 정지, 방향, 속도 선택을 입력 단자로 받고 버스를 통한 운전 명령은 거부합니다. 여기서 시운전하려면 &quot;%2&quot;(으)로 전환하십시오: opentop-cli set %3 %4=%5 (설비 자체 조작으로 다시 운전하려면 &quot;%1&quot;(=%6)(으)로 되돌리십시오).</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="265"/>
        <source>An alarm is active: the drive refuses to run until it is cleared. See opentop-cli alarms %1, then alarms %1 --reset --yes.</source>
        <translation>알람이 발생 중입니다: 해제할 때까지 드라이버는 운전을 거부합니다. opentop-cli alarms %1을(를) 확인한 뒤 alarms %1 --reset --yes를 실행하십시오.</translation>
    </message>
</context>
<context>
    <name>opentop::RunLiveState</name>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="26"/>
        <source>The drive now</source>
        <translation>현재 드라이버</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="49"/>
        <source>State</source>
        <translation>상태</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="51"/>
        <source>Alarm</source>
        <translation>알람</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="58"/>
        <source>Running data</source>
        <translation>운전 데이터</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="95"/>
        <source>%1:</source>
        <translation>%1:</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="133"/>
        <source>%1 (%2 %3)</source>
        <translation>%1 (%2 %3)</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="135"/>
        <source>not reported</source>
        <translation>알려주지 않음</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="143"/>
        <location filename="../ui/run/RunLiveState.cpp" line="146"/>
        <location filename="../ui/run/RunLiveState.cpp" line="156"/>
        <source>not read</source>
        <translation>읽지 않음</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="143"/>
        <source>SPno%1</source>
        <translation>SPno%1</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="148"/>
        <source>none</source>
        <translation>없음</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="151"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="153"/>
        <source>active</source>
        <translation>발생 중</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="172"/>
        <source>waiting for the first answer…</source>
        <translation>첫 응답 대기 중…</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="172"/>
        <source>not watched</source>
        <translation>감시 안 함</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="178"/>
        <source>Not live: %1</source>
        <translation>실시간 아님: %1</translation>
    </message>
</context>
<context>
    <name>opentop::RunningData</name>
    <message>
        <location filename="../model/profile/RunningData.cpp" line="76"/>
        <source>SPno%1 slows down from %2 r/min in %3 s: the manual asks for a deceleration time of more than %4 s when slowing down from high speed (about %5 r/min and above).</source>
        <translation>SPno%1은(는) %2 r/min에서 %3 s 동안 감속합니다: 매뉴얼은 고속(약 %5 r/min 이상)에서 감속할 때 감속 시간을 %4 s 이상으로 하도록 요구합니다.</translation>
    </message>
    <message>
        <location filename="../model/profile/RunningData.cpp" line="144"/>
        <source>Short deceleration from high speed on %1 (%2 r/min in %3 s): the manual asks for a deceleration time of more than %4 s when slowing down from high speed (about %5 r/min and above).</source>
        <translation>%1의 고속 감속 시간이 짧습니다(%2 r/min에서 %3 s): 매뉴얼은 고속(약 %5 r/min 이상)에서 감속할 때 감속 시간을 %4 s 이상으로 하도록 요구합니다.</translation>
    </message>
</context>
<context>
    <name>opentop::RunningDataPage</name>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="40"/>
        <location filename="../ui/pages/RunningDataPage.cpp" line="55"/>
        <source>Running data</source>
        <translation>운전 데이터</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="55"/>
        <source>Speed (r/min)</source>
        <translation>속도 (r/min)</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="55"/>
        <source>Acceleration (s)</source>
        <translation>가속 (s)</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="56"/>
        <source>Deceleration (s)</source>
        <translation>감속 (s)</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="56"/>
        <source>Direction</source>
        <translation>방향</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="69"/>
        <source>SPno%1</source>
        <translation>SPno%1</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="72"/>
        <source>Selected by the inputs M0 = %1, M1 = %2, M2 = %3 or by the running data selection command</source>
        <translation>입력 M0 = %1, M1 = %2, M2 = %3 또는 운전 데이터 선택 명령으로 선택</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="95"/>
        <source>SS trimmer</source>
        <translation>SS 트리머</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="96"/>
        <source>SPno1 has no acceleration register: the SS trimmer on the drive sets it (0.5–30 s); it is not stored in the drive</source>
        <translation>SPno1에는 가속 레지스터가 없습니다: 드라이버의 SS 트리머로 설정합니다(0.5–30 s). 드라이버에 저장되지 않습니다</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="99"/>
        <source>SD trimmer</source>
        <translation>SD 트리머</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="100"/>
        <source>SPno1 has no deceleration register: the SD trimmer on the drive sets it (0.5 s or 2–30 s); it is not stored in the drive</source>
        <translation>SPno1에는 감속 레지스터가 없습니다: 드라이버의 SD 트리머로 설정합니다(0.5 s 또는 2–30 s). 드라이버에 저장되지 않습니다</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="104"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="105"/>
        <source>This drive has no register for this value</source>
        <translation>이 드라이버에는 이 값의 레지스터가 없습니다</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="112"/>
        <source>Initialize</source>
        <translation>초기화</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="114"/>
        <source>Reset SPno%1 on the drive to its factory defaults</source>
        <translation>드라이버의 SPno%1을(를) 공장 출하값으로 되돌립니다</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="115"/>
        <location filename="../ui/pages/RunningDataPage.cpp" line="315"/>
        <location filename="../ui/pages/RunningDataPage.cpp" line="322"/>
        <source>Initialize SPno%1</source>
        <translation>SPno%1 초기화</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="145"/>
        <source>SPno1 runs at the speed of the external speed-setting VR (CN3) with the SS/SD trimmer times; it is not stored in the drive</source>
        <translation>SPno1은 외부 속도 설정 VR(CN3)의 속도와 SS/SD 트리머 시간으로 운전합니다. 드라이버에 저장되지 않습니다</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="255"/>
        <source>Allowed speed on this %1: %2 (0 stops the motor)</source>
        <translation>이 %1에서 허용되는 속도: %2 (0이면 모터 정지)</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="168"/>
        <location filename="../ui/pages/RunningDataPage.cpp" line="265"/>
        <location filename="../ui/pages/RunningDataPage.cpp" line="281"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="268"/>
        <source>Allowed speed: %1</source>
        <translation>허용 속도: %1</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="269"/>
        <source>The drive&apos;s variant is not known, so a speed must suit every variant (0 stops the motor): %1</source>
        <translation>드라이버의 기종을 알 수 없으므로 속도는 모든 기종에 맞아야 합니다(0이면 모터 정지): %1</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="281"/>
        <source>its factory default</source>
        <translation>공장 출하값</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="303"/>
        <source>The SPno1 speed and times come from the external VR and the SS/SD trimmers; they do not change.</source>
        <translation>SPno1의 속도와 시간은 외부 VR과 SS/SD 트리머로 정해지므로 바뀌지 않습니다.</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="310"/>
        <source>Your unwritten edits in this row are discarded.</source>
        <translation>이 행에서 쓰지 않은 편집은 버려집니다.</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="316"/>
        <source>Reset running data SPno%1 of drive %2 to these factory defaults?</source>
        <translation>드라이버 %2의 운전 데이터 SPno%1을(를) 이 공장 출하값으로 되돌리시겠습니까?</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="328"/>
        <source>Initializing SPno%1…</source>
        <translation>SPno%1 초기화 중…</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="343"/>
        <source>SPno%1 was not initialized: %2</source>
        <translation>SPno%1을(를) 초기화하지 못했습니다: %2</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/pages/RunningDataPage.cpp" line="359"/>
        <source>SPno%1 initialized; %n value(s) could not be read back</source>
        <translation>
            <numerusform>SPno%1 초기화 완료. 값 %n개를 다시 읽을 수 없습니다</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="361"/>
        <source>SPno%1 initialized to its factory defaults</source>
        <translation>SPno%1을(를) 공장 출하값으로 초기화했습니다</translation>
    </message>
</context>
<context>
    <name>opentop::ScanCommand</name>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="66"/>
        <source>Find and identify the drives on the bus (machine numbers 1–247)</source>
        <translation>버스의 드라이버를 찾아 식별합니다(국번 1–247)</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="72"/>
        <source>First machine number to ask, 1–247 (default 1).</source>
        <translation>조회할 첫 국번, 1–247 (기본값 1).</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="72"/>
        <location filename="../cli/ScanCommand.cpp" line="73"/>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="73"/>
        <source>Last machine number to ask, 1–247 (default 247).</source>
        <translation>조회할 마지막 국번, 1–247 (기본값 247).</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="75"/>
        <source>Wait per machine number in ms, 10–5000 (default: derived from the baud rate; raise it for slow adapters or gateways).</source>
        <translation>국번당 대기 시간(ms), 10–5000 (기본값: 통신 속도에서 산출; 느린 어댑터나 게이트웨이는 늘리십시오).</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="77"/>
        <source>MS</source>
        <translation>MS</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="79"/>
        <source>Also ask the machine numbers not found in every other line format a drive can be set to (a DC controller at 8E1 on a DBU bus at 8N1): one more pass per format, off by default.</source>
        <translation>찾지 못한 국번을 드라이브가 설정될 수 있는 다른 모든 통신 형식으로도 묻습니다(8N1의 DBU 버스에 있는 8E1의 DC 컨트롤러). 형식마다 스캔이 한 번 더 필요하며 기본은 꺼져 있습니다.</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="94"/>
        <source>error: --%1 must be a number %2–%3, not &quot;%4&quot;</source>
        <translation>오류: --%1은(는) %2–%3의 숫자여야 합니다. &quot;%4&quot;은(는) 안 됩니다</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="106"/>
        <source>error: scan takes no arguments; use --from N --to N</source>
        <translation>오류: scan은 인수를 받지 않습니다. --from N --to N을 사용하십시오</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="115"/>
        <source>error: --from %1 is after --to %2</source>
        <translation>오류: --from %1이(가) --to %2보다 뒤입니다</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="133"/>
        <source>Scanning machine numbers %1–%2 on %3, %4 ms each…</source>
        <translation>%3에서 국번 %1–%2 스캔 중, 국번당 %4 ms…</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="180"/>
        <source>Interrupted before any machine number was scanned.</source>
        <translation>국번을 하나도 스캔하기 전에 중단되었습니다.</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="182"/>
        <source>Interrupted: machine numbers %1–%2 were scanned (%3 of %4); %5–%6 were not asked.</source>
        <translation>중단됨: 국번 %1–%2을(를) 스캔했습니다(%4개 중 %3개). %5–%6은(는) 조회하지 않았습니다.</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="196"/>
        <source>error: the scan stopped at machine number %1: %2</source>
        <translation>오류: 국번 %1에서 스캔이 멈췄습니다: %2</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="208"/>
        <source>note: remembered for %1: %2; set, run and restore read their communication groups before a write</source>
        <translation>참고: %1에 대해 기억함: %2. set, run, restore는 쓰기 전에 이 드라이버들의 통신 그룹을 읽습니다</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="217"/>
        <source>warning: %1</source>
        <translation>경고: %1</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="219"/>
        <source>note: %1 drive(s) answered only after the %2 ms wait and were asked again; if scans miss drives, give a longer --wait.</source>
        <translation>참고: 드라이버 %1대가 %2 ms 대기 후에야 응답하여 다시 조회했습니다. 스캔에서 드라이버가 누락되면 --wait를 늘리십시오.</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="228"/>
        <source>warning: machine number %1 answered, but its identification failed, also when asked again %2 more times; it is not counted as a drive. Add it by hand: name it in a command (it is identified again then, within --timeout; raise it for a slow device), or check its line settings and scan again with a longer --wait.</source>
        <translation>경고: 국번 %1이(가) 응답했지만 %2번 더 물어도 식별에 실패했습니다. 드라이버로 세지 않습니다. 직접 추가하십시오: 명령에 이 국번을 지정하면 --timeout 안에 다시 식별합니다(응답이 느린 장치는 늘리십시오). 또는 통신 설정을 확인한 뒤 더 긴 --wait로 다시 스캔하십시오.</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="237"/>
        <source>No drive answered at machine numbers %1–%2. Check:
  - the wiring, and the A/B polarity (swap A and B if unsure);
  - baud rate and parity: the drives&apos; settings must match %3 (--baud, --parity, --family);
  - the termination (120 Ω at both ends of the bus) and that the drives are powered.</source>
        <translation>국번 %1–%2에서 응답한 드라이버가 없습니다. 확인 사항:
  - 배선과 A/B 극성 (확실하지 않으면 A와 B를 바꿔 보십시오);
  - 통신 속도와 패리티: 드라이버 설정이 %3과(와) 같아야 합니다(--baud, --parity, --family);
  - 종단 저항 (버스 양 끝에 120 Ω)과 드라이버 전원.</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="250"/>
        <source>hint: %1 Retry with the same connection and: %2</source>
        <translation>힌트: %1 같은 연결에 다음을 추가하여 다시 시도하십시오: %2</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="263"/>
        <source>Serial line: %1</source>
        <translation>시리얼 라인: %1</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="266"/>
        <source>warning: %1 The scan waits up to %2 ms longer per machine number because of it.</source>
        <translation>경고: %1 이 때문에 스캔 시 국번마다 최대 %2 ms를 더 기다립니다.</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="390"/>
        <source>warning: machine number %1 (%2) answers with garbled replies: two drives probably have the same machine number. Check the address switches of the drives on this bus, give each drive its own machine number, power them off and on, and scan again.</source>
        <translation>경고: 국번 %1(%2)의 응답이 손상되었습니다. 두 드라이버가 같은 국번일 가능성이 큽니다. 이 버스 드라이버들의 주소 스위치를 확인하고, 드라이버마다 다른 국번을 지정한 뒤 전원을 껐다 켜고 다시 스캔하십시오.</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="276"/>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="276"/>
        <source>hex</source>
        <translation>16진수</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="276"/>
        <source>switches</source>
        <translation>스위치</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="276"/>
        <source>family</source>
        <translation>제품군</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="277"/>
        <source>model</source>
        <translation>모델</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="277"/>
        <source>firmware</source>
        <translation>펌웨어</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="277"/>
        <source>state</source>
        <translation>상태</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="283"/>
        <source>name</source>
        <translation>이름</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="289"/>
        <source>comm. group</source>
        <translation>통신 그룹</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="294"/>
        <source>line format</source>
        <translation>통신 형식</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="311"/>
        <source>the port&apos;s</source>
        <translation>포트 형식</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="371"/>
        <source>1 drive found in %1 s</source>
        <translation>드라이버 1대 발견(%1 s)</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="372"/>
        <source>%1 drives found in %2 s</source>
        <translation>드라이버 %1대 발견(%2 s)</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="374"/>
        <source>; 1 possible duplicate machine number: %1</source>
        <translation>; 중복 가능성이 있는 국번 1개: %1</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="376"/>
        <source>; %1 possible duplicate machine numbers: %2</source>
        <translation>; 중복 가능성이 있는 국번 %1개: %2</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="380"/>
        <source>; answered, identification failed: %1 (add by hand)</source>
        <translation>; 응답 있음, 식별 실패: %1(직접 추가)</translation>
    </message>
</context>
<context>
    <name>opentop::ScanDrives</name>
    <message>
        <location filename="../cli/ScanDrives.cpp" line="43"/>
        <source>%1 — variant unknown</source>
        <translation>%1 — 기종 알 수 없음</translation>
    </message>
    <message>
        <location filename="../cli/ScanDrives.cpp" line="44"/>
        <source>the drive does not report its variant; give it with --variant %1=VARIANT (%2)</source>
        <translation>드라이버가 기종을 알려주지 않습니다. --variant %1=VARIANT로 지정하십시오(%2)</translation>
    </message>
</context>
<context>
    <name>opentop::ScanFormats</name>
    <message>
        <location filename="../cli/ScanFormats.cpp" line="44"/>
        <source>Scanning machine numbers %1–%2 at %3 (--try-formats), %4 ms each…</source>
        <translation>%3(으)로 국번 %1–%2 스캔 중(--try-formats), 각 %4 ms…</translation>
    </message>
    <message>
        <location filename="../cli/ScanFormats.cpp" line="71"/>
        <source>Machine number %1 answered at %2: it is asked at that format from now on (--drive-format %1=%3).</source>
        <translation>국번 %1이(가) %2(으)로 응답했습니다. 이제부터 그 형식으로 묻습니다(--drive-format %1=%3).</translation>
    </message>
    <message>
        <location filename="../cli/ScanFormats.cpp" line="99"/>
        <source>hint: %1 If one is on this bus, give its machine number its format with --drive-format ID=BAUD:FORMAT (e.g. 7=9600:8E1), or scan with --try-formats: %2 more passes, %3 more requests, about %4 s more.</source>
        <translation>힌트: %1 버스에 이런 드라이브가 있으면 --drive-format ID=BAUD:FORMAT(예: 7=9600:8E1)으로 그 국번의 형식을 지정하거나 --try-formats로 스캔하십시오: 스캔 %2회, 요청 %3개, 약 %4 s가 더 걸립니다.</translation>
    </message>
</context>
<context>
    <name>opentop::ScanProgress</name>
    <message>
        <location filename="../cli/ScanProgress.cpp" line="34"/>
        <source>scanning %1/%2 (%3 %), machine number %4, %5 found</source>
        <translation>스캔 중 %1/%2 (%3 %), 국번 %4, %5대 발견</translation>
    </message>
    <message>
        <location filename="../cli/ScanProgress.cpp" line="49"/>
        <source>scan: %1 % (%2 of %3 machine numbers), %4 found</source>
        <translation>스캔: %1 % (국번 %3개 중 %2개), %4대 발견</translation>
    </message>
    <message>
        <location filename="../cli/ScanProgress.cpp" line="60"/>
        <source>scan: machine number %1 answered, identification failed: retrying (%2 of %3)…</source>
        <translation>스캔: 국번 %1이(가) 응답했지만 식별에 실패했습니다: 재시도 중(%3회 중 %2회째)…</translation>
    </message>
</context>
<context>
    <name>opentop::SerialEntry</name>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="28"/>
        <source>Scan or type the serial number, then Enter</source>
        <translation>시리얼 번호를 스캔하거나 입력한 뒤 Enter</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="29"/>
        <source>Cancel unit (Esc)</source>
        <translation>제품 취소 (Esc)</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="73"/>
        <source>Serial number NOT taken: %1.</source>
        <translation>시리얼 번호가 접수되지 않았습니다: %1.</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="102"/>
        <source>Serial %1 was NOT taken: unit %2 is being tested. Scan it again once its verdict shows.</source>
        <translation>일련번호 %1은(는) 접수되지 않았습니다: 유닛 %2을(를) 검사 중입니다. 판정이 표시된 후 다시 스캔하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="104"/>
        <location filename="../ui/eol/SerialEntry.cpp" line="106"/>
        <source>another</source>
        <translation>다른 유닛</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="105"/>
        <source>A serial number was NOT taken: %1. Unit %2 is being tested.</source>
        <translation>시리얼 번호가 접수되지 않았습니다: %1. 유닛 %2을(를) 검사 중입니다.</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="122"/>
        <source>Per-unit value</source>
        <translation>제품별 값</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="123"/>
        <source>Drive %1: %2 (%3–%4 %5)</source>
        <translation>드라이버 %1: %2 (%3–%4 %5)</translation>
    </message>
</context>
<context>
    <name>opentop::SerialLineFields</name>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="29"/>
        <source>Adapter switches itself</source>
        <translation>어댑터가 직접 전환</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="30"/>
        <source>Auto (kernel, else RTS)</source>
        <translation>자동 (커널, 안 되면 RTS)</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="31"/>
        <source>Kernel RS-485 mode</source>
        <translation>커널 RS-485 모드</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="32"/>
        <source>RTS from the program</source>
        <translation>프로그램이 RTS 제어</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="34"/>
        <source>Who switches the RS-485 transceiver between sending and receiving. USB–RS-485 adapters do it themselves; on-board RS-485 ports need the driver&apos;s RS-485 mode (kernel) or RTS switched by the program. The status bar says what the driver accepted.</source>
        <translation>RS-485 트랜시버의 송신/수신 전환을 누가 하는지 지정합니다. USB–RS-485 어댑터는 직접 전환합니다. 보드 내장 RS-485 포트는 시리얼 드라이버의 RS-485 모드(커널)나 프로그램의 RTS 전환이 필요합니다. 시리얼 드라이버가 받아들인 설정은 상태 표시줄에 표시됩니다.</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="38"/>
        <source>RS-485 d&amp;irection:</source>
        <translation>RS-485 방향 전환(&amp;I):</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="43"/>
        <source>high while sending</source>
        <translation>송신 중 High</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="44"/>
        <source>low while sending</source>
        <translation>송신 중 Low</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="45"/>
        <source>The RTS level that enables the transceiver&apos;s driver</source>
        <translation>트랜시버의 송신부를 활성화하는 RTS 레벨</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="50"/>
        <source>delay </source>
        <translation>지연 </translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="51"/>
        <source> µs</source>
        <translation> µs</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="52"/>
        <source>default delay</source>
        <translation>기본 지연</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="53"/>
        <source>Before and after sending. Default: the driver&apos;s own, or one character time from the program; the kernel rounds up to whole ms.</source>
        <translation>송신 전후의 지연입니다. 기본값: 시리얼 드라이버 자체 지연, 또는 프로그램의 1문자 시간. 커널은 ms 단위로 올림합니다.</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="58"/>
        <source>RTS le&amp;vel:</source>
        <translation>RTS 레벨(&amp;V):</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="62"/>
        <source>&amp;Low latency (no 16 ms hold-back in USB adapters)</source>
        <translation>저지연 (USB 어댑터의 16 ms 보류 없음)(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="65"/>
        <source>Asks the driver to pass received bytes on at once. Many USB–serial chips otherwise hold them for up to 16 ms, which slows scans and polling.</source>
        <translation>수신한 바이트를 즉시 넘기도록 시리얼 드라이버에 요청합니다. 그렇지 않으면 많은 USB–시리얼 칩이 최대 16 ms 동안 보류하여 스캔과 폴링이 느려집니다.</translation>
    </message>
</context>
<context>
    <name>opentop::SerialLock</name>
    <message>
        <location filename="../model/session/SerialLock.cpp" line="39"/>
        <source>%1 = %2 prohibits configuration over the serial interface: OpenTOP may then no longer be able to change this drive&apos;s settings over the serial line it talks on. To undo it: write %1 = %3 again if the drive still accepts it; while it is not stored, switch the drive off and on; otherwise switch the controller to potentiometer/analog control, connect at 9600 bit/s, 8E1, address 1 and write %1 = %3 there.</source>
        <translation>%1 = %2은(는) 시리얼 인터페이스를 통한 설정 변경을 금지합니다: 그러면 OpenTOP이 현재 통신 중인 시리얼 라인으로 이 드라이버의 설정을 더 이상 변경하지 못할 수 있습니다. 되돌리는 방법: 드라이버가 아직 받아들이면 %1 = %3을(를) 다시 씁니다. 저장되지 않았다면 드라이버 전원을 껐다 켭니다. 그렇지 않으면 컨트롤러를 포텐셔미터/아날로그 제어로 바꾸고 9600 bit/s, 8E1, 국번 1로 연결하여 %1 = %3을(를) 씁니다.</translation>
    </message>
</context>
<context>
    <name>opentop::SerialRule</name>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="65"/>
        <source>no serial number</source>
        <translation>시리얼 번호 없음</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="67"/>
        <source>a serial number has at most %1 characters; this one has %2</source>
        <translation>시리얼 번호는 최대 %1자입니다. 이 번호는 %2자입니다</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="71"/>
        <source>a serial number may not hold control characters, format characters or line breaks; character %1 is %2</source>
        <translation>시리얼 번호에는 제어 문자, 서식 문자나 줄바꿈을 넣을 수 없습니다. %1번째 문자는 %2입니다</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="75"/>
        <source>serial number &quot;%1&quot; begins or ends with white space; a serial number is tested exactly as given</source>
        <translation>시리얼 번호 &quot;%1&quot;의 앞이나 뒤에 공백이 있습니다. 시리얼 번호는 입력된 그대로 검사됩니다</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="85"/>
        <source>serial number &quot;%1&quot; does not match the recipe&apos;s serial pattern %2</source>
        <translation>시리얼 번호 &quot;%1&quot;이(가) 레시피의 시리얼 번호 패턴 %2과(와) 일치하지 않습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="87"/>
        <source>serial number &quot;%1&quot; does not match the recipe&apos;s serial pattern %2 (e.g. %3)</source>
        <translation>시리얼 번호 &quot;%1&quot;이(가) 레시피의 시리얼 번호 패턴 %2과(와) 일치하지 않습니다(예: %3)</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="104"/>
        <source>&quot;serialPattern&quot; has %1 characters; at most %2 are allowed</source>
        <translation>&quot;serialPattern&quot;은(는) %1자입니다. 최대 %2자까지 허용됩니다</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="108"/>
        <source>&quot;serialPattern&quot; may not hold control characters, format characters or line breaks (no serial number holds one); character %1 is %2</source>
        <translation>&quot;serialPattern&quot;에는 제어 문자, 서식 문자나 줄바꿈을 넣을 수 없습니다(시리얼 번호에는 없는 문자입니다). %1번째 문자는 %2입니다</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="115"/>
        <source>&quot;serialPattern&quot; %1 is not a valid regular expression: %2 at character %3</source>
        <translation>&quot;serialPattern&quot; %1은(는) 올바른 정규 표현식이 아닙니다: %3번째 문자에서 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="121"/>
        <source>&quot;serialPattern&quot; %1 cannot be matched against a whole serial number</source>
        <translation>&quot;serialPattern&quot; %1은(는) 시리얼 번호 전체와 대조할 수 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="127"/>
        <source>&quot;serialExample&quot; needs a &quot;serialPattern&quot; that it matches</source>
        <translation>&quot;serialExample&quot;에는 그것과 일치하는 &quot;serialPattern&quot;이 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="130"/>
        <source>&quot;serialExample&quot;: %1</source>
        <translation>&quot;serialExample&quot;: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="140"/>
        <source>any, at most %1 characters</source>
        <translation>모두 허용, 최대 %1자</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="143"/>
        <source>%1 (e.g. %2)</source>
        <translation>%1(예: %2)</translation>
    </message>
</context>
<context>
    <name>opentop::SetCommand</name>
    <message>
        <location filename="../cli/SetCommand.cpp" line="43"/>
        <source>Write parameters by name, validated, read back and verified</source>
        <translation>파라미터를 이름으로 쓰고, 검사하고, 다시 읽어 검증합니다</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="53"/>
        <source>Write registers by address: ADDR=VALUE (repeatable; VALUE,VALUE... with --fc 16).</source>
        <translation>주소로 레지스터를 씁니다: ADDR=VALUE (반복 가능; --fc 16이면 VALUE,VALUE...).</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="54"/>
        <source>ADDR=VALUE</source>
        <translation>ADDR=VALUE</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="55"/>
        <source>Function code for --raw writes: 6 (default) or 16.</source>
        <translation>--raw 쓰기의 기능 코드: 6(기본값) 또는 16.</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="55"/>
        <source>FC</source>
        <translation>FC</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="64"/>
        <source>error: usage: set ID NAME=VALUE... (e.g. set 1 spno2.accel=2.5), or set ID --raw ADDR=VALUE</source>
        <translation>오류: 사용법: set ID NAME=VALUE... (예: set 1 spno2.accel=2.5) 또는 set ID --raw ADDR=VALUE</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="76"/>
        <source>error: &quot;%1&quot; is not NAME=VALUE</source>
        <translation>오류: &quot;%1&quot;은(는) NAME=VALUE 형식이 아닙니다</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="83"/>
        <location filename="../cli/SetCommand.cpp" line="92"/>
        <location filename="../cli/SetCommand.cpp" line="108"/>
        <source>error: %1</source>
        <translation>오류: %1</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="105"/>
        <location filename="../cli/SetCommand.cpp" line="117"/>
        <source>warning: %1</source>
        <translation>경고: %1</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="50"/>
        <source>Confirm commands that move a motor, reset, erase, initialise or store, and setting the serial configuration lock.</source>
        <translation>모터를 움직이거나 리셋, 삭제, 초기화, 저장하는 명령과 시리얼 설정 잠금의 설정을 확인합니다.</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="149"/>
        <source>next: %1</source>
        <translation>다음: %1</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="151"/>
        <source>next: opentop-cli --baud %1 --parity %2 --stop-bits %3 ... (the factory line settings)</source>
        <translation>다음: opentop-cli --baud %1 --parity %2 --stop-bits %3 ... (공장 출하 통신 설정)</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="196"/>
        <source>Parameter</source>
        <translation>파라미터</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="196"/>
        <source>Value</source>
        <translation>값</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="196"/>
        <source>Result</source>
        <translation>결과</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="202"/>
        <source>written, verified</source>
        <translation>쓰기 완료, 검증됨</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="204"/>
        <source>written, not verified: %1</source>
        <translation>쓰기 완료, 확인 안 됨: %1</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="205"/>
        <source>written (command, not readable)</source>
        <translation>쓰기 완료(명령, 읽기 불가)</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="207"/>
        <source>not confirmed (%1): the drive may or may not hold it; &quot;get&quot; reads it back</source>
        <translation>확인 안 됨(%1): 드라이버에 값이 들어갔는지 알 수 없습니다. &quot;get&quot;으로 다시 읽으십시오</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="218"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="225"/>
        <source>note: the drive uses %1 from its next power-up on: switch the drive off and on, then connect with the new setting (--baud, --parity)</source>
        <translation>참고: 드라이버는 다음 전원 투입부터 %1을(를) 사용합니다: 드라이버 전원을 껐다 켠 뒤 새 설정(--baud, --parity)으로 연결하십시오</translation>
    </message>
</context>
<context>
    <name>opentop::SetRaw</name>
    <message>
        <location filename="../cli/SetRaw.cpp" line="30"/>
        <source>error: --fc for raw writes is 6 or 16</source>
        <translation>오류: raw 쓰기의 --fc는 6 또는 16입니다</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="56"/>
        <source>error: &quot;%1&quot; is not ADDR=VALUE (0x.. or decimal, 0–65535; several values, comma separated, only with --fc 16)</source>
        <translation>오류: &quot;%1&quot;은(는) ADDR=VALUE 형식이 아닙니다(0x.. 또는 10진수, 0–65535; 여러 값은 쉼표로 구분하며 --fc 16에서만)</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="73"/>
        <source>error: 0x%1 is not a register the profile knows; add --yes to write it anyway; nothing was written</source>
        <translation>오류: 0x%1은(는) 프로파일에 없는 레지스터입니다. 그래도 쓰려면 --yes를 추가하십시오. 아무것도 쓰지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="83"/>
        <location filename="../cli/SetRaw.cpp" line="128"/>
        <source>error: %1; nothing was written</source>
        <translation>오류: %1; 아무것도 쓰지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="84"/>
        <source>%1 is a %2 command; add --yes</source>
        <translation>%1은(는) %2 명령입니다. --yes를 추가하십시오</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="91"/>
        <source>error: the write covers part of %1; add --yes to write it anyway; nothing was written</source>
        <translation>오류: 이 쓰기는 %1의 일부만 덮습니다. 그래도 쓰려면 --yes를 추가하십시오. 아무것도 쓰지 않았습니다</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="141"/>
        <source>Address</source>
        <translation>주소</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="141"/>
        <source>Written</source>
        <translation>쓴 값</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="141"/>
        <source>Result</source>
        <translation>결과</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="174"/>
        <source>written</source>
        <translation>쓰기 완료</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="176"/>
        <source>written, verified</source>
        <translation>쓰기 완료, 검증됨</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="178"/>
        <source>written, but reads back differently</source>
        <translation>쓰기 완료, 다시 읽은 값이 다름</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="181"/>
        <source>written (not readable back: %1)</source>
        <translation>쓰기 완료(다시 읽기 불가: %1)</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="193"/>
        <source>Also written to %1 (communication group); not read back: no parameter of the profile</source>
        <translation>%1에도 씀(통신 그룹). 다시 읽지 않음: 프로파일의 파라미터가 아님</translation>
    </message>
</context>
<context>
    <name>opentop::SettingsWrite</name>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="29"/>
        <source>%1 is given twice (%2=%3 and %4); give each setting once; nothing written</source>
        <translation>%1이(가) 두 번 지정되었습니다(%2=%3 및 %4). 설정은 한 번씩만 지정하십시오. 아무것도 쓰지 않았습니다</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="76"/>
        <source>%1 has no parameter &quot;%2&quot;; see &quot;opentop-cli params --family %1&quot;</source>
        <translation>%1에 파라미터 &quot;%2&quot;이(가) 없습니다. &quot;opentop-cli params --family %1&quot;을 참조하십시오</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="80"/>
        <source>%1 is read-only</source>
        <translation>%1은(는) 읽기 전용입니다</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="83"/>
        <source>%1 is a %2 command; add --yes to send it</source>
        <translation>%1은(는) %2 명령입니다. 보내려면 --yes를 추가하십시오</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="105"/>
        <source>cannot read %1 to check the values; nothing written</source>
        <translation>값을 검사하기 위해 %1을(를) 읽을 수 없습니다. 아무것도 쓰지 않았습니다</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="157"/>
        <source>Add --yes to set it.</source>
        <translation>설정하려면 --yes를 추가하십시오.</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="229"/>
        <source>interrupted as it was sent</source>
        <translation>전송 중 중단됨</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="231"/>
        <source>not written (interrupted)</source>
        <translation>쓰지 않음(중단됨)</translation>
    </message>
</context>
<context>
    <name>opentop::ShiftPlan</name>
    <message>
        <location filename="../model/eol/ShiftPlan.cpp" line="30"/>
        <source>&quot;%1&quot; is not a time of day such as 06:00</source>
        <translation>&quot;%1&quot;은(는) 06:00 같은 시각이 아닙니다</translation>
    </message>
    <message>
        <location filename="../model/eol/ShiftPlan.cpp" line="35"/>
        <source>shift starts must be in order from the day&apos;s first: %1</source>
        <translation>근무조 시작 시각은 하루의 첫 근무조부터 순서대로 주어야 합니다: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/ShiftPlan.cpp" line="42"/>
        <source>no shift start given; e.g. 06:00,14:00,22:00</source>
        <translation>근무조 시작 시각이 없습니다. 예: 06:00,14:00,22:00</translation>
    </message>
</context>
<context>
    <name>opentop::ShortcutsDialog</name>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="63"/>
        <source>Main window</source>
        <translation>메인 창</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="36"/>
        <source>Everywhere, dialogs included</source>
        <translation>모든 곳(대화 상자 포함)</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="37"/>
        <source>STOP ALL (stop every drive on the bus)</source>
        <translation>전체 정지 (버스의 모든 드라이버 정지)</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="73"/>
        <source>Keyboard shortcuts</source>
        <translation>단축키</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="77"/>
        <source>Where</source>
        <translation>위치</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="77"/>
        <source>Command</source>
        <translation>명령</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="77"/>
        <source>Keys</source>
        <translation>키</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="87"/>
        <source> or </source>
        <translation> 또는 </translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="96"/>
        <source>STOP ALL&apos;s keys work in every window of the program, also while a dialog is open.</source>
        <translation>전체 정지 키는 대화 상자가 열려 있을 때도 프로그램의 모든 창에서 동작합니다.</translation>
    </message>
</context>
<context>
    <name>opentop::SimApp</name>
    <message>
        <location filename="../sim/SimApp.cpp" line="77"/>
        <source>opentop-sim: %1@%2 talks %3 (its own line settings): it answers only frames sent in that format</source>
        <translation>opentop-sim: %1@%2은(는) %3(자체 라인 설정)으로 통신합니다. 그 형식으로 보낸 프레임에만 응답합니다</translation>
    </message>
    <message>
        <location filename="../sim/SimApp.cpp" line="83"/>
        <source>opentop-sim: warning: %1@%2 cannot use %3 %4 and will not answer</source>
        <translation>opentop-sim: 경고: %1@%2은(는) %3 %4을(를) 사용할 수 없으므로 응답하지 않습니다</translation>
    </message>
    <message>
        <location filename="../sim/SimApp.cpp" line="97"/>
        <source>opentop-sim: --defect %1:%2: no drive with machine number %1 on the bus %3</source>
        <translation>opentop-sim: --defect %1:%2: 버스 %3에 국번 %1인 드라이버가 없습니다</translation>
    </message>
    <message>
        <location filename="../sim/SimApp.cpp" line="104"/>
        <source>opentop-sim: --defect %1 (%2@%1): %3</source>
        <translation>opentop-sim: --defect %1 (%2@%1): %3</translation>
    </message>
    <message>
        <location filename="../sim/SimApp.cpp" line="138"/>
        <source>the port is unplugged already</source>
        <translation>포트가 이미 분리되어 있습니다</translation>
    </message>
    <message>
        <location filename="../sim/SimApp.cpp" line="140"/>
        <source>unplugged</source>
        <translation>분리됨</translation>
    </message>
    <message>
        <location filename="../sim/SimApp.cpp" line="167"/>
        <source>error: %1</source>
        <translation>오류: %1</translation>
    </message>
</context>
<context>
    <name>opentop::SimBackdoor</name>
    <message>
        <location filename="../sim/SimBackdoor.cpp" line="17"/>
        <source>usage: set ID ADDR VALUE [fc]</source>
        <translation>사용법: set ID ADDR VALUE [fc]</translation>
    </message>
    <message>
        <location filename="../sim/SimBackdoor.cpp" line="18"/>
        <source>usage: get ID ADDR [fc]</source>
        <translation>사용법: get ID ADDR [fc]</translation>
    </message>
    <message>
        <location filename="../sim/SimBackdoor.cpp" line="21"/>
        <source>address must be 0..0xFFFF, got &apos;%1&apos;</source>
        <translation>주소는 0..0xFFFF여야 합니다. 입력값: &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../sim/SimBackdoor.cpp" line="27"/>
        <source>function must be 3, 4 or 6 (write-only), got &apos;%1&apos;</source>
        <translation>기능은 3, 4 또는 6(쓰기 전용)이어야 합니다. 입력값: &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../sim/SimBackdoor.cpp" line="40"/>
        <source>value must be -32768..65535, got &apos;%1&apos;</source>
        <translation>값은 -32768..65535여야 합니다. 입력값: &apos;%1&apos;</translation>
    </message>
</context>
<context>
    <name>opentop::SimBackend</name>
    <message>
        <location filename="../sim/SimBackend.cpp" line="24"/>
        <source>no simulated bus</source>
        <translation>시뮬레이션 버스 없음</translation>
    </message>
    <message>
        <location filename="../sim/SimBackend.cpp" line="47"/>
        <source>the simulated bus is not open</source>
        <translation>시뮬레이션 버스가 열려 있지 않습니다</translation>
    </message>
    <message>
        <location filename="../sim/SimBackend.cpp" line="53"/>
        <source>the simulated adapter was unplugged</source>
        <translation>시뮬레이션 어댑터가 분리되었습니다</translation>
    </message>
    <message>
        <location filename="../sim/SimBackend.cpp" line="85"/>
        <source>interrupted while waiting</source>
        <translation>대기 중 중단됨</translation>
    </message>
    <message>
        <location filename="../sim/SimBackend.cpp" line="92"/>
        <source>no reply within %1 ms</source>
        <translation>%1 ms 이내에 응답 없음</translation>
    </message>
</context>
<context>
    <name>opentop::SimBus</name>
    <message>
        <location filename="../sim/SimBus.cpp" line="38"/>
        <source>unknown device type &apos;%1&apos;; known: %2</source>
        <translation>알 수 없는 장치 유형 &apos;%1&apos;; 알려진 유형: %2</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="66"/>
        <location filename="../sim/SimBus.cpp" line="74"/>
        <source>%1@%2{%3}: %4</source>
        <translation>%1@%2{%3}: %4</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="107"/>
        <source>no device with machine number %1</source>
        <translation>국번 %1인 장치가 없습니다</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="118"/>
        <source>baud=%1: this drive talks at %2 bit/s</source>
        <translation>baud=%1: 이 드라이브의 통신 속도는 %2 bit/s입니다</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="126"/>
        <source>format=%1: this drive offers %2 only</source>
        <translation>format=%1: 이 드라이브는 %2만 제공합니다</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="132"/>
        <source>this simulated drive has no line settings of its own</source>
        <translation>이 시뮬레이션 드라이브에는 자체 라인 설정이 없습니다</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="145"/>
        <source>machine number %1 is outside 1..247</source>
        <translation>국번 %1이(가) 1..247 범위를 벗어납니다</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="146"/>
        <source>machine number %1 is used twice</source>
        <translation>국번 %1이(가) 두 번 사용되었습니다</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="317"/>
        <source>no device with machine number %1 (bus: %2)</source>
        <translation>국번 %1인 장치가 없습니다(버스: %2)</translation>
    </message>
</context>
<context>
    <name>opentop::SimConsole</name>
    <message>
        <location filename="../sim/SimConsole.cpp" line="32"/>
        <source>commands:
  help                      this text
  list                      the devices and their state
  alarm ID CODE             raise an alarm (DBU)
  warning ID CODE           raise a warning, CODE 0 clears it (DBU)
  load ID PERCENT           add to the load rate (DBU) or current (DC)
  vr ID RPM                 Ext-VR speed, used by SPno1 (DBU)
  input ID MASK             input terminals: X0..X3 (DBU), SQ1 SQ2 DE (DC)
  ignore-stop ID on|off     acknowledge stop commands but keep running (DBU)
  power-cycle ID            turn the device off and on
  get ID ADDR [fc]          show a register (fc 3, 4 or 6 for write-only)
  set ID ADDR VALUE [fc]    change a register without any check
  defect ID DEFECT[,...]    add defects to a drive (see --help), e.g.
                            defect 3 max_speed=800 or defect 4 alarm=0x07@2s
  defect ID clear           the drive has no defects again
  defects                   the drives&apos; defects
  motor ID [KEY=VALUE ...]  show or change a DC controller&apos;s motor and load,
                            e.g. motor 7 load=0.05 inertia=3e-4 (see --motor)
  unplug                    close the pty under its client (adapter pulled out)
  replug                    a new pty behind the same symlink
  quit                      stop the simulator</source>
        <translation>명령:
  help                      이 도움말
  list                      장치와 상태
  alarm ID CODE             알람 발생 (DBU)
  warning ID CODE           경고 발생, CODE 0이면 해제 (DBU)
  load ID PERCENT           부하율(DBU) 또는 전류(DC)에 더함
  vr ID RPM                 Ext-VR 속도, SPno1에서 사용 (DBU)
  input ID MASK             입력 단자: X0..X3 (DBU), SQ1 SQ2 DE (DC)
  ignore-stop ID on|off     정지 명령을 수신 확인만 하고 계속 운전 (DBU)
  power-cycle ID            장치 전원을 껐다 켬
  get ID ADDR [fc]          레지스터 표시 (fc 3, 4 또는 쓰기 전용은 6)
  set ID ADDR VALUE [fc]    검사 없이 레지스터 변경
  defect ID DEFECT[,...]    드라이버에 결함 추가 (--help 참조), 예:
                            defect 3 max_speed=800 또는 defect 4 alarm=0x07@2s
  defect ID clear           드라이버의 결함을 모두 제거
  defects                   드라이버의 결함 목록
  motor ID [KEY=VALUE ...]  DC 컨트롤러의 모터와 부하를 표시 또는 변경, 예:
                            motor 7 load=0.05 inertia=3e-4 (--motor 참조)
  unplug                    클라이언트가 쓰는 pty를 닫음 (어댑터 분리)
  replug                    같은 심볼릭 링크 뒤에 새 pty 생성
  quit                      시뮬레이터 종료</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="66"/>
        <source>bye</source>
        <translation>종료합니다</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="71"/>
        <source>%1 needs the pty server (--pty)</source>
        <translation>%1에는 pty 서버(--pty)가 필요합니다</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="82"/>
        <source>, defects: %1</source>
        <translation>, 결함: %1</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="95"/>
        <source>no drive has defects</source>
        <translation>결함이 있는 드라이버 없음</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="101"/>
        <source>unknown command &apos;%1&apos;; type help for the list</source>
        <translation>알 수 없는 명령 &apos;%1&apos;; 목록을 보려면 help를 입력하십시오</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="105"/>
        <source>usage: %1 ID ...; ID is a machine number on the bus (%2)</source>
        <translation>사용법: %1 ID ...; ID는 버스에 있는 국번입니다(%2)</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="111"/>
        <source>&apos;%1&apos; is not a machine number; the bus has %2</source>
        <translation>&apos;%1&apos;은(는) 국번이 아닙니다. 버스에 있는 국번: %2</translation>
    </message>
</context>
<context>
    <name>opentop::SimDefectSpec</name>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="45"/>
        <source>firmware=MAJOR.MINOR (e.g. firmware=1.4), max_speed=N (e.g. max_speed=800), stall, load=+N, load=-N or load=xF (e.g. load=+40, load=x1.5), alarm=CODE@TIME (e.g. alarm=0x07@1500ms, alarm=overload@2s; DC: alarm=stall@1s), nostick=PARAM, nostore=PARAM (a parameter name or register address, e.g. nostick=spno2.speed, nostore=0x0081), turnaround=MS (e.g. turnaround=14), clear</source>
        <translation>firmware=MAJOR.MINOR (예: firmware=1.4), max_speed=N (예: max_speed=800), stall, load=+N, load=-N 또는 load=xF (예: load=+40, load=x1.5), alarm=CODE@TIME (예: alarm=0x07@1500ms, alarm=overload@2s; DC: alarm=stall@1s), nostick=PARAM, nostore=PARAM (파라미터 이름 또는 레지스터 주소, 예: nostick=spno2.speed, nostore=0x0081), turnaround=MS (예: turnaround=14), clear</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="123"/>
        <source>unknown defect &quot;%1&quot;; allowed: %2</source>
        <translation>알 수 없는 결함 &quot;%1&quot;; 허용: %2</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="126"/>
        <source>&quot;%1&quot; needs a value: %2=...</source>
        <translation>&quot;%1&quot;에는 값이 필요합니다: %2=...</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="128"/>
        <source>&quot;%1&quot; takes no value; write %2</source>
        <translation>&quot;%1&quot;은(는) 값을 받지 않습니다. %2(으)로 쓰십시오</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="141"/>
        <source>firmware=%1: write MAJOR.MINOR with each 0..255, e.g. firmware=1.4</source>
        <translation>firmware=%1: 각각 0..255인 MAJOR.MINOR로 쓰십시오. 예: firmware=1.4</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="148"/>
        <source>max_speed=%1: write a whole number 0..%2, e.g. max_speed=800</source>
        <translation>max_speed=%1: 0..%2의 정수로 쓰십시오. 예: max_speed=800</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="158"/>
        <source>load=%1: a factor is x0.1..x10, e.g. load=x1.5</source>
        <translation>load=%1: 배율은 x0.1..x10입니다. 예: load=x1.5</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="163"/>
        <source>load=%1: an offset is -200..+200, e.g. load=+40</source>
        <translation>load=%1: 오프셋은 -200..+200입니다. 예: load=+40</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="166"/>
        <source>load=%1: write load=+N, load=-N (an offset) or load=xF (a factor), e.g. load=+40 or load=x1.5</source>
        <translation>load=%1: load=+N, load=-N (오프셋) 또는 load=xF (배율)로 쓰십시오. 예: load=+40 또는 load=x1.5</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="175"/>
        <source>alarm=%1: write alarm=CODE@TIME, e.g. alarm=0x07@1500ms or alarm=overload@2s</source>
        <translation>alarm=%1: alarm=CODE@TIME으로 쓰십시오. 예: alarm=0x07@1500ms 또는 alarm=overload@2s</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="180"/>
        <source>alarm=%1: the time after the start is 0..3600 s, written 1500ms, 1.5s or 1500 (ms)</source>
        <translation>alarm=%1: 기동 후 시간은 0..3600 s이며, 1500ms, 1.5s 또는 1500(ms)으로 씁니다</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="189"/>
        <source>turnaround=%1: write the answer delay in ms, 0..1000, e.g. turnaround=14</source>
        <translation>turnaround=%1: 응답 지연을 ms로 0..1000 범위에서 쓰십시오. 예: turnaround=14</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="194"/>
        <source>%1=%2: name a parameter (e.g. spno2.speed) or a register address (e.g. 0x1102)</source>
        <translation>%1=%2: 파라미터 이름(예: spno2.speed) 또는 레지스터 주소(예: 0x1102)를 지정하십시오</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="210"/>
        <source>no defect given; allowed: %1</source>
        <translation>결함이 지정되지 않았습니다. 허용: %1</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="216"/>
        <source>empty item in &quot;%1&quot;</source>
        <translation>&quot;%1&quot;에 빈 항목이 있습니다</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="234"/>
        <source>&quot;%1&quot;: write ID:DEFECT[,DEFECT...] with ID the machine number 1..247, e.g. 3:firmware=1.4 or 5:max_speed=800,load=+40</source>
        <translation>&quot;%1&quot;: ID:DEFECT[,DEFECT...] 형식으로 쓰십시오. ID는 국번 1..247. 예: 3:firmware=1.4 또는 5:max_speed=800,load=+40</translation>
    </message>
</context>
<context>
    <name>opentop::SimDefects</name>
    <message>
        <location filename="../sim/SimDefects.cpp" line="71"/>
        <source>a %1 reports no firmware version</source>
        <translation>%1은(는) 펌웨어 버전을 알려주지 않습니다</translation>
    </message>
    <message>
        <location filename="../sim/SimDefects.cpp" line="83"/>
        <source>alarm=%1: a %2 has no alarm codes; its protection is the stall stop: write alarm=stall@TIME</source>
        <translation>alarm=%1: %2에는 알람 코드가 없습니다. 보호 기능은 구속 정지입니다: alarm=stall@TIME으로 쓰십시오</translation>
    </message>
    <message>
        <location filename="../sim/SimDefects.cpp" line="99"/>
        <source>alarm=%1: not an alarm of a %2; allowed: %3</source>
        <translation>alarm=%1: %2의 알람이 아닙니다. 허용: %3</translation>
    </message>
    <message>
        <location filename="../sim/SimDefects.cpp" line="110"/>
        <source>%1=%2: no writable parameter of a %3 has this name or address; e.g. %4</source>
        <translation>%1=%2: %3에는 이 이름 또는 주소의 쓰기 가능한 파라미터가 없습니다. 예: %4</translation>
    </message>
</context>
<context>
    <name>opentop::SimDevice</name>
    <message>
        <location filename="../sim/SimDevice.cpp" line="248"/>
        <source>missing command</source>
        <translation>명령 없음</translation>
    </message>
    <message>
        <location filename="../sim/SimDevice.cpp" line="257"/>
        <source>slave %1 power cycled</source>
        <translation>슬레이브 %1 전원 재투입함</translation>
    </message>
    <message>
        <location filename="../sim/SimDevice.cpp" line="299"/>
        <source>usage: defect ID DEFECT[,DEFECT...] or defect ID clear; DEFECT: %1</source>
        <translation>사용법: defect ID DEFECT[,DEFECT...] 또는 defect ID clear; DEFECT: %1</translation>
    </message>
    <message>
        <location filename="../sim/SimDevice.cpp" line="306"/>
        <source>slave %1 defects: %2</source>
        <translation>슬레이브 %1 결함: %2</translation>
    </message>
    <message>
        <location filename="../sim/SimDevice.cpp" line="308"/>
        <source>none</source>
        <translation>없음</translation>
    </message>
    <message>
        <location filename="../sim/SimDevice.cpp" line="313"/>
        <source>&apos;%1&apos; is not supported by a %2 device</source>
        <translation>&apos;%1&apos;은(는) %2 장치에서 지원하지 않습니다</translation>
    </message>
</context>
<context>
    <name>opentop::SimOptions</name>
    <message>
        <location filename="../sim/SimOptions.cpp" line="14"/>
        <source>Usage: opentop-sim --devices SPEC [options]
Simulates Modbus RTU drives on a pseudo-terminal or as a Modbus TCP gateway.

  --devices SPEC     devices and machine numbers, e.g. dbu200@1,dbu400@150,dcpid@7
                     a drive&apos;s own line settings in braces, e.g.
                     dcpid@7{format=8E1,baud=19200}: it hears only frames sent in
                     that format (a pty passes the client&apos;s rate and parity on)
  --pty [PATH]       serve on a pty (default); PATH: also create this symlink
  --tcp HOST:PORT    serve Modbus TCP (HOST defaults to 127.0.0.1, PORT 0: any)
  --baud N           line speed for wire timing and device settings (19200); a
                     drive hears a frame only at its own rate and parity
  --parity N|E|O     line parity (N): the drives without settings of their own
                     are set to --baud and --parity
  --wire-timing      delay replies as a real line at --baud would
  --turnaround MS    device turnaround with --wire-timing (2)
  --half-duplex      with --wire-timing: a request overlapping a reply on the line
                     garbles both, one within 3.5 characters of a reply is lost
  --faults LIST      e.g. drop=0.02,crc=0.01,late=0.01,busy=0.01,late_ms=1000
  --seed N           seed of the fault injection (1)
  --defect ID:LIST   defects of drive ID (repeatable), LIST of:
                       firmware=MAJOR.MINOR  identification reports this version
                       max_speed=N           the motor saturates at N (DBU r/min,
                                             DC commutations/s), load high
                       stall                 the motor does not turn, load high
                       load=+N|-N|xF         load rate (DC: current %) off or scaled
                       alarm=CODE@TIME       alarm after TIME running, e.g.
                                             0x07@1500ms, overload@2s (DC: stall@1s)
                       nostick=PARAM         writes acknowledged, old value stays
                       nostore=PARAM         value lost at the next power cycle
                     e.g. --defect 3:firmware=1.4 --defect 5:max_speed=800,load=+40
  --motor LIST       the DC controllers&apos; motor and load, e.g. inertia=2e-4,load=0.05;
                     supply (V), resistance (ohm), no_load (1/s at full duty),
                     commutations (per revolution), inertia (kg m2), viscous
                     (N m s/rad), coulomb (N m), load (N m), gate (ms), tacho (V s)
  --quiet            no frame trace on stderr
  --lang CODE        language of messages: en, zh_TW, zh_CN, ko, ja
  --help             this text
  --version          the program&apos;s version

Prints &quot;pty: PATH&quot; (and &quot;tcp: HOST:PORT&quot;), then &quot;ready&quot;. Reads console commands
from stdin (type help). Stops on SIGINT, SIGTERM or quit.
</source>
        <translation>사용법: opentop-sim --devices SPEC [옵션]
Modbus RTU 드라이버를 가상 터미널 또는 Modbus TCP 게이트웨이로 시뮬레이션합니다.

  --devices SPEC     장치와 국번, 예: dbu200@1,dbu400@150,dcpid@7
                     드라이브 자체 라인 설정은 중괄호 안에. 예:
                     dcpid@7{format=8E1,baud=19200}: 그 형식으로 보낸
                     프레임만 받음 (pty는 클라이언트의 속도와 패리티를 전달)
  --pty [PATH]       pty로 서비스 (기본값); PATH: 이 심볼릭 링크도 생성
  --tcp HOST:PORT    Modbus TCP로 서비스 (HOST 기본값 127.0.0.1, PORT 0: 임의)
  --baud N           전송 타이밍과 장치 설정에 쓰는 통신 속도 (19200). 드라이브는
                     자체 속도와 패리티의 프레임만 받음
  --parity N|E|O     라인 패리티 (N): 자체 설정이 없는 드라이브는
                     --baud와 --parity로 설정됨
  --wire-timing      --baud의 실제 라인처럼 응답을 지연
  --turnaround MS    --wire-timing 사용 시 장치 응답 전환 시간 (2)
  --half-duplex      --wire-timing과 함께: 라인에서 요청이 응답과 겹치면
                     둘 다 깨지고, 응답과 3.5문자 이내인 요청은 손실됨
  --faults LIST      예: drop=0.02,crc=0.01,late=0.01,busy=0.01,late_ms=1000
  --seed N           결함 주입의 시드 (1)
  --defect ID:LIST   드라이버 ID의 결함 (반복 가능), LIST 항목:
                       firmware=MAJOR.MINOR  식별 시 이 버전을 알려줌
                       max_speed=N           모터가 N에서 포화 (DBU r/min,
                                             DC 정류 횟수/s), 부하 높음
                       stall                 모터가 회전하지 않음, 부하 높음
                       load=+N|-N|xF         부하율(DC: 전류 %)에 오프셋 또는 배율
                       alarm=CODE@TIME       TIME 동안 운전 후 알람, 예:
                                             0x07@1500ms, overload@2s (DC: stall@1s)
                       nostick=PARAM         쓰기는 수신 확인하지만 이전 값 유지
                       nostore=PARAM         다음 전원 재투입 시 값 손실
                     예: --defect 3:firmware=1.4 --defect 5:max_speed=800,load=+40
  --motor LIST       DC 컨트롤러의 모터와 부하, 예: inertia=2e-4,load=0.05;
                     supply (V), resistance (ohm), no_load (최대 듀티에서의 1/s),
                     commutations (1회전당 정류 횟수), inertia (kg m2), viscous
                     (N m s/rad), coulomb (N m), load (N m), gate (ms), tacho (V s)
  --quiet            stderr에 프레임 추적을 출력하지 않음
  --lang CODE        메시지 언어: en, zh_TW, zh_CN, ko, ja
  --help             이 도움말
  --version          프로그램 버전

&quot;pty: PATH&quot;(및 &quot;tcp: HOST:PORT&quot;)를 출력한 뒤 &quot;ready&quot;를 출력합니다. 콘솔 명령을
stdin에서 읽습니다(help 입력). SIGINT, SIGTERM 또는 quit으로 종료합니다.
</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="92"/>
        <source>--lang needs a language code such as ko</source>
        <translation>--lang에는 ko 같은 언어 코드가 필요합니다</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="95"/>
        <source>--devices needs a device list such as dbu200@1,dcpid@7</source>
        <translation>--devices에는 dbu200@1,dcpid@7 같은 장치 목록이 필요합니다</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="104"/>
        <source>--tcp needs HOST:PORT, e.g. 127.0.0.1:5020</source>
        <translation>--tcp에는 HOST:PORT가 필요합니다. 예: 127.0.0.1:5020</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="110"/>
        <source>--tcp needs HOST:PORT with PORT 0..65535, got &apos;%1&apos;</source>
        <translation>--tcp에는 PORT가 0..65535인 HOST:PORT가 필요합니다. 입력값: &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="122"/>
        <source>--baud must be one of %1, got &apos;%2&apos;</source>
        <translation>--baud는 %1 중 하나여야 합니다. 입력값: &apos;%2&apos;</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="129"/>
        <source>--parity must be N, E or O, got &apos;%1&apos;</source>
        <translation>--parity는 N, E 또는 O여야 합니다. 입력값: &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="139"/>
        <source>--turnaround must be 0..1000 ms, got &apos;%1&apos;</source>
        <translation>--turnaround는 0..1000 ms여야 합니다. 입력값: &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="143"/>
        <source>--faults needs a list such as drop=0.02,crc=0.01</source>
        <translation>--faults에는 drop=0.02,crc=0.01 같은 목록이 필요합니다</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="147"/>
        <source>--faults: %1</source>
        <translation>--faults: %1</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="153"/>
        <source>--seed must be a whole number 0..4294967295, got &apos;%1&apos;</source>
        <translation>--seed는 0..4294967295의 정수여야 합니다. 입력값: &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="157"/>
        <source>--defect needs ID:DEFECT[,DEFECT...], e.g. 3:firmware=1.4; DEFECT: %1</source>
        <translation>--defect에는 ID:DEFECT[,DEFECT...]가 필요합니다. 예: 3:firmware=1.4; DEFECT: %1</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="164"/>
        <source>--defect: %1</source>
        <translation>--defect: %1</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="168"/>
        <source>--motor needs a list such as inertia=2e-4,load=0.05</source>
        <translation>--motor에는 inertia=2e-4,load=0.05 같은 목록이 필요합니다</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="172"/>
        <source>--motor: %1</source>
        <translation>--motor: %1</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="177"/>
        <source>unknown argument &apos;%1&apos;; options: --devices, --pty, --tcp, --baud, --parity, --wire-timing, --half-duplex, --turnaround, --faults, --seed, --defect, --motor, --quiet, --help, --version</source>
        <translation>알 수 없는 인수 &apos;%1&apos;; 옵션: --devices, --pty, --tcp, --baud, --parity, --wire-timing, --half-duplex, --turnaround, --faults, --seed, --defect, --motor, --quiet, --help, --version</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="186"/>
        <source>--devices SPEC is required, e.g. --devices dbu200@1,dcpid@7</source>
        <translation>--devices SPEC이 필요합니다. 예: --devices dbu200@1,dcpid@7</translation>
    </message>
</context>
<context>
    <name>opentop::SpeedDisplay</name>
    <message>
        <location filename="../model/profile/SpeedDisplay.cpp" line="90"/>
        <source>speed display settings not known: %1</source>
        <translation>속도 표시 설정을 알 수 없습니다: %1</translation>
    </message>
    <message>
        <location filename="../model/profile/SpeedDisplay.cpp" line="92"/>
        <source>speed display unit code %1 is unknown (0–3)</source>
        <translation>속도 표시 단위 코드 %1을(를) 알 수 없습니다(0–3)</translation>
    </message>
    <message>
        <location filename="../model/profile/SpeedDisplay.cpp" line="94"/>
        <source>speed display ratios must be positive (reduction %1, increase %2)</source>
        <translation>속도 표시 비율은 양수여야 합니다(감속비 %1, 증속비 %2)</translation>
    </message>
    <message>
        <location filename="../model/profile/SpeedDisplay.cpp" line="98"/>
        <source>speed display decimals %1 outside 0–3</source>
        <translation>속도 표시 소수 자릿수 %1이(가) 0–3을 벗어납니다</translation>
    </message>
</context>
<context>
    <name>opentop::SpeedUnitsPage</name>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="36"/>
        <source>Speed display</source>
        <translation>속도 표시</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="52"/>
        <source>Unit shown</source>
        <translation>표시 단위</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="53"/>
        <source>&amp;Unit:</source>
        <translation>단위(&amp;U):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="54"/>
        <source>Reduction r&amp;atio:</source>
        <translation>감속비(&amp;A):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="55"/>
        <source>&amp;Increasing ratio:</source>
        <translation>증속비(&amp;I):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="60"/>
        <source>Linear speed</source>
        <translation>선속도</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="61"/>
        <source>Roller diameter for &amp;yd/min:</source>
        <translation>yd/min용 롤러 직경(&amp;Y):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="62"/>
        <source>Roller diameter for &amp;m/min:</source>
        <translation>m/min용 롤러 직경(&amp;M):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="65"/>
        <source>Time for a distance</source>
        <translation>거리 이동 시간</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="66"/>
        <source>Roller &amp;diameter:</source>
        <translation>롤러 직경(&amp;D):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="67"/>
        <source>Dis&amp;tance:</source>
        <translation>거리(&amp;T):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="68"/>
        <source>Distance u&amp;nit:</source>
        <translation>거리 단위(&amp;N):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="69"/>
        <source>Time &amp;format (min = m:ss):</source>
        <translation>시간 형식(&amp;F) (min = m:ss):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="72"/>
        <source>Display</source>
        <translation>표시</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="73"/>
        <source>D&amp;ecimals (0–3):</source>
        <translation>소수 자릿수(&amp;E) (0–3):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="74"/>
        <source>U&amp;pdate time:</source>
        <translation>갱신 시간(&amp;P):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="78"/>
        <source>Display corrections (motor r/min)</source>
        <translation>표시 보정 (모터 r/min)</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="79"/>
        <source>ro-&amp;0, 250 (300)–500 r/min:</source>
        <translation>ro-0(&amp;0), 250 (300)–500 r/min:</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="79"/>
        <source>ro-&amp;1, 501–1000 r/min:</source>
        <translation>ro-1(&amp;1), 501–1000 r/min:</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="80"/>
        <source>ro-&amp;2, 1001–2000 r/min:</source>
        <translation>ro-2(&amp;2), 1001–2000 r/min:</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="80"/>
        <source>ro-&amp;3, 2001–3000 r/min:</source>
        <translation>ro-3(&amp;3), 2001–3000 r/min:</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="85"/>
        <source>Preview of the drive&apos;s display</source>
        <translation>드라이버 표시 미리 보기</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="88"/>
        <source> r/min</source>
        <translation> r/min</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="89"/>
        <source>Motor speed for the preview</source>
        <translation>미리 보기용 모터 속도</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="90"/>
        <source>Motor &amp;speed:</source>
        <translation>모터 속도(&amp;S):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="93"/>
        <source>Forward</source>
        <translation>정회전</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="94"/>
        <source>Reverse (shown with “-”)</source>
        <translation>역회전 (“-”로 표시)</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="95"/>
        <source>Dire&amp;ction:</source>
        <translation>방향(&amp;C):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="110"/>
        <source>Drive shows:</source>
        <translation>드라이버 표시:</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="214"/>
        <source>yd</source>
        <translation>yd</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="214"/>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="255"/>
        <source>Drive shows %1 %2</source>
        <translation>드라이버 표시 %1 %2</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="259"/>
        <source>Section ro-%1: correction %2 r/min, shaft speed %3 r/min.</source>
        <translation>구간 ro-%1: 보정 %2 r/min, 축 속도 %3 r/min.</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="264"/>
        <source>%1 has more digits than the drive&apos;s %2-digit display can show.</source>
        <translation>%1은(는) 드라이버의 %2자리 표시부로 나타낼 수 있는 자릿수를 넘습니다.</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="268"/>
        <source>Computed %1 %2; the %3-digit display drops the decimals that do not fit.</source>
        <translation>계산값 %1 %2; %3자리 표시부에서는 넘치는 소수 자리가 잘립니다.</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="275"/>
        <source>Includes edits not yet written.</source>
        <translation>아직 쓰지 않은 편집이 포함되어 있습니다.</translation>
    </message>
</context>
<context>
    <name>opentop::SpnoSelector</name>
    <message>
        <location filename="../ui/run/SpnoSelector.cpp" line="29"/>
        <source>The running data that Select running data sends; &quot;The drive now&quot; shows the running data the drive runs</source>
        <translation>운전 데이터 선택이 보내는 운전 데이터입니다. &quot;현재 드라이버&quot;에 드라이버가 실행 중인 운전 데이터가 표시됩니다</translation>
    </message>
    <message>
        <location filename="../ui/run/SpnoSelector.cpp" line="70"/>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <location filename="../ui/run/SpnoSelector.cpp" line="84"/>
        <source>The running data that Select running data sends. The drive reported SPno%1 at %2; &quot;The drive now&quot; shows what it runs now.</source>
        <translation>운전 데이터 선택이 보내는 운전 데이터입니다. 드라이버는 %2에 SPno%1을(를) 보고했습니다. 지금 실행 중인 것은 &quot;현재 드라이버&quot;에 표시됩니다.</translation>
    </message>
</context>
<context>
    <name>opentop::StaleLook</name>
    <message>
        <location filename="../ui/widgets/StaleLook.cpp" line="52"/>
        <source>not read yet</source>
        <translation>아직 읽지 않음</translation>
    </message>
    <message>
        <location filename="../ui/widgets/StaleLook.cpp" line="55"/>
        <source>updated %1 s ago</source>
        <translation>%1초 전 갱신</translation>
    </message>
</context>
<context>
    <name>opentop::StartPreview</name>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="110"/>
        <source>CCW</source>
        <translation>CCW</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="110"/>
        <source>CW</source>
        <translation>CW</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="154"/>
        <source>communication group of %1</source>
        <translation>%1의 통신 그룹</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="182"/>
        <source>It runs with running data SPno%1</source>
        <translation>기동 시 운전 데이터: SPno%1</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="184"/>
        <source> at %1</source>
        <translation> (%1)</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="187"/>
        <source>, direction %1 (the direction command sent since)</source>
        <translation>, 방향 %1 (이후 보낸 방향 명령)</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="188"/>
        <source>, direction %1</source>
        <translation>, 방향 %1</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="191"/>
        <source>Which running data it runs with could not be read.</source>
        <translation>어떤 운전 데이터로 운전할지 읽을 수 없습니다.</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="194"/>
        <source>Warning: %1</source>
        <translation>경고: %1</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="196"/>
        <source>The start also reaches machine number(s) %1: %2.</source>
        <translation>기동 명령은 국번 %1에도 전달됩니다: %2.</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="202"/>
        <source>Not read: %1.</source>
        <translation>읽지 않음: %1.</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="219"/>
        <source>This starts the motor of machine number %1.</source>
        <translation>국번 %1의 모터를 기동합니다.</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="221"/>
        <source>This sets the speed command of machine number %1 to %2: its motor runs.</source>
        <translation>국번 %1의 속도 명령을 %2(으)로 설정합니다: 모터가 운전합니다.</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="225"/>
        <source>Make sure that nobody is near the machine and that it may move. STOP ALL stops every drive at any time.</source>
        <translation>설비 주변에 사람이 없고 설비가 움직여도 되는지 확인하십시오. 전체 정지로 언제든지 모든 드라이버를 정지할 수 있습니다.</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="228"/>
        <source>You are asked once per drive while the program runs.</source>
        <translation>프로그램 실행 중 드라이버마다 한 번씩 확인합니다.</translation>
    </message>
</context>
<context>
    <name>opentop::StationAccess</name>
    <message>
        <location filename="../model/access/StationAccess.cpp" line="74"/>
        <location filename="../model/access/StationAccess.cpp" line="127"/>
        <source>the results database is not open</source>
        <translation>결과 데이터베이스가 열려 있지 않습니다</translation>
    </message>
    <message>
        <location filename="../model/access/StationAccess.cpp" line="105"/>
        <source>the results database is not open, so nobody can be identified</source>
        <translation>결과 데이터베이스가 열려 있지 않아 누구도 확인할 수 없습니다</translation>
    </message>
    <message>
        <location filename="../model/access/StationAccess.cpp" line="160"/>
        <source>the station&apos;s users are being read from the results database</source>
        <translation>결과 데이터베이스에서 스테이션 사용자를 읽는 중입니다</translation>
    </message>
    <message>
        <location filename="../model/access/StationAccess.cpp" line="161"/>
        <source>the station&apos;s users cannot be read: %1</source>
        <translation>스테이션 사용자를 읽을 수 없습니다: %1</translation>
    </message>
    <message>
        <location filename="../model/access/StationAccess.cpp" line="166"/>
        <source>nobody is logged in: log in with your user name and password (or badge)</source>
        <translation>로그인한 사람이 없습니다: 사용자 이름과 비밀번호(또는 사원증)로 로그인하십시오</translation>
    </message>
    <message>
        <location filename="../model/access/StationAccess.cpp" line="170"/>
        <source>the recipe&apos;s approval is being read from the results database</source>
        <translation>결과 데이터베이스에서 레시피 승인을 읽는 중입니다</translation>
    </message>
</context>
<context>
    <name>opentop::StationActions</name>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="24"/>
        <source>Reset alarm and test again</source>
        <translation>알람 리셋 후 다시 검사</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="25"/>
        <source>Technician: test again…</source>
        <translation>기술자: 다시 검사…</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="50"/>
        <source>A technician may allow unit %1 to be tested again.</source>
        <translation>기술자가 유닛 %1의 재시험을 허가할 수 있습니다.</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="57"/>
        <source>Resetting the alarm of machine number %1…</source>
        <translation>국번 %1의 알람을 리셋하는 중…</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="66"/>
        <source>The alarm is not cleared; nothing was started:
%1</source>
        <translation>알람이 해제되지 않았습니다. 아무것도 시작하지 않았습니다:
%1</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="76"/>
        <source>reset the alarm</source>
        <translation>알람 리셋</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="82"/>
        <source>serial %1</source>
        <translation>시리얼 %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="91"/>
        <source>test serial %1 again</source>
        <translation>시리얼 %1 재시험</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="105"/>
        <source>An alarm was active on machine number %1 before the test: nothing was written. Reset it (the drive&apos;s own reset; one that needs a power cycle says so) and the unit is tested again.</source>
        <translation>검사 전에 국번 %1에 알람이 발생해 있었습니다. 아무것도 쓰지 않았습니다. 알람을 리셋하면(드라이버 자체의 리셋 사용, 전원 재투입이 필요한 알람은 따로 표시됨) 제품을 다시 검사합니다.</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="134"/>
        <source>(no name)</source>
        <translation>(이름 없음)</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="136"/>
        <source>Test again</source>
        <translation>다시 검사</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="137"/>
        <source>%1

Test unit %2 again? It is recorded as allowed by %3.</source>
        <translation>%1

제품 %2을(를) 다시 검사하시겠습니까? %3이(가) 허가한 것으로 기록됩니다.</translation>
    </message>
</context>
<context>
    <name>opentop::StationAlarmReset</name>
    <message>
        <location filename="../model/eol/StationAlarmReset.cpp" line="56"/>
        <source>machine number %1: not connected to a bus</source>
        <translation>국번 %1: 버스에 연결되어 있지 않음</translation>
    </message>
    <message>
        <location filename="../model/eol/StationAlarmReset.cpp" line="57"/>
        <source>machine number %1 is not a position of the recipe</source>
        <translation>국번 %1은(는) 레시피에 있는 위치가 아닙니다</translation>
    </message>
    <message>
        <location filename="../model/eol/StationAlarmReset.cpp" line="65"/>
        <source>machine number %1: %2 drives have no alarm reset command; switch the drive off and on</source>
        <translation>국번 %1: %2 드라이버에는 알람 리셋 명령이 없습니다. 드라이버 전원을 껐다 켜십시오</translation>
    </message>
    <message>
        <location filename="../model/eol/StationAlarmReset.cpp" line="75"/>
        <source>machine number %1: %2</source>
        <translation>국번 %1: %2</translation>
    </message>
</context>
<context>
    <name>opentop::StationFigures</name>
    <message>
        <location filename="../ui/eol/StationFigures.cpp" line="27"/>
        <source>This shift: no figures yet (%1)</source>
        <translation>이번 근무조: 아직 집계 없음 (%1)</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationFigures.cpp" line="28"/>
        <source>results database not read</source>
        <translation>결과 데이터베이스를 아직 읽지 않음</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationFigures.cpp" line="31"/>
        <source>This shift: tested %1 · passed %2 · failed %3 · station errors %4 · %5</source>
        <translation>이번 근무조: 검사 %1 · 합격 %2 · 불합격 %3 · 스테이션 오류 %4 · %5</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationFigures.cpp" line="39"/>
        <source>This station, this recipe version, since %1 (read %2). The same figures: %3</source>
        <translation>이 스테이션, 이 레시피 버전, %1 이후 (%2에 읽음). 같은 수치를 보는 명령: %3</translation>
    </message>
</context>
<context>
    <name>opentop::StationLogin</name>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="38"/>
        <source>operator</source>
        <translation>작업자</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="40"/>
        <source>Operator:</source>
        <translation>작업자:</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="44"/>
        <source>user name</source>
        <translation>사용자 이름</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="49"/>
        <source>password</source>
        <translation>비밀번호</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="51"/>
        <source>Log in</source>
        <translation>로그인</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="52"/>
        <source>Log in:</source>
        <translation>로그인:</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="57"/>
        <source>Log out</source>
        <translation>로그아웃</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="104"/>
        <source>Not logged in: %1</source>
        <translation>로그인하지 못했습니다: %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="125"/>
        <source>Logged in: &lt;b&gt;%1&lt;/b&gt; (%2)</source>
        <translation>로그인: &lt;b&gt;%1&lt;/b&gt;(%2)</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="131"/>
        <source>No users set up: anyone can run, edit and leave; set up users with opentop-cli eol user add</source>
        <translation>사용자가 설정되지 않았습니다: 누구나 실행, 편집, 종료할 수 있습니다. opentop-cli eol user add로 사용자를 설정하십시오</translation>
    </message>
</context>
<context>
    <name>opentop::StationNotice</name>
    <message numerus="yes">
        <location filename="../ui/eol/StationNotice.cpp" line="31"/>
        <source>%n result(s) kept on this station, not yet in the results database: %1. They are sent by themselves, in order, when it answers.</source>
        <translation>
            <numerusform>이 스테이션에 결과 %n건이 보관되어 있으며 아직 결과 데이터베이스에 없습니다: %1. 데이터베이스가 응답하면 순서대로 자동 전송됩니다.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/eol/StationNotice.cpp" line="35"/>
        <source>it does not answer</source>
        <translation>데이터베이스가 응답하지 않습니다</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationNotice.cpp" line="38"/>
        <source>Unit %1 (begun %2) was not finished: the station stopped during its test. It is recorded as interrupted; test it again.</source>
        <translation>유닛 %1(%2 시작)이 완료되지 않았습니다: 검사 중에 스테이션이 멈췄습니다. &apos;중단됨&apos;으로 기록되었으니 다시 검사하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationNotice.cpp" line="44"/>
        <source>Making the recipe&apos;s drives safe: reading each, stopping one left running, giving control back to their inputs…</source>
        <translation>레시피의 드라이브를 안전 상태로 만드는 중: 하나씩 읽고, 운전 중인 것을 정지하고, 제어를 입력 단자로 되돌립니다…</translation>
    </message>
</context>
<context>
    <name>opentop::StationRecipe</name>
    <message>
        <location filename="../model/station/StationRecipe.cpp" line="68"/>
        <source>this recipe takes per-unit values from a CSV file: open it first</source>
        <translation>이 레시피는 제품별 값을 CSV 파일에서 가져옵니다: 먼저 그 파일을 여십시오</translation>
    </message>
</context>
<context>
    <name>opentop::StationResults</name>
    <message>
        <location filename="../model/station/StationResults.cpp" line="63"/>
        <source>opening the results database</source>
        <translation>결과 데이터베이스를 여는 중</translation>
    </message>
    <message>
        <location filename="../model/station/StationResults.cpp" line="65"/>
        <source>NOT REACHABLE (%1); trying again by itself</source>
        <translation>연결할 수 없음(%1). 자동으로 다시 시도하는 중</translation>
    </message>
    <message>
        <location filename="../model/station/StationResults.cpp" line="66"/>
        <source>no results database</source>
        <translation>결과 데이터베이스 없음</translation>
    </message>
    <message>
        <location filename="../model/station/StationResults.cpp" line="72"/>
        <source>the result of unit %1 (%2) is not in the results database yet: nothing is tested until it is. The station tries again by itself (%3)</source>
        <translation>제품 %1의 결과(%2)가 아직 결과 데이터베이스에 기록되지 않았습니다. 기록될 때까지 검사하지 않습니다. 스테이션이 자동으로 다시 시도합니다(%3)</translation>
    </message>
    <message>
        <location filename="../model/station/StationResults.cpp" line="77"/>
        <source>the results database is being opened; try again in a moment</source>
        <translation>결과 데이터베이스를 여는 중입니다. 잠시 후 다시 시도하십시오</translation>
    </message>
    <message>
        <location filename="../model/station/StationResults.cpp" line="79"/>
        <source>the results database is not open; nothing is tested unless it is recorded</source>
        <translation>결과 데이터베이스가 열려 있지 않습니다. 기록할 수 없으면 검사하지 않습니다</translation>
    </message>
    <message>
        <location filename="../model/station/StationResults.cpp" line="80"/>
        <source>the results database cannot be reached (%1); nothing is tested unless it is recorded. The station tries again by itself.</source>
        <translation>결과 데이터베이스에 연결할 수 없습니다(%1). 기록할 수 없으면 검사하지 않습니다. 스테이션이 자동으로 다시 시도합니다.</translation>
    </message>
</context>
<context>
    <name>opentop::StationSafeState</name>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="44"/>
        <source>%1: no answer (%2); not checked</source>
        <translation>%1: 응답 없음(%2), 확인하지 않음</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="49"/>
        <source>%1 was RUNNING (%2)</source>
        <translation>%1이(가) 운전 중이었습니다(%2)</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="52"/>
        <source>: stopped by the station</source>
        <translation>: 스테이션이 정지시켰습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="55"/>
        <source>%1 stopped</source>
        <translation>%1 정지 상태</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="58"/>
        <source>; control given back to its inputs (I/O priority)</source>
        <translation>; 제어를 입력 단자로 되돌렸습니다(I/O 우선)</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="99"/>
        <source>drive %1</source>
        <translation>드라이브 %1</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="100"/>
        <source>drive %1 (%2)</source>
        <translation>드라이브 %1(%2)</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="104"/>
        <source>the recipe&apos;s family %1 is not known</source>
        <translation>레시피의 제품군 %1을(를) 알 수 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="148"/>
        <source>whether its motor runs cannot be read</source>
        <translation>모터가 운전 중인지 읽을 수 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="159"/>
        <source>it runs from its input terminals (I/O priority): not the station&apos;s to stop; stop it at the machine</source>
        <translation>입력 단자로 운전 중입니다(I/O 우선): 스테이션이 정지할 대상이 아닙니다. 기계에서 정지하십시오</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="184"/>
        <source>the stop was refused: %1</source>
        <translation>정지 명령이 거부되었습니다: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="198"/>
        <source>NOT CONFIRMED STOPPED: %1</source>
        <translation>정지 미확인: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="240"/>
        <source>control could not be given back to its inputs: %1</source>
        <translation>제어를 입력 단자로 되돌릴 수 없습니다: %1</translation>
    </message>
</context>
<context>
    <name>opentop::StationYield</name>
    <message>
        <location filename="../model/eol/StationYield.cpp" line="48"/>
        <source>the results database is not open</source>
        <translation>결과 데이터베이스가 열려 있지 않습니다</translation>
    </message>
</context>
<context>
    <name>opentop::StatusLight</name>
    <message>
        <location filename="../ui/widgets/StatusLight.cpp" line="30"/>
        <source>Status not known yet</source>
        <translation>상태 아직 알 수 없음</translation>
    </message>
    <message>
        <location filename="../ui/widgets/StatusLight.cpp" line="44"/>
        <source>Status light %1: %2</source>
        <translation>상태등 %1: %2</translation>
    </message>
    <message>
        <location filename="../ui/widgets/StatusLight.cpp" line="48"/>
        <source>The drive&apos;s manual: %1</source>
        <translation>드라이버 매뉴얼: %1</translation>
    </message>
</context>
<context>
    <name>opentop::StepMeasure</name>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="85"/>
        <source>%1: the drive stopped answering: %2</source>
        <translation>%1: 드라이버가 응답하지 않습니다: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="93"/>
        <source>%1: the drive raised an alarm while running</source>
        <translation>%1: 운전 중 드라이버에서 알람이 발생했습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="113"/>
        <source>%1: %2 %3</source>
        <translation>%1: %2 %3</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="132"/>
        <source>%1: the drive has no speed to wait for</source>
        <translation>%1: 드라이버에 기다릴 속도가 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="155"/>
        <source>time to reach speed</source>
        <translation>속도 도달 시간</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="159"/>
        <location filename="../model/eol/StepMeasure.cpp" line="167"/>
        <location filename="../model/eol/StepMeasure.cpp" line="299"/>
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="168"/>
        <source>unknown</source>
        <translation>알 수 없음</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="169"/>
        <source>%1: did not reach %2 %3 ±%4 %3 within %5 s (last read %6 %3)</source>
        <translation>%1: %5 s 이내에 %2 %3 ±%4 %3에 도달하지 못했습니다(마지막 읽은 값 %6 %3)</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="170"/>
        <source>its target</source>
        <translation>목표 속도</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="205"/>
        <location filename="../model/eol/StepMeasure.cpp" line="220"/>
        <location filename="../model/eol/StepMeasure.cpp" line="240"/>
        <location filename="../model/eol/StepMeasure.cpp" line="301"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="215"/>
        <source>%1: the drive reports no alarms</source>
        <translation>%1: 드라이버가 알람을 알려주지 않습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="225"/>
        <source>alarms raised</source>
        <translation>알람 발생</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="227"/>
        <source>%1: the drive has an alarm</source>
        <translation>%1: 드라이버에 알람이 있습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="234"/>
        <source>%1: nothing to read</source>
        <translation>%1: 읽을 항목이 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="248"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="251"/>
        <source>%1: %2 reads &quot;%3&quot;, expected &quot;%4&quot;</source>
        <translation>%1: %2 읽은 값 &quot;%3&quot;, 기대값 &quot;%4&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="259"/>
        <source>%1: %2 reads %3 %4, %5</source>
        <translation>%1: %2 읽은 값 %3 %4, %5</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="299"/>
        <source>time to stop</source>
        <translation>정지 시간</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="303"/>
        <source>%1: stopped after %2 s, allowed at most %3 s</source>
        <translation>%1: %2 s 후 정지, 허용 최대 %3 s</translation>
    </message>
</context>
<context>
    <name>opentop::StepMetrics</name>
    <message>
        <location filename="../model/tuning/StepMetrics.cpp" line="18"/>
        <source>the step has no height (from = to)</source>
        <translation>스텝 크기가 0입니다(from = to)</translation>
    </message>
    <message>
        <location filename="../model/tuning/StepMetrics.cpp" line="19"/>
        <source>too few samples after the step (%1)</source>
        <translation>스텝 이후 샘플이 너무 적습니다(%1)</translation>
    </message>
</context>
<context>
    <name>opentop::StepTest</name>
    <message>
        <location filename="../model/tuning/StepTest.cpp" line="39"/>
        <source>a step test runs forward from one speed to another: from and to must differ and be 0 or more</source>
        <translation>스텝 시험은 한 속도에서 다른 속도로 정회전합니다: 시작 속도와 목표 속도는 서로 달라야 하며 0 이상이어야 합니다</translation>
    </message>
    <message>
        <location filename="../model/tuning/StepTest.cpp" line="47"/>
        <source>%1 %2 is beyond the test&apos;s speed limit %3 %2</source>
        <translation>%1 %2이(가) 시험 속도 한계값 %3 %2을(를) 넘습니다</translation>
    </message>
    <message>
        <location filename="../model/tuning/StepTest.cpp" line="55"/>
        <source>Running to %1 %2</source>
        <translation>%1 %2까지 운전하는 중</translation>
    </message>
    <message>
        <location filename="../model/tuning/StepTest.cpp" line="88"/>
        <source>Step to %1 %2</source>
        <translation>%1 %2(으)로 스텝</translation>
    </message>
</context>
<context>
    <name>opentop::StepTestPanel</name>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="22"/>
        <source>Run step test…</source>
        <translation>스텝 시험 실행…</translation>
    </message>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="29"/>
        <source>From:</source>
        <translation>시작:</translation>
    </message>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="30"/>
        <source>To:</source>
        <translation>목표:</translation>
    </message>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="31"/>
        <source>Record time:</source>
        <translation>기록 시간:</translation>
    </message>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="32"/>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="75"/>
        <source>Enter two different speeds of 0 %1 or more.</source>
        <translation>0 %1 이상의 서로 다른 두 속도를 입력하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="79"/>
        <source>Enter a record time of 100–60000 ms.</source>
        <translation>기록 시간을 100–60000 ms로 입력하십시오.</translation>
    </message>
</context>
<context>
    <name>opentop::StopAllButton</name>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="16"/>
        <location filename="../ui/run/StopAllButton.cpp" line="92"/>
        <source>STOP ALL</source>
        <translation>전체 정지</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="20"/>
        <source>Stops every drive on the bus at once (%1), then checks that each has stopped.</source>
        <translation>버스의 모든 드라이버를 한 번에 정지한 뒤(%1) 각 드라이버가 정지했는지 확인합니다.</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="87"/>
        <source>STOPPING…</source>
        <translation>정지 중…</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="103"/>
        <source>The stop broadcast to %1 drives FAILED: %2</source>
        <translation>드라이버 %1대에 보낸 정지 브로드캐스트 실패: %2</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="106"/>
        <source>Stop sent to every drive. No drives are known on the bus, so none was checked; scan the bus to have them checked.</source>
        <translation>모든 드라이버에 정지를 보냈습니다. 버스에 알려진 드라이버가 없어 확인하지 않았습니다. 확인하려면 버스를 스캔하십시오.</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="114"/>
        <source>Machine number %1: stopped after %2 s</source>
        <translation>국번 %1: %2 s 후 정지</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="117"/>
        <source>Machine number %1: STILL RUNNING (%2)</source>
        <translation>국번 %1: 아직 운전 중 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="120"/>
        <source>Machine number %1: NO ANSWER, not confirmed stopped</source>
        <translation>국번 %1: 응답 없음, 정지 확인 안 됨</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="135"/>
        <source>STOP ALL: the stop broadcast FAILED</source>
        <translation>전체 정지: 정지 브로드캐스트 실패</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="136"/>
        <source>STOP ALL: stop sent, no drive checked</source>
        <translation>전체 정지: 정지 보냄, 확인한 드라이버 없음</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="137"/>
        <source>STOP ALL: every drive stopped</source>
        <translation>전체 정지: 모든 드라이버 정지</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="138"/>
        <source>STOP ALL: not every drive is confirmed stopped</source>
        <translation>전체 정지: 정지 확인되지 않은 드라이버 있음</translation>
    </message>
</context>
<context>
    <name>opentop::StopAllCommand</name>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="54"/>
        <source>Broadcast stop to every drive, then confirm each has stopped (needs --yes)</source>
        <translation>모든 드라이버에 정지를 브로드캐스트한 뒤 각 드라이버의 정지를 확인합니다(--yes 필요)</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="60"/>
        <source>Send the stop broadcast.</source>
        <translation>정지 브로드캐스트를 보냅니다.</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="62"/>
        <source>Machine numbers to confirm, e.g. 1,2,5-7 (default on a simulated bus: its drives).</source>
        <translation>정지를 확인할 국번, 예: 1,2,5-7 (시뮬레이션 버스의 기본값: 그 버스의 드라이버).</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="63"/>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="72"/>
        <source>error: usage: %1 (no other arguments)</source>
        <translation>오류: 사용법: %1 (다른 인수 없음)</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="80"/>
        <source>error: --ids: %1</source>
        <translation>오류: --ids: %1</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="87"/>
        <source>Would broadcast to every drive on the bus (machine number 0, no reply):</source>
        <translation>버스의 모든 드라이버에 브로드캐스트할 명령(국번 0, 응답 없음):</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="91"/>
        <source>Add --yes to send it.</source>
        <translation>보내려면 --yes를 추가하십시오.</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="119"/>
        <source>Broadcast %1: %2</source>
        <translation>브로드캐스트 %1: %2</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="120"/>
        <source>Broadcast %1 FAILED: %2: %3</source>
        <translation>브로드캐스트 %1 실패: %2: %3</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="124"/>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="124"/>
        <source>Family</source>
        <translation>제품군</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="124"/>
        <source>State</source>
        <translation>상태</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="124"/>
        <source>Speed</source>
        <translation>속도</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="124"/>
        <source>After</source>
        <translation>이후</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="124"/>
        <source>Detail</source>
        <translation>상세</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="156"/>
        <source>Only the broadcast was sent: drives do not answer a broadcast, so nothing confirms that they stopped. To confirm, pass the machine numbers on this bus, e.g. --ids 1,2,5-7 (opentop-cli scan finds them).</source>
        <translation>브로드캐스트만 보냈습니다: 드라이버는 브로드캐스트에 응답하지 않으므로 정지를 확인할 수 없습니다. 확인하려면 이 버스의 국번을 지정하십시오. 예: --ids 1,2,5-7 (opentop-cli scan으로 찾을 수 있음).</translation>
    </message>
</context>
<context>
    <name>opentop::StopConfirmer</name>
    <message>
        <location filename="../model/run/StopConfirmer.cpp" line="80"/>
        <source>%1 drives report neither running state nor speed</source>
        <translation>%1 드라이버는 운전 상태도 속도도 알려주지 않습니다</translation>
    </message>
    <message>
        <location filename="../model/run/StopConfirmer.cpp" line="111"/>
        <source>%1 is %2: the drive does not take motion commands over the bus (it follows its input terminals)</source>
        <translation>%1이(가) %2입니다: 드라이버가 버스를 통한 운전 명령을 받지 않습니다(입력 단자를 따름)</translation>
    </message>
    <message>
        <location filename="../model/run/StopConfirmer.cpp" line="185"/>
        <source>still at %1 after %2 s</source>
        <translation>%2 s 후에도 %1</translation>
    </message>
    <message>
        <location filename="../model/run/StopConfirmer.cpp" line="187"/>
        <source>still running after %1 s</source>
        <translation>%1 s 후에도 운전 중</translation>
    </message>
</context>
<context>
    <name>opentop::TcpSimServer</name>
    <message>
        <location filename="../sim/TcpSimServer.cpp" line="36"/>
        <source>cannot listen on %1:%2: %3</source>
        <translation>%1:%2에서 수신 대기할 수 없습니다: %3</translation>
    </message>
</context>
<context>
    <name>opentop::TerminalLamps</name>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="184"/>
        <source>n/a</source>
        <translation>해당 없음</translation>
    </message>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="185"/>
        <source>%1: not applicable (%2)</source>
        <translation>%1: 해당 없음 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="188"/>
        <source>?</source>
        <translation>?</translation>
    </message>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="189"/>
        <source>%1: not read</source>
        <translation>%1: 읽지 않음</translation>
    </message>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="193"/>
        <source>ON</source>
        <translation>ON</translation>
    </message>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="193"/>
        <source>OFF</source>
        <translation>OFF</translation>
    </message>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="194"/>
        <source>%1 is ON</source>
        <translation>%1 ON</translation>
    </message>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="194"/>
        <source>%1 is OFF</source>
        <translation>%1 OFF</translation>
    </message>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="196"/>
        <source>%1 (last state read, not live)</source>
        <translation>%1 (마지막으로 읽은 상태, 실시간 아님)</translation>
    </message>
</context>
<context>
    <name>opentop::TestRunPanel</name>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="48"/>
        <source>&lt;b&gt;Test run of machine number %1&lt;/b&gt;</source>
        <translation>&lt;b&gt;국번 %1 시운전&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="54"/>
        <source>Machine number %1 has not been identified as a drive of a known family; a test run needs one.</source>
        <translation>국번 %1이(가) 알려진 제품군의 드라이버로 식별되지 않았습니다. 시운전에는 식별이 필요합니다.</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="31"/>
        <source>&amp;Start</source>
        <translation>기동(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="32"/>
        <source>S&amp;top</source>
        <translation>정지(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="33"/>
        <source>&amp;CW</source>
        <translation>CW(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="34"/>
        <source>CC&amp;W</source>
        <translation>CCW(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="35"/>
        <source>&amp;Hold</source>
        <translation>여자 유지(&amp;H)</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="36"/>
        <source>&amp;Free</source>
        <translation>여자 해제(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="54"/>
        <source>Se&amp;lect running data</source>
        <translation>운전 데이터 선택(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="67"/>
        <source>Return to &amp;I/O priority</source>
        <translation>I/O 우선으로 복귀(&amp;I)</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="69"/>
        <source>Give run, stop, direction and speed selection back to the drive&apos;s input terminals</source>
        <translation>운전, 정지, 방향, 속도 선택을 드라이버의 입력 단자로 되돌립니다</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="161"/>
        <source>Cannot read %1 to check that the drive takes motion commands: %2</source>
        <translation>드라이버가 운전 명령을 받는지 확인하기 위해 %1을(를) 읽을 수 없습니다: %2</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="197"/>
        <source>Not started: the variant of %1 was not given.</source>
        <translation>시작하지 않았습니다: %1의 기종이 지정되지 않았습니다.</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="204"/>
        <source>Reading what the start will run…</source>
        <translation>기동 시 운전할 내용을 읽는 중…</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="220"/>
        <source>Start the motor</source>
        <translation>모터 기동</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="234"/>
        <source>Sending %1…</source>
        <translation>%1 보내는 중…</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="263"/>
        <source>Not every drive of its communication group runs: see below.</source>
        <translation>통신 그룹의 모든 드라이버가 운전 중인 것은 아닙니다: 아래를 보십시오.</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="281"/>
        <source>Sent: %1</source>
        <translation>보냄: %1</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="350"/>
        <source>Polling is paused: the controller brakes the motor %1 s after the last frame it receives (%2). Resume polling to keep the motor running.</source>
        <translation>폴링이 일시 정지되었습니다: 컨트롤러는 마지막 프레임을 받은 뒤 %1 s가 지나면 모터에 브레이크를 겁니다(%2). 모터를 계속 운전하려면 폴링을 재개하십시오.</translation>
    </message>
</context>
<context>
    <name>opentop::TrafficDescriber</name>
    <message>
        <location filename="../model/traffic/TrafficDescriber.cpp" line="150"/>
        <source>broadcast: every drive executes it</source>
        <translation>브로드캐스트: 모든 드라이버가 실행</translation>
    </message>
    <message>
        <location filename="../model/traffic/TrafficDescriber.cpp" line="159"/>
        <source>to %1 (group parent: also %2)</source>
        <translation>%1에게 (그룹 부모: %2에도)</translation>
    </message>
</context>
<context>
    <name>opentop::TrafficLogModel</name>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="93"/>
        <source>Tx</source>
        <translation>Tx</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="95"/>
        <source>Rx</source>
        <translation>Rx</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="97"/>
        <source>–</source>
        <translation>–</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="108"/>
        <source>%1 (%2 ms)</source>
        <translation>%1 (%2 ms)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="123"/>
        <source>Time</source>
        <translation>시각</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="125"/>
        <source>Direction</source>
        <translation>방향</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="127"/>
        <source>Drive</source>
        <translation>드라이버</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="129"/>
        <source>Function</source>
        <translation>기능</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="131"/>
        <source>Bytes</source>
        <translation>바이트</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="133"/>
        <source>Meaning</source>
        <translation>의미</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="135"/>
        <source>Error</source>
        <translation>오류</translation>
    </message>
</context>
<context>
    <name>opentop::TrafficLogView</name>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="43"/>
        <source>&amp;Errors only</source>
        <translation>오류만(&amp;E)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="44"/>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="171"/>
        <source>&amp;Pause</source>
        <translation>일시 정지(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="53"/>
        <source>All drives</source>
        <translation>모든 드라이버</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="55"/>
        <source>All</source>
        <translation>전체</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="56"/>
        <source>Tx (requests)</source>
        <translation>Tx (요청)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="57"/>
        <source>Rx (replies)</source>
        <translation>Rx (응답)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="58"/>
        <source>Events (no reply)</source>
        <translation>이벤트 (응답 없음)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="62"/>
        <source>&amp;Clear</source>
        <translation>지우기(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="64"/>
        <source>&amp;Save…</source>
        <translation>저장(&amp;S)…</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="67"/>
        <source>&amp;Drive:</source>
        <translation>드라이버(&amp;D):</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="69"/>
        <source>Di&amp;rection:</source>
        <translation>방향(&amp;R):</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="83"/>
        <source>Frames</source>
        <translation>프레임</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="112"/>
        <source>Drive</source>
        <translation>드라이버</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="112"/>
        <source>Requests</source>
        <translation>요청</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="112"/>
        <source>Replies</source>
        <translation>응답</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="112"/>
        <source>Timeouts</source>
        <translation>타임아웃</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="112"/>
        <source>CRC errors</source>
        <translation>CRC 오류</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="113"/>
        <source>Exceptions</source>
        <translation>예외</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="113"/>
        <source>Wrong/garbled</source>
        <translation>잘못됨/깨짐</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="113"/>
        <source>Mean ms</source>
        <translation>평균 ms</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="113"/>
        <source>Late replies</source>
        <translation>지연 응답</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="113"/>
        <source>Max ms</source>
        <translation>최대 ms</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="115"/>
        <source>Statistics per drive</source>
        <translation>드라이버별 통계</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="119"/>
        <source>Frames that answered nothing asked at the time: a reply to an earlier request that came too late, discarded and never taken as a value</source>
        <translation>당시 요청에 대한 응답이 아닌 프레임입니다. 이전 요청에 대한 응답이 늦게 도착한 것으로, 폐기되며 값으로 사용되지 않습니다.</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="171"/>
        <source>&amp;Resume</source>
        <translation>재개(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="242"/>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="320"/>
        <source>Broadcast</source>
        <translation>브로드캐스트</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="242"/>
        <source>Drive %1</source>
        <translation>드라이버 %1</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="309"/>
        <source>%1 addresses did not answer: %2</source>
        <translation>응답하지 않은 주소 %1개: %2</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="311"/>
        <source>No reply from machine numbers %1</source>
        <translation>응답 없는 국번: %1</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="352"/>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="357"/>
        <source>Save traffic log</source>
        <translation>통신 로그 저장</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="352"/>
        <source>Text files (*.txt)</source>
        <translation>텍스트 파일 (*.txt)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="358"/>
        <source>Could not save %1: %2</source>
        <translation>%1을(를) 저장할 수 없습니다: %2</translation>
    </message>
</context>
<context>
    <name>opentop::Transport</name>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="16"/>
        <source>No serial port given: enter a device such as /dev/ttyUSB0 or COM3.</source>
        <translation>시리얼 포트가 지정되지 않았습니다: /dev/ttyUSB0 또는 COM3 같은 장치를 입력하십시오.</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="20"/>
        <source>Baud rate %1 is not supported: use 1200–115200 (e.g. 9600, 19200, 38400, 57600, 115200).</source>
        <translation>통신 속도 %1은(는) 지원하지 않습니다: 1200–115200을 사용하십시오(예: 9600, 19200, 38400, 57600, 115200).</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="26"/>
        <source>Parity &apos;%1&apos; is not supported: use N (none), E (even) or O (odd).</source>
        <translation>패리티 &apos;%1&apos;은(는) 지원하지 않습니다: N(없음), E(짝수) 또는 O(홀수)를 사용하십시오.</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="31"/>
        <source>%1 data bits are not supported: use 7 or 8.</source>
        <translation>데이터 비트 %1은(는) 지원하지 않습니다: 7 또는 8을 사용하십시오.</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="35"/>
        <source>%1 stop bits are not supported: use 1 or 2.</source>
        <translation>스톱 비트 %1은(는) 지원하지 않습니다: 1 또는 2를 사용하십시오.</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="39"/>
        <source>Byte timeout %1 ms is not allowed: use 1–10000 ms, or 0 to derive it from the baud rate.</source>
        <translation>바이트 타임아웃 %1 ms는 허용되지 않습니다: 1–10000 ms를 사용하거나, 통신 속도에서 산출하려면 0을 사용하십시오.</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="45"/>
        <source>RS-485 mode %1 is not supported: use off, auto, kernel or rts.</source>
        <translation>RS-485 모드 %1은(는) 지원하지 않습니다: off, auto, kernel 또는 rts를 사용하십시오.</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="52"/>
        <source>Line format of machine number %1: %2 Use machine numbers 1–247.</source>
        <translation>국번 %1의 통신 형식: %2 국번은 1–247을 쓰십시오.</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="60"/>
        <source>RTS delay %1 µs is not allowed: use 0–%2 µs (0: the driver&apos;s or libmodbus&apos; own).</source>
        <translation>RTS 지연 %1 µs는 허용되지 않습니다: 0–%2 µs를 사용하십시오(0: 시리얼 드라이버 또는 libmodbus 자체 지연).</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="69"/>
        <source>No host given: enter the gateway&apos;s address, e.g. 192.168.1.10.</source>
        <translation>호스트가 지정되지 않았습니다: 게이트웨이 주소를 입력하십시오. 예: 192.168.1.10.</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="73"/>
        <source>TCP port %1 is not allowed: use 1–65535 (Modbus TCP uses 502).</source>
        <translation>TCP 포트 %1은(는) 허용되지 않습니다: 1–65535를 사용하십시오(Modbus TCP는 502 사용).</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="80"/>
        <source>No simulated devices given: use a list such as dbu200@1,dcpid@7.</source>
        <translation>시뮬레이션 장치가 지정되지 않았습니다: dbu200@1,dcpid@7 같은 목록을 사용하십시오.</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="86"/>
        <source>Timeout %1 ms is not allowed: use 10–10000 ms.</source>
        <translation>타임아웃 %1 ms는 허용되지 않습니다: 10–10000 ms를 사용하십시오.</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="90"/>
        <source>%1 retries are not allowed: use 0–10.</source>
        <translation>재시도 %1회는 허용되지 않습니다: 0–10을 사용하십시오.</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="56"/>
        <source>Vendor name</source>
        <translation>제조사 이름</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="58"/>
        <source>Product code</source>
        <translation>제품 코드</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="60"/>
        <source>Revision</source>
        <translation>개정</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="62"/>
        <source>Vendor URL</source>
        <translation>제조사 URL</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="64"/>
        <source>Product name</source>
        <translation>제품 이름</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="66"/>
        <source>Model name</source>
        <translation>모델 이름</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="68"/>
        <source>User application name</source>
        <translation>사용자 애플리케이션 이름</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="70"/>
        <source>Object 0x%1</source>
        <translation>오브젝트 0x%1</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="26"/>
        <source>Cannot open %1: %2</source>
        <translation>%1을(를) 열 수 없습니다: %2</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="89"/>
        <source>read twice: a read of the same length was unanswered, and the first reply could have been its late answer</source>
        <translation>두 번 읽음: 같은 길이의 읽기가 응답 없이 남아 있어 첫 응답이 그 지연 응답일 수 있었습니다</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="102"/>
        <source>replies disagree: late answers to earlier reads are likely</source>
        <translation>응답이 일치하지 않음: 이전 읽기에 대한 지연 응답일 가능성이 높습니다</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="115"/>
        <location filename="../transport/ModbusClientWorker.cpp" line="373"/>
        <source>%1 is not open</source>
        <translation>%1이(가) 열려 있지 않습니다</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="160"/>
        <source>send failed</source>
        <translation>송신 실패</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="186"/>
        <source>interrupted while waiting</source>
        <translation>대기 중 중단됨</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="190"/>
        <location filename="../transport/MockBackend.cpp" line="101"/>
        <source>no reply within %1 ms</source>
        <translation>%1 ms 이내에 응답 없음</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="226"/>
        <source>another reply followed: this one may have answered an earlier request</source>
        <translation>다른 응답이 이어졌습니다: 이 응답은 이전 요청에 대한 것일 수 있습니다</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="253"/>
        <source>a drive&apos;s own line format needs a serial port; a Modbus TCP gateway sets its line itself</source>
        <translation>드라이브 자체 통신 형식에는 시리얼 포트가 필요합니다. Modbus TCP 게이트웨이는 라인을 스스로 설정합니다</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="269"/>
        <source>cannot switch the line to %1: %2</source>
        <translation>라인을 %1(으)로 전환할 수 없습니다: %2</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="312"/>
        <source>no reply within %1 ms (a late reply to an earlier request was discarded)</source>
        <translation>%1 ms 이내에 응답 없음 (이전 요청에 대한 지연 응답은 폐기함)</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="334"/>
        <location filename="../transport/RtuFrame.cpp" line="140"/>
        <source>reply from slave %1, expected %2</source>
        <translation>슬레이브 %1의 응답, 기대값 %2</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusContext.cpp" line="140"/>
        <location filename="../transport/RtuBackend.cpp" line="191"/>
        <location filename="../transport/TcpBackend.cpp" line="112"/>
        <source>reply incomplete</source>
        <translation>응답 불완전</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusContext.cpp" line="144"/>
        <location filename="../transport/RtuFrame.cpp" line="133"/>
        <source>CRC mismatch</source>
        <translation>CRC 불일치</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="344"/>
        <location filename="../transport/RtuBackend.cpp" line="198"/>
        <location filename="../transport/TcpBackend.cpp" line="118"/>
        <source>receive failed</source>
        <translation>수신 실패</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="362"/>
        <source>late reply discarded: complete %1 ms after the request, where an answer needs at least %2 ms on the wire</source>
        <translation>지연 응답 폐기: 요청 후 %1 ms에 수신 완료. 응답은 선로에서 최소 %2 ms가 걸립니다</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="378"/>
        <source> (connection closed)</source>
        <translation> (연결 끊김)</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="393"/>
        <source>stale bytes discarded before sending</source>
        <translation>송신 전 남아 있던 바이트 버림</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="440"/>
        <source>late bytes discarded after an error</source>
        <translation>오류 후 늦게 온 바이트 버림</translation>
    </message>
    <message>
        <location filename="../transport/MockBackend.cpp" line="57"/>
        <source>mock is not open</source>
        <translation>mock이 열려 있지 않습니다</translation>
    </message>
    <message>
        <location filename="../transport/ModbusBackend.cpp" line="39"/>
        <source>→ %1 bytes</source>
        <translation>→ %1 바이트</translation>
    </message>
    <message>
        <location filename="../transport/ModbusBackend.cpp" line="51"/>
        <source>echo %1 = %2</source>
        <translation>에코 %1 = %2</translation>
    </message>
    <message>
        <location filename="../transport/ModbusBackend.cpp" line="54"/>
        <source>echo %1 ×%2</source>
        <translation>에코 %1 ×%2</translation>
    </message>
    <message>
        <location filename="../transport/ModbusClientWorker.cpp" line="220"/>
        <location filename="../transport/ModbusClientWorker.cpp" line="239"/>
        <source>cancelled before sending</source>
        <translation>송신 전 취소됨</translation>
    </message>
    <message>
        <location filename="../transport/ModbusClientWorker.cpp" line="285"/>
        <source>cannot open %1</source>
        <translation>%1을(를) 열 수 없습니다</translation>
    </message>
    <message>
        <location filename="../transport/ModbusClientWorker.cpp" line="327"/>
        <source>client closed</source>
        <translation>클라이언트 닫힘</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="142"/>
        <source>Slave address %1 is not allowed: use 1–247, or 0 to broadcast a write.</source>
        <translation>슬레이브 주소 %1은(는) 허용되지 않습니다: 1–247을 사용하거나, 쓰기를 브로드캐스트하려면 0을 사용하십시오.</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="147"/>
        <source>Function code 0x%1 is not allowed: use 0x01–0x7F.</source>
        <translation>기능 코드 0x%1은(는) 허용되지 않습니다: 0x01–0x7F를 사용하십시오.</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="151"/>
        <source>Timeout %1 ms is not allowed: use 10–10000 ms, or -1 for the default.</source>
        <translation>타임아웃 %1 ms는 허용되지 않습니다: 10–10000 ms를 사용하거나, 기본값은 -1을 사용하십시오.</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="156"/>
        <source>%1 retries are not allowed: use 0–10, or -1 for the default.</source>
        <translation>재시도 %1회는 허용되지 않습니다: 0–10을 사용하거나, 기본값은 -1을 사용하십시오.</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="169"/>
        <source>Function 0x%1 cannot be broadcast: only functions 06h and 10h (writes) may be sent to machine number 0; use slave address 1–247.</source>
        <translation>기능 코드 0x%1은(는) 브로드캐스트할 수 없습니다: 기능 코드 06h와 10h(쓰기)만 국번 0으로 보낼 수 있습니다. 슬레이브 주소 1–247을 사용하십시오.</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="176"/>
        <source>Function code 0x%1 must be sent as a raw request.</source>
        <translation>기능 코드 0x%1은(는) raw 요청으로 보내야 합니다.</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="180"/>
        <source>Raw request data of %1 bytes is too long: at most %2 bytes.</source>
        <translation>raw 요청 데이터 %1바이트는 너무 깁니다: 최대 %2바이트.</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="193"/>
        <source>Cannot read %1 registers at once: use 1–125 registers.</source>
        <translation>레지스터 %1개를 한 번에 읽을 수 없습니다: 1–125개를 사용하십시오.</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="200"/>
        <source>Write single register needs exactly 1 value, not %1.</source>
        <translation>단일 레지스터 쓰기에는 값이 정확히 1개 필요합니다(%1개가 아님).</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="206"/>
        <source>Cannot write %1 registers at once: use 1–123 registers.</source>
        <translation>레지스터 %1개를 한 번에 쓸 수 없습니다: 1–123개를 사용하십시오.</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="211"/>
        <source>%1 values given for %2 registers.</source>
        <translation>레지스터 %2개에 값 %1개가 주어졌습니다.</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="220"/>
        <source>Registers %1 ×%2 run past the last address 0xFFFF.</source>
        <translation>레지스터 %1 ×%2이(가) 마지막 주소 0xFFFF를 넘어갑니다.</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="231"/>
        <source>device identification code %1 object %2</source>
        <translation>장치 식별 코드 %1 오브젝트 %2</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="239"/>
        <source>raw %1 %2</source>
        <translation>raw %1 %2</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="243"/>
        <source>read %1 %2 ×%3</source>
        <translation>읽기 %1 %2 ×%3</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="247"/>
        <source>write %1 %2 = %3</source>
        <translation>쓰기 %1 %2 = %3</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="250"/>
        <source>write %1 %2 ×%3 = %4</source>
        <translation>쓰기 %1 %2 ×%3 = %4</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="256"/>
        <source>broadcast %1</source>
        <translation>브로드캐스트 %1</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="11"/>
        <source>ok</source>
        <translation>정상</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="13"/>
        <source>timeout</source>
        <translation>타임아웃</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="15"/>
        <source>CRC error</source>
        <translation>CRC 오류</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="17"/>
        <source>reply from wrong slave</source>
        <translation>다른 슬레이브의 응답</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="19"/>
        <source>exception</source>
        <translation>예외</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="21"/>
        <source>malformed reply</source>
        <translation>잘못된 형식의 응답</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="23"/>
        <source>port error</source>
        <translation>포트 오류</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="25"/>
        <source>not connected</source>
        <translation>연결 안 됨</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="27"/>
        <source>invalid request</source>
        <translation>잘못된 요청</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="29"/>
        <source>cancelled</source>
        <translation>취소됨</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="38"/>
        <source>Illegal function</source>
        <translation>잘못된 기능 코드</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="40"/>
        <source>Illegal data address</source>
        <translation>잘못된 데이터 주소</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="42"/>
        <source>Illegal data value</source>
        <translation>잘못된 데이터 값</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="44"/>
        <source>Slave device failure</source>
        <translation>슬레이브 장치 고장</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="46"/>
        <source>Acknowledge (processing)</source>
        <translation>수신 확인 (처리 중)</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="48"/>
        <source>Slave device busy</source>
        <translation>슬레이브 장치 사용 중</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="50"/>
        <source>Negative acknowledge</source>
        <translation>부정 응답</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="52"/>
        <source>Memory parity error</source>
        <translation>메모리 패리티 오류</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="54"/>
        <source>Gateway path unavailable</source>
        <translation>게이트웨이 경로 사용 불가</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="56"/>
        <source>Gateway target device failed to respond</source>
        <translation>게이트웨이 대상 장치 응답 없음</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="60"/>
        <source>Prohibited action</source>
        <translation>금지된 동작</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="62"/>
        <source>Undefined error</source>
        <translation>정의되지 않은 오류</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="64"/>
        <source>Unknown exception</source>
        <translation>알 수 없는 예외</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="74"/>
        <source>exception %1 %2</source>
        <translation>예외 %1 %2</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="79"/>
        <source>timeout after %1 attempts</source>
        <translation>%1회 시도 후 타임아웃</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="81"/>
        <source>timeout (no reply)</source>
        <translation>타임아웃 (응답 없음)</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="89"/>
        <source> (%1 attempts)</source>
        <translation> (%1회 시도)</translation>
    </message>
    <message>
        <location filename="../transport/PortLock.cpp" line="22"/>
        <source>%1 is in use by another program; close it first.</source>
        <translation>다른 프로그램이 %1을(를) 사용 중입니다. 먼저 그 프로그램을 닫으십시오.</translation>
    </message>
    <message>
        <location filename="../transport/PortLock.cpp" line="27"/>
        <source>another program</source>
        <translation>다른 프로그램</translation>
    </message>
    <message>
        <location filename="../transport/PortLock.cpp" line="29"/>
        <source>%1 is in use by %2 (PID %3); close it first.</source>
        <translation>%2(PID %3)이(가) %1을(를) 사용 중입니다. 먼저 닫으십시오.</translation>
    </message>
    <message>
        <location filename="../transport/RtuBackend.cpp" line="127"/>
        <source>: your user may not open serial ports. Add it to the dialout group with
    sudo usermod -aG dialout $USER
then log out and in again (the group applies to new sessions only).</source>
        <translation>: 현재 사용자에게 시리얼 포트를 열 권한이 없습니다. 다음 명령으로 dialout 그룹에 추가하고
    sudo usermod -aG dialout $USER
로그아웃했다가 다시 로그인하십시오(그룹은 새 세션에만 적용됨).</translation>
    </message>
    <message>
        <location filename="../transport/RtuBackend.cpp" line="134"/>
        <source> (the device may not support this parity; ptys need N)</source>
        <translation> (장치가 이 패리티를 지원하지 않을 수 있습니다. pty는 N이 필요합니다)</translation>
    </message>
    <message>
        <location filename="../transport/RtuBackend.cpp" line="169"/>
        <source>reply announces %1 bytes, more than an RTU frame holds</source>
        <translation>응답이 %1바이트라고 알리지만 RTU 프레임에 들어갈 수 있는 크기보다 큽니다</translation>
    </message>
    <message>
        <location filename="../transport/RtuBackend.cpp" line="190"/>
        <source>no reply</source>
        <translation>응답 없음</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="127"/>
        <source>reply too short (%1 bytes)</source>
        <translation>응답이 너무 짧음(%1바이트)</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="148"/>
        <source>exception reply of %1 bytes</source>
        <translation>%1바이트의 예외 응답</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="159"/>
        <source>reply function %1, expected %2</source>
        <translation>응답 기능 %1, 기대값 %2</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="166"/>
        <source>reply ends inside its own data</source>
        <translation>응답이 자체 데이터 중간에서 끝남</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="171"/>
        <source>reply of %1 bytes, expected %2</source>
        <translation>응답 %1바이트, 기대값 %2</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="181"/>
        <source>MEI type %1, expected %2</source>
        <translation>MEI 유형 %1, 기대값 %2</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="194"/>
        <source>byte count %1, expected %2</source>
        <translation>바이트 수 %1, 기대값 %2</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="207"/>
        <source>echo %1 = %2 differs from the write</source>
        <translation>에코 %1 = %2이(가) 쓴 내용과 다름</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="218"/>
        <source>echo %1 ×%2 differs from the write</source>
        <translation>에코 %1 ×%2이(가) 쓴 내용과 다름</translation>
    </message>
    <message>
        <location filename="../transport/SerialPortList.cpp" line="87"/>
        <source>An adapter missing here has no driver: see Device Manager, Ports (COM &amp; LPT). A port can also be typed, e.g. COM12.</source>
        <translation>여기에 없는 어댑터는 드라이버가 설치되지 않은 것입니다: 장치 관리자의 &apos;포트(COM &amp; LPT)&apos;를 확인하십시오. 포트를 직접 입력할 수도 있습니다(예: COM12).</translation>
    </message>
    <message>
        <location filename="../transport/SerialPortList.cpp" line="92"/>
        <source>Pseudo-terminals (e.g. /dev/pts/3 or a socat link) are not listed: type their path.</source>
        <translation>가상 터미널(예: /dev/pts/3 또는 socat 링크)은 목록에 나오지 않습니다: 경로를 입력하십시오.</translation>
    </message>
    <message>
        <location filename="../transport/TcpBackend.cpp" line="61"/>
        <source>Cannot open %1: the name %2 was not found (%3); check the gateway&apos;s name, or give its address</source>
        <translation>%1을(를) 열 수 없습니다: 이름 %2을(를) 찾을 수 없습니다(%3). 게이트웨이 이름을 확인하거나 주소를 입력하십시오</translation>
    </message>
    <message>
        <location filename="../transport/TcpBackend.cpp" line="128"/>
        <source>MBAP length %1</source>
        <translation>MBAP 길이 %1</translation>
    </message>
    <message>
        <location filename="../transport/TrafficEntry.cpp" line="13"/>
        <source>TX</source>
        <translation>TX</translation>
    </message>
    <message>
        <location filename="../transport/TrafficEntry.cpp" line="15"/>
        <source>RX</source>
        <translation>RX</translation>
    </message>
    <message>
        <location filename="../transport/TrafficEntry.cpp" line="17"/>
        <source>--</source>
        <translation>--</translation>
    </message>
    <message>
        <location filename="../transport/TrafficEntry.cpp" line="37"/>
        <source>error: %1</source>
        <translation>오류: %1</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="13"/>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="14"/>
        <source>%1 µs</source>
        <translation>%1 µs</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="31"/>
        <source>RTS high while sending</source>
        <translation>송신 중 RTS High</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="32"/>
        <source>RTS low while sending</source>
        <translation>송신 중 RTS Low</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="35"/>
        <source>, %1 before and after</source>
        <translation>, 송신 전후 %1</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="37"/>
        <source>, %1 before, %2 after</source>
        <translation>, 송신 전 %1, 송신 후 %2</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="43"/>
        <source>RS-485: switched by the adapter</source>
        <translation>RS-485: 어댑터가 전환</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="45"/>
        <source>RS-485: kernel mode left on by the driver (%1)</source>
        <translation>RS-485: 시리얼 드라이버가 커널 모드를 켠 상태로 유지 (%1)</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="49"/>
        <source>RS-485: kernel (%1)</source>
        <translation>RS-485: 커널 (%1)</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="52"/>
        <source>RS-485: RTS from the program (%1; kernel mode refused: %2)</source>
        <translation>RS-485: 프로그램이 RTS 제어 (%1; 커널 모드 거부됨: %2)</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="56"/>
        <source>RS-485: RTS from the program (%1)</source>
        <translation>RS-485: 프로그램이 RTS 제어 (%1)</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="61"/>
        <source>RS-485: not available (kernel mode refused: %1; RTS not switchable: %2)</source>
        <translation>RS-485: 사용할 수 없음 (커널 모드 거부됨: %1; RTS 전환 불가: %2)</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="66"/>
        <source>RS-485: RTS not switchable on this port (%1)</source>
        <translation>RS-485: 이 포트에서는 RTS 전환 불가 (%1)</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="69"/>
        <source>RS-485: kernel mode refused by the driver (%1)</source>
        <translation>RS-485: 시리얼 드라이버가 커널 모드를 거부함 (%1)</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="78"/>
        <source>latency timer %1 ms</source>
        <translation>지연 타이머 %1 ms</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="86"/>
        <source>low latency: not a UART, no adapter latency</source>
        <translation>저지연: UART 아님, 어댑터 지연 없음</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="90"/>
        <source>low latency: on (but %1)</source>
        <translation>저지연: 켜짐 (단, %1)</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="92"/>
        <source>low latency: on</source>
        <translation>저지연: 켜짐</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="95"/>
        <source>low latency: the driver&apos;s setting (FTDI: Latency Timer 1 ms in Device Manager)</source>
        <translation>저지연: 드라이버 설정(FTDI: 장치 관리자에서 Latency Timer를 1 ms로)</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="100"/>
        <source>low latency: not offered by the driver (%1)</source>
        <translation>저지연: 시리얼 드라이버가 지원하지 않음 (%1)</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="104"/>
        <source>low latency: not offered by the driver (USB adapter: up to %1 ms assumed)</source>
        <translation>저지연: 시리얼 드라이버가 지원하지 않음 (USB 어댑터: 최대 %1 ms로 가정)</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="108"/>
        <source>low latency: not offered by the driver</source>
        <translation>저지연: 시리얼 드라이버가 지원하지 않음</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="112"/>
        <source>low latency: off</source>
        <translation>저지연: 꺼짐</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="113"/>
        <source>low latency: off (%1)</source>
        <translation>저지연: 꺼짐 (%1)</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="137"/>
        <source>low latency is off</source>
        <translation>저지연이 꺼져 있음</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="139"/>
        <source>the driver took low latency but kept its latency timer</source>
        <translation>시리얼 드라이버가 저지연을 받아들였지만 지연 타이머는 그대로임</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="142"/>
        <source>the driver did not take low latency</source>
        <translation>시리얼 드라이버가 저지연을 받아들이지 않음</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="145"/>
        <source>see docs/hardware.md, or use an adapter whose driver offers low latency</source>
        <translation>docs/hardware.md를 참조하거나, 시리얼 드라이버가 저지연을 지원하는 어댑터를 사용하십시오</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="149"/>
        <source>as root: echo 1 &gt; %1, or the udev rule in docs/hardware.md</source>
        <translation>root로 실행: echo 1 &gt; %1, 또는 docs/hardware.md의 udev 규칙 사용</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="153"/>
        <source>The adapter holds received bytes for up to %1 ms before passing them on (%2). Fix: %3.</source>
        <translation>어댑터가 수신한 바이트를 최대 %1 ms 동안 보류한 뒤 넘깁니다(%2). 해결 방법: %3.</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineSetup.cpp" line="131"/>
        <source>the driver left it off</source>
        <translation>시리얼 드라이버가 꺼진 상태로 둠</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineSetup.cpp" line="200"/>
        <source>the port does not take %1</source>
        <translation>포트가 %1을(를) 받아들이지 않습니다</translation>
    </message>
</context>
<context>
    <name>opentop::TrendAxes</name>
    <message>
        <location filename="../ui/trends/TrendAxes.cpp" line="51"/>
        <location filename="../ui/trends/TrendAxes.cpp" line="52"/>
        <source>%1 [%2]</source>
        <translation>%1 [%2]</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendAxes.cpp" line="49"/>
        <source>[%1]</source>
        <translation>[%1]</translation>
    </message>
</context>
<context>
    <name>opentop::TrendChart</name>
    <message>
        <location filename="../ui/trends/TrendChart.cpp" line="33"/>
        <location filename="../ui/trends/TrendChart.cpp" line="59"/>
        <source>Time (hh:mm:ss)</source>
        <translation>시간 (hh:mm:ss)</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendChart.cpp" line="109"/>
        <source>Drive %1</source>
        <translation>드라이버 %1</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendChart.cpp" line="300"/>
        <source>There is no trend data to export yet.</source>
        <translation>아직 내보낼 트렌드 데이터가 없습니다.</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendChart.cpp" line="313"/>
        <source>Cannot write the picture %1.</source>
        <translation>이미지 %1을(를) 저장할 수 없습니다.</translation>
    </message>
</context>
<context>
    <name>opentop::TrendCsv</name>
    <message>
        <location filename="../model/monitor/TrendCsv.cpp" line="28"/>
        <source>time</source>
        <translation>시간</translation>
    </message>
    <message>
        <location filename="../model/monitor/TrendCsv.cpp" line="28"/>
        <source>seconds</source>
        <translation>초</translation>
    </message>
</context>
<context>
    <name>opentop::TrendPanel</name>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="50"/>
        <location filename="../ui/trends/TrendPanel.cpp" line="78"/>
        <source>Pause</source>
        <translation>일시 정지</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="51"/>
        <source>Live</source>
        <translation>실시간</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="54"/>
        <source>How often each charted drive is polled. Commands you give always go first; the drives take turns on the bus.</source>
        <translation>차트에 표시하는 각 드라이버를 폴링하는 주기. 사용자가 내린 명령이 항상 먼저 처리되고, 드라이버들은 버스를 차례로 사용합니다.</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="65"/>
        <source>30 s</source>
        <translation>30 s</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="65"/>
        <source>1 min</source>
        <translation>1 min</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="65"/>
        <source>5 min</source>
        <translation>5 min</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="65"/>
        <source>15 min</source>
        <translation>15 min</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="74"/>
        <source>Freezes the chart; the values keep being recorded.</source>
        <translation>차트를 고정합니다. 값은 계속 기록됩니다.</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="78"/>
        <source>Resume</source>
        <translation>재개</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="81"/>
        <source>Back to the latest values after zooming or pausing.</source>
        <translation>확대하거나 일시 정지한 뒤 최신 값으로 돌아갑니다.</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="86"/>
        <source>Clear markers</source>
        <translation>마커 지우기</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="89"/>
        <source>Export CSV…</source>
        <translation>CSV 내보내기…</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="92"/>
        <source>Export PNG…</source>
        <translation>PNG 내보내기…</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="97"/>
        <source>Drive / quantity</source>
        <translation>드라이버 / 측정 항목</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="111"/>
        <source>Poll rate:</source>
        <translation>폴링 주기:</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="113"/>
        <source>Window:</source>
        <translation>표시 범위:</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="141"/>
        <source>%1 Hz (%2 ms)</source>
        <translation>%1 Hz (%2 ms)</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="200"/>
        <source>%1 [%2]</source>
        <translation>%1 [%2]</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="253"/>
        <source>Export trend as CSV</source>
        <translation>트렌드를 CSV로 내보내기</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="253"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV 파일 (*.csv)</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="256"/>
        <source>Export CSV</source>
        <translation>CSV 내보내기</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="262"/>
        <source>Export trend as picture</source>
        <translation>트렌드를 이미지로 내보내기</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="263"/>
        <source>PNG pictures (*.png)</source>
        <translation>PNG 이미지 (*.png)</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="266"/>
        <source>Export PNG</source>
        <translation>PNG 내보내기</translation>
    </message>
</context>
<context>
    <name>opentop::TrendReadout</name>
    <message>
        <location filename="../ui/trends/TrendReadout.cpp" line="25"/>
        <source>Markers: click in the chart to set marker A, click again to set marker B.</source>
        <translation>마커: 차트를 클릭하면 마커 A, 다시 클릭하면 마커 B를 설정합니다.</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendReadout.cpp" line="28"/>
        <source>A %1   B %2   Δt = B − A = %3 s</source>
        <translation>A %1   B %2   Δt = B − A = %3 s</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendReadout.cpp" line="31"/>
        <source>A %1   (click in the chart to set marker B)</source>
        <translation>A %1   (차트를 클릭하면 마커 B 설정)</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendReadout.cpp" line="32"/>
        <source>B %1   (click in the chart to set marker A)</source>
        <translation>B %1   (차트를 클릭하면 마커 A 설정)</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendReadout.cpp" line="34"/>
        <source>no data</source>
        <translation>데이터 없음</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendReadout.cpp" line="44"/>
        <source>%1:   A %2   B %3   Δ %4</source>
        <translation>%1:   A %2   B %3   Δ %4</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendReadout.cpp" line="46"/>
        <source>%1:   %2 %3</source>
        <translation>%1:   %2 %3</translation>
    </message>
</context>
<context>
    <name>opentop::TuneCommand</name>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="82"/>
        <source>Speed-loop step test and relay autotune of a DC controller (needs --yes)</source>
        <translation>DC 컨트롤러의 속도 루프 스텝 시험과 릴레이 오토튜닝 (--yes 필요)</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="88"/>
        <source>Run the test (it moves the motor).</source>
        <translation>시험을 실행합니다(모터가 움직입니다).</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="89"/>
        <source>step: speed before the step (default 0).</source>
        <translation>step: 스텝 전 속도 (기본값 0).</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="89"/>
        <location filename="../cli/TuneCommand.cpp" line="90"/>
        <location filename="../cli/TuneCommand.cpp" line="93"/>
        <location filename="../cli/TuneCommand.cpp" line="107"/>
        <source>SPEED</source>
        <translation>SPEED</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="90"/>
        <source>step: speed after the step.</source>
        <translation>step: 스텝 후 속도.</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="91"/>
        <source>step: record this long after the step (default 1500).</source>
        <translation>step: 스텝 후 기록할 시간 (기본값 1500).</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="92"/>
        <source>MS</source>
        <translation>MS</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="93"/>
        <source>autotune: operating speed of the relay test.</source>
        <translation>autotune: 릴레이 시험의 운전 속도.</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="94"/>
        <source>autotune: output swing, % of full output (default 10).</source>
        <translation>autotune: 출력 스윙, 최대 출력에 대한 % (기본값 10).</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="95"/>
        <source>PERCENT</source>
        <translation>PERCENT</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="97"/>
        <source>autotune: soft, medium (default), stiff, tyreus-luyben or zn-pi.</source>
        <translation>autotune: soft, medium (기본값), stiff, tyreus-luyben 또는 zn-pi.</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="97"/>
        <source>RULE</source>
        <translation>RULE</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="98"/>
        <source>autotune: write the proposed gains, then run a step test from half the operating speed to it.</source>
        <translation>autotune: 제안된 게인을 쓴 뒤, 운전 속도의 절반에서 운전 속도까지 스텝 시험을 실행합니다.</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="101"/>
        <source>autotune: with --accept, store the gains in the drive if the step measured with them passes the check.</source>
        <translation>autotune: --accept와 함께 쓰면, 그 게인으로 측정한 스텝이 확인을 통과할 때 게인을 드라이버에 저장합니다.</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="104"/>
        <source>autotune: with --accept, keep (and with --store, store) gains whose measured step failed the check; without it they are written back to what the drive had.</source>
        <translation>autotune: --accept와 함께 쓰면 측정한 스텝이 확인을 통과하지 못해도 게인을 유지합니다(--store가 있으면 저장). 지정하지 않으면 드라이버의 이전 게인을 다시 씁니다.</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="107"/>
        <source>Stop at once beyond this speed (default 120 % of the test&apos;s highest).</source>
        <translation>속도가 이 값을 넘으면 즉시 정지합니다(기본값: 시험 최고 속도의 120 %).</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="108"/>
        <source>Stop at once beyond this current in A (default 20).</source>
        <translation>전류가 이 값(A)을 넘으면 즉시 정지합니다(기본값 20).</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="109"/>
        <source>A</source>
        <translation>A</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="110"/>
        <source>Write the samples to FILE.</source>
        <translation>샘플을 FILE에 씁니다.</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="110"/>
        <source>FILE</source>
        <translation>FILE</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="124"/>
        <source>error: usage: %1</source>
        <translation>오류: 사용법: %1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="134"/>
        <source>error: --%1 must be a number 0 or more, got &apos;%2&apos;</source>
        <translation>오류: --%1은(는) 0 이상의 숫자여야 합니다. 입력값: &apos;%2&apos;</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="156"/>
        <location filename="../cli/TuneCommand.cpp" line="167"/>
        <location filename="../cli/TuneCommand.cpp" line="172"/>
        <location filename="../cli/TuneCommand.cpp" line="375"/>
        <source>error: %1</source>
        <translation>오류: %1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="157"/>
        <source>step needs --to SPEED</source>
        <translation>step에는 --to SPEED가 필요합니다</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="158"/>
        <source>--rule must be one of %1</source>
        <translation>--rule은 %1 중 하나여야 합니다</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="160"/>
        <source>autotune needs --speed SPEED</source>
        <translation>autotune에는 --speed SPEED가 필요합니다</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="176"/>
        <source>Would run the motor of machine number %1 from %2 to %3 and record the step response.</source>
        <translation>국번 %1의 모터를 %2에서 %3(으)로 운전하고 스텝 응답을 기록합니다.</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="181"/>
        <source>Would run the motor of machine number %1 in a relay test around %2 (output ±%3 %).</source>
        <translation>국번 %1의 모터를 %2 부근에서 릴레이 시험으로 운전합니다(출력 ±%3 %).</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="187"/>
        <source>This moves the motor: add --yes to run it.</source>
        <translation>모터가 움직입니다: 실행하려면 --yes를 추가하십시오.</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="236"/>
        <source>Machine number %1, gains %2</source>
        <translation>국번 %1, 게인 %2</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="238"/>
        <source>  rise time (10–90 %): %1</source>
        <translation>  상승 시간 (10–90 %): %1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="239"/>
        <source>  overshoot: %1 %</source>
        <translation>  오버슈트: %1 %</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="240"/>
        <source>  settling time (2 %): %1</source>
        <translation>  정정 시간 (2 %): %1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="241"/>
        <source>  steady-state error: %1 %2</source>
        <translation>  정상상태 오차: %1 %2</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="242"/>
        <source>  peak current: %1 A</source>
        <translation>  피크 전류: %1 A</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="268"/>
        <source>Step %1 → %2 %3:</source>
        <translation>스텝 %1 → %2 %3:</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="273"/>
        <source>Relay test: Ku %1, Tu %2 ms measured (amplitude ±%3 %4, %5 cycles, %6 readings per period, one every %7 ms)</source>
        <translation>릴레이 시험: Ku %1, 측정된 Tu %2 ms (진폭 ±%3 %4, %5주기, 주기당 읽기 %6회, %7 ms마다)</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="365"/>
        <source>What to change: %1</source>
        <translation>바꿀 점: %1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="282"/>
        <source>Model: gain %1, time constant %2 ms, dead time %3 ms (the bus&apos;s %4 ms left out)</source>
        <translation>모델: 게인 %1, 시정수 %2 ms, 무효 시간 %3 ms (버스의 %4 ms는 제외)</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="288"/>
        <source>The drive&apos;s own loop on the model: Ku %1, Tu %2 ms</source>
        <translation>모델상 드라이버 자체 루프: Ku %1, Tu %2 ms</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="291"/>
        <source>Proposed (%1): %2</source>
        <translation>제안값 (%1): %2</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="292"/>
        <source>  the rule&apos;s P × %1, Ti × %2; predicted step %3 → %4 %5: overshoot %6 %, settling time %7</source>
        <translation>  규칙의 P × %1, Ti × %2; 예측 스텝 %3 → %4 %5: 오버슈트 %6 %, 정정 시간 %7</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="308"/>
        <source>Writing the proposed gains failed: %1</source>
        <translation>제안 게인 쓰기 실패: %1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="311"/>
        <source>Proposed gains written (not stored).</source>
        <translation>제안 게인을 썼습니다(저장 안 됨).</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="314"/>
        <source>Measured step %1 → %2 %3 with them:</source>
        <translation>이 게인으로 측정한 스텝 %1 → %2 %3:</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="322"/>
        <source>interrupted</source>
        <translation>중단됨</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="325"/>
        <source>Check after Accept: passed. %1</source>
        <translation>수락 후 확인: 통과. %1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="326"/>
        <source>Check after Accept: FAILED. %1</source>
        <translation>수락 후 확인: 실패. %1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="335"/>
        <source>The gains before were written back (%1); nothing was stored. --override-check keeps the proposal (and with --store stores it) all the same.</source>
        <translation>이전 게인을 다시 썼습니다(%1). 아무것도 저장하지 않았습니다. --override-check를 주면 그래도 제안값을 유지합니다(--store가 있으면 저장).</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="339"/>
        <source>Writing back the gains before failed: %1; the proposal is still in the drive (not stored).</source>
        <translation>이전 게인 다시 쓰기 실패: %1. 제안값이 아직 드라이버에 있습니다(저장 안 됨).</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="346"/>
        <source>Storing although the check failed (--override-check).</source>
        <translation>확인을 통과하지 못했지만 저장합니다(--override-check).</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="355"/>
        <source>Gains stored in the drive.</source>
        <translation>게인을 드라이버에 저장했습니다.</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="356"/>
        <source>Storing the gains failed: %1</source>
        <translation>게인 저장 실패: %1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="363"/>
        <source>Test ended: %1</source>
        <translation>시험 종료: %1</translation>
    </message>
</context>
<context>
    <name>opentop::TuningChart</name>
    <message>
        <location filename="../ui/tuning/TuningChart.cpp" line="41"/>
        <source>Time (ms)</source>
        <translation>시간 (ms)</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningChart.cpp" line="45"/>
        <location filename="../ui/tuning/TuningChart.cpp" line="83"/>
        <source>Current (A)</source>
        <translation>전류 (A)</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningChart.cpp" line="81"/>
        <source>Speed</source>
        <translation>속도</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningChart.cpp" line="81"/>
        <source>Speed (%1)</source>
        <translation>속도 (%1)</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningChart.cpp" line="82"/>
        <location filename="../ui/tuning/TuningChart.cpp" line="83"/>
        <source>(%1)</source>
        <translation>(%1)</translation>
    </message>
</context>
<context>
    <name>opentop::TuningDrive</name>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="50"/>
        <source>a tuning test is already running</source>
        <translation>튜닝 시험이 이미 실행 중입니다</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="88"/>
        <source>Reading the drive&apos;s settings</source>
        <translation>드라이버 설정을 읽는 중</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="98"/>
        <source>could not read the drive&apos;s settings: %1</source>
        <translation>드라이버 설정을 읽을 수 없습니다: %1</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="139"/>
        <source>the drive is not in a closed-loop speed mode: set %1 (%2) to %3 first</source>
        <translation>드라이버가 폐루프 속도 모드가 아닙니다: 먼저 %1(%2)을(를) %3(으)로 설정하십시오</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="141"/>
        <source> or </source>
        <translation> 또는 </translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="146"/>
        <source>Setting the communication-loss braking time to %1 s</source>
        <translation>통신 두절 정지 시간을 %1 s로 설정하는 중</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="201"/>
        <source>the drive stopped answering: %1</source>
        <translation>드라이버가 응답하지 않습니다: %1</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="221"/>
        <source>speed %1 %2 beyond the test&apos;s limit %3 %2: stopped at once</source>
        <translation>속도 %1 %2이(가) 시험 한계값 %3 %2을(를) 넘었습니다: 즉시 정지함</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="228"/>
        <source>current %1 A beyond the test&apos;s limit %2 A: stopped at once</source>
        <translation>전류 %1 A가 시험 한계값 %2 A를 넘었습니다: 즉시 정지함</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="234"/>
        <source>cancelled</source>
        <translation>취소됨</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="271"/>
        <source>Stopping the motor</source>
        <translation>모터를 정지하는 중</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="303"/>
        <source>motor stopped (confirmed)</source>
        <translation>모터 정지됨(확인됨)</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="304"/>
        <source>the motor could not be confirmed stopped: check it</source>
        <translation>모터 정지를 확인할 수 없습니다: 모터를 점검하십시오</translation>
    </message>
</context>
<context>
    <name>opentop::TuningDriveSettings</name>
    <message>
        <location filename="../ui/tuning/TuningDriveSettings.cpp" line="53"/>
        <source>Could not read the speed mode: %1</source>
        <translation>속도 모드를 읽을 수 없습니다: %1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningDriveSettings.cpp" line="56"/>
        <source>The drive is not in a closed-loop speed mode (now: %1). Choose one on its settings page first.</source>
        <translation>드라이버가 폐루프 속도 모드가 아닙니다(현재: %1). 먼저 설정 페이지에서 폐루프 모드를 선택하십시오.</translation>
    </message>
</context>
<context>
    <name>opentop::TuningGains</name>
    <message>
        <location filename="../ui/tuning/TuningGains.cpp" line="43"/>
        <source>Writing the gains failed: %1</source>
        <translation>게인 쓰기 실패: %1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningGains.cpp" line="62"/>
        <source>Proposal written (temporary until stored).</source>
        <translation>제안값을 썼습니다(저장 전까지 임시).</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningGains.cpp" line="83"/>
        <source>%1: the gains before were written back (%2).</source>
        <translation>%1: 이전 게인을 다시 썼습니다(%2).</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningGains.cpp" line="102"/>
        <source>Gains stored in the drive.</source>
        <translation>게인을 드라이버에 저장했습니다.</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningGains.cpp" line="104"/>
        <source>Storing the gains failed: %1</source>
        <translation>게인 저장 실패: %1</translation>
    </message>
</context>
<context>
    <name>opentop::TuningLimitsBox</name>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="12"/>
        <source>Limits</source>
        <translation>한계값</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="17"/>
        <source>Beyond it the motor is stopped at once. Empty: 125 % of the step test&apos;s highest speed, 150 % of the autotune&apos;s speed</source>
        <translation>이 값을 넘으면 모터를 즉시 정지합니다. 비워 두면: 스텝 시험 최고 속도의 125 %, 오토튜닝 속도의 150 %</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="19"/>
        <source>Beyond it the motor is stopped at once. Empty: 1.2 × the drive&apos;s maximum current</source>
        <translation>이 값을 넘으면 모터를 즉시 정지합니다. 비워 두면: 1.2 × 드라이버 최대 전류</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="22"/>
        <source>Max. speed:</source>
        <translation>최고 속도:</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="23"/>
        <source>Max. current:</source>
        <translation>최대 전류:</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="24"/>
        <source>A</source>
        <translation>A</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="37"/>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="39"/>
        <source>auto: %1</source>
        <translation>자동: %1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="39"/>
        <source>none</source>
        <translation>없음</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="48"/>
        <source>Enter a speed limit above 0 %1, or leave it empty.</source>
        <translation>0 %1보다 큰 속도 한계값을 입력하거나 비워 두십시오.</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="52"/>
        <source>Enter a current limit above 0 A, or leave it empty.</source>
        <translation>0 A보다 큰 전류 한계값을 입력하거나 비워 두십시오.</translation>
    </message>
</context>
<context>
    <name>opentop::TuningMetricsView</name>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="25"/>
        <source>Rise time (10–90 %):</source>
        <translation>상승 시간 (10–90 %):</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="26"/>
        <source>Overshoot:</source>
        <translation>오버슈트:</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="27"/>
        <source>Settling time (2 %):</source>
        <translation>정정 시간 (2 %):</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="28"/>
        <source>Steady-state error:</source>
        <translation>정상상태 오차:</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="29"/>
        <source>Peak current:</source>
        <translation>피크 전류:</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="40"/>
        <source>No run yet</source>
        <translation>아직 실행한 시험 없음</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="41"/>
        <source>%1: recording</source>
        <translation>%1: 기록 중</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="44"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="52"/>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="55"/>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="53"/>
        <source>not reached</source>
        <translation>도달 안 함</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="54"/>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="56"/>
        <source>not settled</source>
        <translation>정정 안 됨</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="57"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="58"/>
        <source>%1 A</source>
        <translation>%1 A</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="63"/>
        <source>Rise time %1; overshoot %2; settling time %3; steady-state error %4; peak current %5</source>
        <translation>상승 시간 %1; 오버슈트 %2; 정정 시간 %3; 정상상태 오차 %4; 피크 전류 %5</translation>
    </message>
</context>
<context>
    <name>opentop::TuningPage</name>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="53"/>
        <location filename="../ui/tuning/TuningPage.cpp" line="213"/>
        <source>Step test</source>
        <translation>스텝 시험</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="54"/>
        <location filename="../ui/tuning/TuningPage.cpp" line="234"/>
        <source>Relay autotune</source>
        <translation>릴레이 오토튜닝</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="112"/>
        <source>Ready. Nothing moves until you confirm a test.</source>
        <translation>준비 완료. 시험을 확인하기 전에는 아무것도 움직이지 않습니다.</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="191"/>
        <source>Limits: %1 %2, %3.</source>
        <translation>한계값: %1 %2, %3.</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="193"/>
        <source>%1 A</source>
        <translation>%1 A</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="193"/>
        <source>no current limit</source>
        <translation>전류 한계값 없음</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="208"/>
        <source>The motor of %1 will run from %2 to %3 %4 in its present speed mode, for about %5 s, and then stop.</source>
        <translation>%1의 모터가 현재 속도 모드로 %2에서 %3 %4까지 약 %5 s 동안 운전한 뒤 정지합니다.</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="213"/>
        <location filename="../ui/tuning/TuningPage.cpp" line="234"/>
        <source>Run</source>
        <translation>실행</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="229"/>
        <source>The motor of %1 will run in open loop (the speed loop off) around %2 %3, its output switching by ±%4 %, for up to %5 s, and then stop.</source>
        <translation>%1의 모터가 개루프(속도 루프 끔)로 %2 %3 부근에서 운전하며 출력을 ±%4 %씩 전환합니다. 최대 %5 s 후 정지합니다.</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="252"/>
        <source>Stop command sent.</source>
        <translation>정지 명령을 보냈습니다.</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="253"/>
        <source>Stop command failed: %1</source>
        <translation>정지 명령 실패: %1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="263"/>
        <source>Stopping…</source>
        <translation>정지하는 중…</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="277"/>
        <source>Run %1: %2 → %3 %4</source>
        <translation>실행 %1: %2 → %3 %4</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="296"/>
        <source>Step test done.</source>
        <translation>스텝 시험 완료.</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="297"/>
        <source>Step test ended: %1</source>
        <translation>스텝 시험 종료: %1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="302"/>
        <source>The test was stopped</source>
        <translation>시험이 정지됨</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="333"/>
        <source>Autotune ended: %1</source>
        <translation>오토튜닝 종료: %1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="335"/>
        <source>The autotune was stopped</source>
        <translation>오토튜닝이 정지됨</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="344"/>
        <source>Predicted: %1 → %2 %3</source>
        <translation>예측: %1 → %2 %3</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="347"/>
        <source>Autotune done: proposal %1. Accept writes it to the drive.</source>
        <translation>오토튜닝 완료: 제안값 %1. 수락하면 드라이버에 씁니다.</translation>
    </message>
</context>
<context>
    <name>opentop::TuningRules</name>
    <message>
        <location filename="../model/tuning/TuningRules.cpp" line="61"/>
        <source>Soft (no overshoot)</source>
        <translation>부드러움 (오버슈트 없음)</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningRules.cpp" line="63"/>
        <source>Medium (some overshoot)</source>
        <translation>보통 (약간의 오버슈트)</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningRules.cpp" line="65"/>
        <source>Stiff (Ziegler–Nichols)</source>
        <translation>고강성 (Ziegler–Nichols)</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningRules.cpp" line="67"/>
        <source>Tyreus–Luyben (robust)</source>
        <translation>Tyreus–Luyben (강건)</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningRules.cpp" line="69"/>
        <source>PI only (Ziegler–Nichols)</source>
        <translation>PI만 (Ziegler–Nichols)</translation>
    </message>
</context>
<context>
    <name>opentop::TuningRunList</name>
    <message>
        <location filename="../ui/tuning/TuningRunList.cpp" line="14"/>
        <source>Run</source>
        <translation>실행</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunList.cpp" line="14"/>
        <source>Gains</source>
        <translation>게인</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunList.cpp" line="43"/>
        <source>%1 (recording)</source>
        <translation>%1 (기록 중)</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunList.cpp" line="45"/>
        <source>P %1 · I %2 · D %3</source>
        <translation>P %1 · I %2 · D %3</translation>
    </message>
</context>
<context>
    <name>opentop::TuningRunsView</name>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="38"/>
        <source>Save CSV…</source>
        <translation>CSV 저장…</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="39"/>
        <source>Save PNG…</source>
        <translation>PNG 저장…</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="44"/>
        <source>Saves the selected run: its samples, gains and metrics</source>
        <translation>선택한 실행 기록을 저장합니다: 샘플, 게인, 지표</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="45"/>
        <source>Saves the chart as it is shown</source>
        <translation>표시된 그대로 차트를 저장합니다</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="46"/>
        <source>solid: speed · dotted: command · dash-dot: current (right axis) · dashed: predicted speed</source>
        <translation>실선: 속도 · 점선: 명령 · 일점쇄선: 전류(오른쪽 축) · 파선: 예측 속도</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="220"/>
        <source>no run to save</source>
        <translation>저장할 실행 기록이 없습니다</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="233"/>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="237"/>
        <source>Save run as CSV</source>
        <translation>실행 기록을 CSV로 저장</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="234"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV 파일 (*.csv)</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="242"/>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="245"/>
        <source>Save chart as PNG</source>
        <translation>차트를 PNG로 저장</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="243"/>
        <source>PNG images (*.png)</source>
        <translation>PNG 이미지 (*.png)</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="245"/>
        <source>Could not write %1.</source>
        <translation>%1에 쓸 수 없습니다.</translation>
    </message>
</context>
<context>
    <name>opentop::TuningSpec</name>
    <message>
        <location filename="../model/tuning/TuningSpec.cpp" line="23"/>
        <source>%1 has no speed loop to tune</source>
        <translation>%1에는 튜닝할 속도 루프가 없습니다</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningSpec.cpp" line="51"/>
        <source>%1: the profile&apos;s tuning needs the roles pidP, pidI, pidD, pidDPeriod, pidStore, speedMode, speedCommand, commLossTime, loadCurrent and output</source>
        <translation>%1: 프로파일의 튜닝에는 pidP, pidI, pidD, pidDPeriod, pidStore, speedMode, speedCommand, commLossTime, loadCurrent, output 역할이 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningSpec.cpp" line="61"/>
        <source>%1: the profile&apos;s tuning section needs periodMs ≥ 1, outputFullScale &gt; 0, openLoopMode and closedLoopModes with known feedback parameters</source>
        <translation>%1: 프로파일의 튜닝 섹션에는 periodMs ≥ 1, outputFullScale &gt; 0, openLoopMode, 그리고 피드백 파라미터가 알려진 closedLoopModes가 필요합니다</translation>
    </message>
</context>
<context>
    <name>opentop::TuningStatusRow</name>
    <message>
        <location filename="../ui/tuning/TuningStatusRow.cpp" line="12"/>
        <source>STOP</source>
        <translation>정지</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningStatusRow.cpp" line="17"/>
        <source>Cancels the running test: the motor is stopped and the stop confirmed</source>
        <translation>진행 중인 시험을 취소합니다: 모터를 정지하고 정지를 확인합니다</translation>
    </message>
</context>
<context>
    <name>opentop::TuningVerdict</name>
    <message>
        <location filename="../model/tuning/TuningVerdict.cpp" line="11"/>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningVerdict.cpp" line="12"/>
        <source>none within the record</source>
        <translation>기록 시간 안에 없음</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningVerdict.cpp" line="20"/>
        <source>no step was measured to its end with these gains: %1</source>
        <translation>이 게인으로 스텝을 끝까지 측정하지 못했습니다: %1</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningVerdict.cpp" line="46"/>
        <source>the speed did not settle within %1 ms (±2 % of the step)</source>
        <translation>속도가 %1 ms 안에 정정되지 않았습니다(스텝의 ±2 %)</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningVerdict.cpp" line="49"/>
        <source>it overshot by %1 % where %2 % was predicted (at most %3 points more are accepted)</source>
        <translation>오버슈트가 %1 %였습니다(예측 %2 %, 예측보다 %3 %p까지만 허용)</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningVerdict.cpp" line="60"/>
        <source>Measured: overshoot %1 % (predicted %2 %), settling time %3 (predicted %4), peak current %5 A.</source>
        <translation>측정: 오버슈트 %1 %(예측 %2 %), 정정 시간 %3(예측 %4), 피크 전류 %5 A.</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningVerdict.cpp" line="70"/>
        <source>Check failed: %1.</source>
        <translation>확인 실패: %1.</translation>
    </message>
</context>
<context>
    <name>opentop::UnitLog</name>
    <message>
        <location filename="../ui/eol/UnitLog.cpp" line="19"/>
        <source>Time</source>
        <translation>시각</translation>
    </message>
    <message>
        <location filename="../ui/eol/UnitLog.cpp" line="19"/>
        <source>Serial</source>
        <translation>시리얼</translation>
    </message>
    <message>
        <location filename="../ui/eol/UnitLog.cpp" line="19"/>
        <source>Verdict</source>
        <translation>판정</translation>
    </message>
    <message>
        <location filename="../ui/eol/UnitLog.cpp" line="19"/>
        <source>Reason</source>
        <translation>원인</translation>
    </message>
    <message>
        <location filename="../ui/eol/UnitLog.cpp" line="32"/>
        <source>%1, NOT RECORDED</source>
        <translation>%1, 기록 안 됨</translation>
    </message>
    <message>
        <location filename="../ui/eol/UnitLog.cpp" line="34"/>
        <source>%1 (kept on this station)</source>
        <translation>%1 (이 스테이션에 보관)</translation>
    </message>
</context>
<context>
    <name>opentop::UnitRecordJson</name>
    <message>
        <location filename="../model/eol/UnitRecordJson.cpp" line="115"/>
        <source>not a unit record (format is not &quot;%1&quot;)</source>
        <translation>제품 기록이 아닙니다(format이 &quot;%1&quot;이(가) 아님)</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitRecordJson.cpp" line="118"/>
        <source>unit record version %1 is not known to this program (it reads up to %2)</source>
        <translation>제품 기록 버전 %1은(는) 이 프로그램이 알지 못합니다(%2까지 읽음)</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitRecordJson.cpp" line="125"/>
        <source>the unit record has no serial number</source>
        <translation>제품 기록에 시리얼 번호가 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitRecordJson.cpp" line="139"/>
        <source>unknown unit status &quot;%1&quot;</source>
        <translation>알 수 없는 제품 상태 &quot;%1&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitRecordJson.cpp" line="153"/>
        <source>unknown variant source &quot;%1&quot;</source>
        <translation>알 수 없는 기종 출처 &quot;%1&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitRecordJson.cpp" line="192"/>
        <source>not JSON: %1</source>
        <translation>JSON이 아닙니다: %1</translation>
    </message>
</context>
<context>
    <name>opentop::UnitStartGate</name>
    <message>
        <location filename="../model/station/UnitStartGate.cpp" line="45"/>
        <source>cancelled before it started</source>
        <translation>시작 전에 취소됨</translation>
    </message>
    <message>
        <location filename="../model/station/UnitStartGate.cpp" line="80"/>
        <source>not connected to a bus</source>
        <translation>버스에 연결되어 있지 않음</translation>
    </message>
    <message>
        <location filename="../model/station/UnitStartGate.cpp" line="85"/>
        <source>a drive of the station is not safe: %1</source>
        <translation>스테이션의 드라이브가 안전하지 않습니다: %1</translation>
    </message>
</context>
<context>
    <name>opentop::UnitValuesCsv</name>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="74"/>
        <source>the CSV file is larger than %1 MB</source>
        <translation>CSV 파일이 %1 MB보다 큽니다</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="76"/>
        <source>not a CSV text file (it holds NUL bytes)</source>
        <translation>CSV 텍스트 파일이 아닙니다(NUL 바이트 포함)</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="97"/>
        <source>line %1: a quoted field is not closed properly</source>
        <translation>%1행: 따옴표로 묶은 필드가 올바르게 닫히지 않았습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="101"/>
        <source>line %1: the header must start with &quot;serial&quot;, not &quot;%2&quot;</source>
        <translation>%1행: 헤더는 &quot;%2&quot;이(가) 아니라 &quot;serial&quot;로 시작해야 합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="105"/>
        <source>line %1: the header names no per-unit value</source>
        <translation>%1행: 헤더에 제품별 값이 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="107"/>
        <source>line %1: more than %2 columns</source>
        <translation>%1행: 열이 %2개보다 많습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="111"/>
        <source>line %1: column %2 has no name</source>
        <translation>%1행: 열 %2에 이름이 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="113"/>
        <source>line %1: column &quot;%2&quot; appears twice</source>
        <translation>%1행: 열 &quot;%2&quot;이(가) 두 번 나옵니다</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="122"/>
        <source>line %1: %2 fields, but the header has %3</source>
        <translation>%1행: 필드가 %2개이지만 헤더는 %3개입니다</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="128"/>
        <source>line %1: no serial number</source>
        <translation>%1행: 시리얼 번호 없음</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="130"/>
        <source>line %1: serial number &quot;%2&quot; is already on line %3</source>
        <translation>%1행: 시리얼 번호 &quot;%2&quot;이(가) 이미 %3행에 있습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="137"/>
        <source>the CSV file is empty; it needs a header &quot;serial,&lt;parameter&gt;,...&quot;</source>
        <translation>CSV 파일이 비어 있습니다. &quot;serial,&lt;parameter&gt;,...&quot; 헤더가 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="151"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="193"/>
        <source>serial number &quot;%1&quot; is not in the CSV file</source>
        <translation>시리얼 번호 &quot;%1&quot;이(가) CSV 파일에 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="206"/>
        <source>%1: column &quot;%2&quot; is ambiguous, several positions have this per-unit value; name the column &quot;%3:%2&quot;</source>
        <translation>%1: 열 &quot;%2&quot;이(가) 모호합니다. 여러 위치에 이 제품별 값이 있습니다. 열 이름을 &quot;%3:%2&quot;(으)로 하십시오</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="210"/>
        <source>%1: the CSV file has no column &quot;%2&quot; (or &quot;%3:%2&quot;) for this per-unit value</source>
        <translation>%1: CSV 파일에 이 제품별 값의 열 &quot;%2&quot;(또는 &quot;%3:%2&quot;)이(가) 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="215"/>
        <source>line %1, column &quot;%2&quot;: no value for serial number &quot;%3&quot;</source>
        <translation>%1행, 열 &quot;%2&quot;: 시리얼 번호 &quot;%3&quot;의 값이 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="225"/>
        <source>line %1, column &quot;%2&quot;: &quot;%3&quot; is not a number</source>
        <translation>%1행, 열 &quot;%2&quot;: &quot;%3&quot;은(는) 숫자가 아닙니다</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="231"/>
        <source>line %1: %2</source>
        <translation>%1행: %2</translation>
    </message>
</context>
<context>
    <name>opentop::UserGuideDialog</name>
    <message>
        <location filename="../ui/help/UserGuideDialog.cpp" line="26"/>
        <source>OpenTOP user guide</source>
        <translation>OpenTOP 사용자 가이드</translation>
    </message>
    <message>
        <location filename="../ui/help/UserGuideDialog.cpp" line="28"/>
        <source> or </source>
        <translation> 또는 </translation>
    </message>
    <message>
        <location filename="../ui/help/UserGuideDialog.cpp" line="31"/>
        <source>&lt;h2&gt;Commissioning a drive with OpenTOP&lt;/h2&gt;&lt;ol&gt;&lt;li&gt;&lt;b&gt;Connect.&lt;/b&gt; Bus ▸ Connect… chooses the serial port (or USB to RS-485 adapter), a Modbus TCP gateway or a simulated bus, with the bus&apos;s baud rate, parity and stop bits. The status bar says what the program is connected to; a simulated bus is marked as such.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Find the drives.&lt;/b&gt; Bus ▸ Scan bus (F5) asks every machine number 1–247; the drives that answer are identified and listed on the left with their state and control priority.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Select a drive.&lt;/b&gt; Its pages open on the right: Monitor (live values), the parameter pages of its profile, Test run and Alarms.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Edit settings.&lt;/b&gt; An edited field is marked as pending until it is written. Write page (or Drive ▸ Write all pending, Ctrl+W) writes and reads every value back to verify it; Revert drops the edits; Re-read (Ctrl+R) reads the drive again. A value the drive would refuse is never sent: the field says why.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Test-run the motor.&lt;/b&gt; The Test run page starts, stops and reverses the drive in communication priority and asks before the first start of each drive. Return the drive to I/O priority when done, so that the machine&apos;s own inputs control it again.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Stop.&lt;/b&gt; STOP ALL on the toolbar, or %1, stops every drive on the bus at once, from any window of the program.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Watch.&lt;/b&gt; View ▸ Trends (Ctrl+G) charts speeds and loads; View ▸ Bus overview shows every drive at a glance; View ▸ Traffic log (Ctrl+T) shows each frame on the bus with its meaning.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Keep the settings.&lt;/b&gt; Files ▸ Back up saves the settings of one drive or the whole bus to a file; Files ▸ Compare shows differences between drives, files and factory defaults; Files ▸ Restore writes a backup back after a preview.&lt;/li&gt;&lt;/ol&gt;&lt;p&gt;Every keyboard shortcut is listed in Help ▸ Keyboard shortcuts.&lt;/p&gt;&lt;h3&gt;More documentation&lt;/h3&gt;&lt;p&gt;The command line and the simulator: &lt;code&gt;man opentop&lt;/code&gt;, &lt;code&gt;man opentop-cli&lt;/code&gt;, &lt;code&gt;man opentop-sim&lt;/code&gt;.&lt;/p&gt;</source>
        <translation>&lt;h2&gt;OpenTOP으로 드라이버 커미셔닝하기&lt;/h2&gt;&lt;ol&gt;&lt;li&gt;&lt;b&gt;연결.&lt;/b&gt; 버스 ▸ 연결…에서 시리얼 포트(또는 USB–RS-485 어댑터), Modbus TCP 게이트웨이 또는 시뮬레이션 버스를 선택하고 버스의 통신 속도, 패리티, 스톱 비트를 지정합니다. 상태 표시줄에 연결 대상이 표시되며, 시뮬레이션 버스는 그렇게 표시됩니다.&lt;/li&gt;&lt;li&gt;&lt;b&gt;드라이버 찾기.&lt;/b&gt; 버스 ▸ 버스 스캔(F5)은 국번 1–247에 모두 묻습니다. 응답한 드라이버는 식별되어 왼쪽 목록에 상태, 제어 우선순위와 함께 표시됩니다.&lt;/li&gt;&lt;li&gt;&lt;b&gt;드라이버 선택.&lt;/b&gt; 오른쪽에 드라이버의 페이지가 열립니다: 모니터(실시간 값), 프로파일의 파라미터 페이지, 시운전, 알람.&lt;/li&gt;&lt;li&gt;&lt;b&gt;설정 편집.&lt;/b&gt; 편집한 항목은 쓸 때까지 쓰기 대기로 표시됩니다. 페이지 쓰기(또는 드라이버 ▸ 쓰기 대기 모두 쓰기, Ctrl+W)는 값을 쓰고 모두 다시 읽어 검증합니다. 되돌리기는 편집을 버리고, 다시 읽기(Ctrl+R)는 드라이버를 다시 읽습니다. 드라이버가 거부할 값은 보내지 않으며, 항목에 그 이유가 표시됩니다.&lt;/li&gt;&lt;li&gt;&lt;b&gt;모터 시운전.&lt;/b&gt; 시운전 페이지에서 통신 우선으로 드라이버를 기동, 정지, 역회전하며, 드라이버마다 첫 기동 전에 확인합니다. 끝나면 설비 자체의 입력으로 다시 제어하도록 드라이버를 I/O 우선으로 되돌리십시오.&lt;/li&gt;&lt;li&gt;&lt;b&gt;정지.&lt;/b&gt; 도구 모음의 전체 정지 또는 %1을(를) 누르면 프로그램의 어느 창에서든 버스의 모든 드라이버를 한 번에 정지합니다.&lt;/li&gt;&lt;li&gt;&lt;b&gt;감시.&lt;/b&gt; 보기 ▸ 트렌드(Ctrl+G)는 속도와 부하를 차트로 표시하고, 보기 ▸ 버스 개요는 모든 드라이버를 한눈에 보여 주며, 보기 ▸ 통신 로그(Ctrl+T)는 버스의 각 프레임과 그 의미를 표시합니다.&lt;/li&gt;&lt;li&gt;&lt;b&gt;설정 보관.&lt;/b&gt; 파일 ▸ 백업은 드라이버 한 대 또는 버스 전체의 설정을 파일로 저장합니다. 파일 ▸ 비교는 드라이버, 파일, 공장 출하값 사이의 차이를 표시합니다. 파일 ▸ 파일에서 복원은 미리 보기 후 백업을 다시 씁니다.&lt;/li&gt;&lt;/ol&gt;&lt;p&gt;모든 단축키는 도움말 ▸ 단축키에 있습니다.&lt;/p&gt;&lt;h3&gt;추가 문서&lt;/h3&gt;&lt;p&gt;명령줄과 시뮬레이터: &lt;code&gt;man opentop&lt;/code&gt;, &lt;code&gt;man opentop-cli&lt;/code&gt;, &lt;code&gt;man opentop-sim&lt;/code&gt;.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../ui/help/UserGuideDialog.cpp" line="66"/>
        <source>&lt;h3&gt;Leaving a bus, and coming back after the link drops&lt;/h3&gt;&lt;p&gt;&lt;b&gt;Leaving.&lt;/b&gt; Quitting, Bus ▸ Disconnect or connecting elsewhere while drives run or are in communication priority names each of them and what will happen to it. The default stops every running drive, reads it back to confirm the stop, and then gives each drive back to its own inputs (I/O priority, read back), so that the machine works without OpenTOP. You may instead give control back only, leave the drives as they are, or stay.&lt;/p&gt;&lt;p&gt;&lt;b&gt;A lost link.&lt;/b&gt; When the adapter is pulled out or the gateway goes, every live value turns grey and a message says which drives were running or in communication priority when the link dropped, with the age of what is known. OpenTOP cannot stop them over a lost link: check the drive&apos;s STOP input, the emergency stop and the power on the machine. Bus ▸ Reconnect (Ctrl+R, also in the message and in the red bar) opens the same port again with the same drives, selected drive and page, reads every drive again and says at once if one is running. While connected, Ctrl+R re-reads the drive&apos;s pages.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;버스에서 나가기, 연결이 끊긴 뒤 다시 연결하기&lt;/h3&gt;&lt;p&gt;&lt;b&gt;나가기.&lt;/b&gt; 드라이버가 운전 중이거나 통신 우선일 때 종료하거나 버스 ▸ 연결 해제 또는 다른 곳에 연결하면, 각 드라이버와 그 드라이버에 할 일을 보여 줍니다. 기본 동작은 운전 중인 드라이버를 모두 정지하고 다시 읽어 정지를 확인한 뒤, 각 드라이버를 자체 입력 단자로 되돌려(I/O 우선, 다시 읽기로 확인) OpenTOP 없이도 설비가 동작하게 합니다. 대신 제어 반환만 하거나, 드라이버를 그대로 두거나, 머무를 수도 있습니다.&lt;/p&gt;&lt;p&gt;&lt;b&gt;연결 끊김.&lt;/b&gt; 어댑터가 뽑히거나 게이트웨이가 사라지면 모든 실시간 값이 회색으로 바뀌고, 연결이 끊겼을 때 어떤 드라이버가 운전 중이거나 통신 우선이었는지 알려진 값의 경과 시간과 함께 메시지로 알려 줍니다. 끊긴 연결로는 OpenTOP이 드라이버를 정지할 수 없습니다: 설비에서 드라이버의 정지 입력 단자, 비상 정지, 전원을 확인하십시오. 버스 ▸ 다시 연결(Ctrl+R, 메시지와 빨간 표시줄에도 있음)은 같은 드라이버, 선택한 드라이버와 페이지로 같은 포트를 다시 열고, 모든 드라이버를 다시 읽어 운전 중인 드라이버가 있으면 바로 알려 줍니다. 연결되어 있을 때 Ctrl+R은 드라이버 페이지를 다시 읽습니다.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../ui/help/UserGuideDialog.cpp" line="86"/>
        <source>&lt;p&gt;The full description of the program: &lt;a href=&quot;%1&quot;&gt;%2&lt;/a&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;프로그램 전체 설명: &lt;a href=&quot;%1&quot;&gt;%2&lt;/a&gt;&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>opentop::UserStore</name>
    <message>
        <location filename="../model/access/UserStore.cpp" line="43"/>
        <source>a user name is 1 to 64 letters, digits or . _ @ - (no spaces): &quot;%1&quot;</source>
        <translation>사용자 이름은 1~64자의 영문자, 숫자 또는 . _ @ -입니다(공백 없음): &quot;%1&quot;</translation>
    </message>
</context>
<context>
    <name>opentop::ValueCodec</name>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="63"/>
        <source>%1: %2 is outside the recommended range %3; it is allowed and will be written</source>
        <translation>%1: %2은(는) 권장 범위 %3을(를) 벗어납니다. 허용되는 값이므로 씁니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="80"/>
        <source> (the variant is not known, so the value must suit %1; name the variant to use its own range)</source>
        <translation> (기종을 알 수 없으므로 값이 %1에 맞아야 합니다. 해당 기종의 범위를 쓰려면 기종을 지정하십시오)</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="90"/>
        <source>%1: the allowed values depend on %2, which has not been read</source>
        <translation>%1: 허용 값이 아직 읽지 않은 %2에 따라 달라집니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="95"/>
        <source>%1: value out of the register&apos;s range; allowed: %2</source>
        <translation>%1: 값이 레지스터 범위를 벗어났습니다. 허용: %2</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="107"/>
        <source>%1: %2 is not allowed; allowed: %3</source>
        <translation>%1: %2은(는) 허용되지 않습니다. 허용: %3</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="119"/>
        <source>%1: expected %2 registers, got %3</source>
        <translation>%1: 레지스터 %2개가 필요하지만 %3개입니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="149"/>
        <source>%1 is text, not a number</source>
        <translation>%1은(는) 숫자가 아니라 텍스트입니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="162"/>
        <source>%1: %2 is finer than the step of %3 %4; allowed: %5</source>
        <translation>%1: %2이(가) 단위 %3 %4보다 세밀합니다. 허용: %5</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="195"/>
        <source>%1: at most %2 characters</source>
        <translation>%1: 최대 %2자</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="200"/>
        <source>%1: only printable ASCII characters are allowed</source>
        <translation>%1: 출력 가능한 ASCII 문자만 허용됩니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="210"/>
        <source>%1: no value given; allowed: %2</source>
        <translation>%1: 값이 없습니다. 허용: %2</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="250"/>
        <source>%1: &quot;%2&quot; is only available when %3 is %4; allowed now: %5</source>
        <translation>%1: &quot;%2&quot;은(는) %3이(가) %4일 때만 사용할 수 있습니다. 현재 허용: %5</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="263"/>
        <location filename="../model/profile/ValueCodec.cpp" line="283"/>
        <source>%1: &quot;%2&quot; is not a valid value; allowed: %3</source>
        <translation>%1: &quot;%2&quot;은(는) 올바른 값이 아닙니다. 허용: %3</translation>
    </message>
</context>
<context>
    <name>opentop::ValueFormat</name>
    <message>
        <location filename="../model/profile/ValueFormat.cpp" line="45"/>
        <source> or </source>
        <translation> 또는 </translation>
    </message>
    <message>
        <location filename="../model/profile/ValueFormat.cpp" line="65"/>
        <source>depends on %1, which is not known yet</source>
        <translation>아직 알 수 없는 %1에 따라 달라집니다</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueFormat.cpp" line="67"/>
        <source>text of up to %1 characters</source>
        <translation>최대 %1자의 텍스트</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueFormat.cpp" line="73"/>
        <source>, or </source>
        <translation>, 또는 </translation>
    </message>
    <message>
        <location filename="../model/profile/ValueFormat.cpp" line="74"/>
        <source>any value</source>
        <translation>모든 값</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueFormat.cpp" line="81"/>
        <source>(invalid)</source>
        <translation>(무효)</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueFormat.cpp" line="92"/>
        <source>unknown code %1</source>
        <translation>알 수 없는 코드 %1</translation>
    </message>
</context>
<context>
    <name>opentop::VariantCheck</name>
    <message>
        <location filename="../model/eol/VariantCheck.cpp" line="23"/>
        <source>proving the variant (%1)</source>
        <translation>기종 확인 중 (%1)</translation>
    </message>
</context>
<context>
    <name>opentop::VariantDecision</name>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="39"/>
        <source>the variant probe left the drive changed: %1</source>
        <translation>기종 확인 후 드라이버가 바뀐 채로 남았습니다: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="44"/>
        <source>reported by the drive</source>
        <translation>드라이버가 알려 줌</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="53"/>
        <source>%1; named by %2</source>
        <translation>%1; %2이(가) 지정</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="57"/>
        <source>given for the unit by %1 (eol run --variant)</source>
        <translation>%1이(가) 이 제품에 지정 (eol run --variant)</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="62"/>
        <source>confirmed by the operator %1 (the recipe asks the operator)</source>
        <translation>작업자 %1이(가) 확인 (레시피가 작업자 확인을 요구)</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="67"/>
        <source>the recipe&apos;s only variant, not proven on the bus</source>
        <translation>레시피의 유일한 기종, 버스에서 확인되지 않음</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="74"/>
        <source>the family has no variant probe</source>
        <translation>이 제품군에는 기종 확인 방법이 없습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="76"/>
        <source>the probe leaves %1 (%2)</source>
        <translation>확인 결과가 %1 중 하나입니다 (%2)</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="81"/>
        <source>the drive does not report its variant and it was not proven (%1)</source>
        <translation>드라이버가 기종을 알려 주지 않으며 확인되지도 않았습니다 (%1)</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="82"/>
        <source>the drive does not report its variant and it was not proven (%1); the recipe allows %2 and needs proof</source>
        <translation>드라이버가 기종을 알려 주지 않으며 확인되지도 않았습니다 (%1); 레시피는 %2을(를) 허용하며 확인이 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="90"/>
        <source>the drive is a %1 (%2), but %3 was given for it</source>
        <translation>드라이버는 %1입니다 (%2). 그러나 %3(으)로 지정되었습니다</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="93"/>
        <source>a %1 (%2), the recipe allows %3</source>
        <translation>%1입니다 (%2). 레시피는 %3을(를) 허용합니다</translation>
    </message>
</context>
<context>
    <name>opentop::VariantNeed</name>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="19"/>
        <source>%1 and %2 more</source>
        <translation>%1 외 %2개</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="69"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="77"/>
        <source>Allowed %1 — %2</source>
        <translation>허용값 %1 — %2</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="94"/>
        <source>The allowed values of the settings you are changing depend on it.</source>
        <translation>변경하려는 설정의 허용값이 기종에 따라 다릅니다.</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="97"/>
        <source>The backup file records it, and a restore checks the values against it.</source>
        <translation>백업 파일에 기종이 기록되고, 복원 시 기종에 따라 값을 검사합니다.</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="100"/>
        <source>The speeds the motor may run at depend on it.</source>
        <translation>모터가 운전할 수 있는 속도가 기종에 따라 다릅니다.</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="104"/>
        <source>Which drive is %1? It reports only &quot;%2&quot;, not whether it is a %3.</source>
        <translation>%1은(는) 어떤 드라이버입니까? &quot;%2&quot;만 보고하고 %3인지는 보고하지 않습니다.</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="105"/>
        <source> or </source>
        <translation> 또는 </translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="108"/>
        <source>Read it on the drive&apos;s rating plate. It is kept for this bus and asked once; without it every value must suit all of them.</source>
        <translation>드라이버 명판에서 확인하십시오. 이 버스에 저장되며 한 번만 묻습니다. 지정하지 않으면 모든 값이 모든 기종에 맞아야 합니다.</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="112"/>
        <source>Last time on this bus it was set as %1.</source>
        <translation>지난번 이 버스에서는 %1(으)로 설정했습니다.</translation>
    </message>
</context>
<context>
    <name>opentop::VariantProbe</name>
    <message>
        <location filename="../model/profile/VariantProbe.cpp" line="51"/>
        <source>unknown key &quot;%1&quot;</source>
        <translation>알 수 없는 키 &quot;%1&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/VariantProbe.cpp" line="58"/>
        <source>needs &quot;parameter&quot;, a number &quot;value&quot; and &quot;refusedCode&quot;</source>
        <translation>&quot;parameter&quot;, 숫자 &quot;value&quot;, &quot;refusedCode&quot;가 필요합니다</translation>
    </message>
    <message>
        <location filename="../model/profile/VariantProbe.cpp" line="63"/>
        <source>no parameter &quot;%1&quot;</source>
        <translation>파라미터 &quot;%1&quot;이(가) 없습니다</translation>
    </message>
    <message>
        <location filename="../model/profile/VariantProbe.cpp" line="67"/>
        <source>%1 must be a readable, writable setting that no role names (never a command or a motion register)</source>
        <translation>%1은(는) 읽고 쓸 수 있고 어떤 역할에도 쓰이지 않는 설정이어야 합니다 (명령이나 운전 레지스터는 안 됩니다)</translation>
    </message>
    <message>
        <location filename="../model/profile/VariantProbe.cpp" line="77"/>
        <source>%1 = %2 must be allowed on some variants and refused on others</source>
        <translation>%1 = %2은(는) 일부 기종에서는 허용되고 다른 기종에서는 거부되어야 합니다</translation>
    </message>
</context>
<context>
    <name>opentop::VariantProber</name>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="47"/>
        <location filename="../model/session/VariantProber.cpp" line="85"/>
        <source>%1 cannot be read: %2</source>
        <translation>%1을(를) 읽을 수 없습니다: %2</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="63"/>
        <source>%1 still holds %2 from a variant probe that was interrupted, and cannot be set back to %3 (%4): set it to %3 before this drive is used</source>
        <translation>%1에 중단된 기종 확인이 쓴 %2이(가) 남아 있고 %3(으)로 되돌릴 수 없습니다(%4): 이 드라이버를 쓰기 전에 %3(으)로 설정하십시오</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="71"/>
        <source>%1 set back from %2 to %3, left by a variant probe that was interrupted</source>
        <translation>%1을(를) %2에서 %3(으)로 되돌렸습니다 (중단된 기종 확인이 남긴 값)</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="102"/>
        <source>not probed: the original value cannot be kept while it is (%1)</source>
        <translation>확인하지 않음: 확인하는 동안 원래 값을 보관할 수 없습니다(%1)</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="123"/>
        <source>the probe %1 was not answered as the manual says: %2</source>
        <translation>기종 확인 %1에 대한 응답이 매뉴얼과 다릅니다: %2</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="147"/>
        <source>%1 could not be set back to %2 after the variant probe (%3): set it to %2 before this drive is used</source>
        <translation>기종 확인 후 %1을(를) %2(으)로 되돌리지 못했습니다 (%3): 이 드라이버를 사용하기 전에 %2(으)로 설정하십시오</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="152"/>
        <source>%1 accepted, %2 written back</source>
        <translation>%1 수락됨, %2(으)로 되돌려 씀</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="160"/>
        <source>%1 refused (%2)</source>
        <translation>%1 거부됨 (%2)</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="171"/>
        <source>%1 does not read back as %2 after the variant probe (%3): set it to %2 before this drive is used</source>
        <translation>기종 확인 후 %1의 읽은 값이 %2이(가) 아닙니다 (%3): 이 드라이버를 사용하기 전에 %2(으)로 설정하십시오</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="181"/>
        <source>the probe did not decide</source>
        <translation>확인으로 판정하지 못했습니다</translation>
    </message>
</context>
<context>
    <name>opentop::VariantQuestion</name>
    <message>
        <location filename="../ui/bus/VariantQuestion.cpp" line="29"/>
        <source>Which drive is it?</source>
        <translation>어떤 드라이버입니까?</translation>
    </message>
    <message>
        <location filename="../ui/bus/VariantQuestion.cpp" line="42"/>
        <source>Not known: check against every variant</source>
        <translation>모름: 모든 기종 기준으로 검사</translation>
    </message>
    <message>
        <location filename="../ui/bus/VariantQuestion.cpp" line="65"/>
        <source>the variant of %1 was not given</source>
        <translation>%1의 기종이 지정되지 않았습니다</translation>
    </message>
</context>
<context>
    <name>opentop::VerdictLook</name>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="16"/>
        <source>READY</source>
        <translation>준비 완료</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="17"/>
        <source>TESTING</source>
        <translation>검사 중</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="18"/>
        <source>NOT STARTED</source>
        <translation>시작 안 됨</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="20"/>
        <source>PASS</source>
        <translation>합격</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="21"/>
        <source>FAIL</source>
        <translation>불합격</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="22"/>
        <source>STATION ERROR</source>
        <translation>스테이션 오류</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="24"/>
        <source>ABORTED</source>
        <translation>중지됨</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="25"/>
        <source>NOT RECORDED</source>
        <translation>기록 안 됨</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="66"/>
        <source>Unit %1</source>
        <translation>제품 %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="69"/>
        <source>%1
Not a verdict on the unit: fix the cause and test it again.</source>
        <translation>%1
제품 판정이 아닙니다: 원인을 해결한 뒤 다시 검사하십시오.</translation>
    </message>
</context>
<context>
    <name>opentop::YieldReport</name>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="100"/>
        <source>%1 rev. %2</source>
        <translation>%1 개정 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="105"/>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="111"/>
        <source>first-pass yield – (no serial tested yet)</source>
        <translation>직행률 – (아직 검사한 시리얼 없음)</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="112"/>
        <source>first-pass yield %1 (%2 of %3 serials) · second-pass %4 · last-pass %5</source>
        <translation>직행률 %1 (시리얼 %3개 중 %2개) · 2회 이내 합격률 %4 · 최종 합격률 %5</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="125"/>
        <source>still running (or its station has not restarted since it stopped)</source>
        <translation>아직 진행 중(또는 멈춘 뒤 스테이션이 다시 시작되지 않음)</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="127"/>
        <source>interrupted</source>
        <translation>중단됨</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="129"/>
        <source>aborted</source>
        <translation>중지됨</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="131"/>
        <source>station error, no reason recorded</source>
        <translation>스테이션 오류, 원인 기록 없음</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="133"/>
        <source>failed, no reason recorded</source>
        <translation>불합격, 원인 기록 없음</translation>
    </message>
</context>
</TS>
