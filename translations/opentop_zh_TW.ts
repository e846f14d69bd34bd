<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_TW">
<context>
    <name>Freshness</name>
    <message>
        <location filename="../model/session/Freshness.cpp" line="29"/>
        <location filename="../model/session/Freshness.cpp" line="31"/>
        <source>%1 s old</source>
        <translation>%1 s 前</translation>
    </message>
    <message>
        <location filename="../model/session/Freshness.cpp" line="33"/>
        <source>%1 min old</source>
        <translation>%1 min 前</translation>
    </message>
    <message>
        <location filename="../model/session/Freshness.cpp" line="34"/>
        <source>%1 h old</source>
        <translation>%1 h 前</translation>
    </message>
    <message>
        <location filename="../model/session/Freshness.cpp" line="40"/>
        <source>never read</source>
        <translation>從未讀取</translation>
    </message>
    <message>
        <location filename="../model/session/Freshness.cpp" line="41"/>
        <source>last answer %1 (%2)</source>
        <translation>最後回應 %1 (%2)</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/main.cpp" line="60"/>
        <source>Commissioning tool for RS-485 Modbus-RTU motor drives.</source>
        <translation>RS-485 Modbus-RTU 馬達驅動器試車調機工具。</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="64"/>
        <source>Language of the program: %1 (default: the language menu&apos;s choice, else the system&apos;s).</source>
        <translation>程式的語言：%1（預設：語言選單的選擇，否則為系統語言）。</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="79"/>
        <source>Open the bus overview and the trends of every drive.</source>
        <translation>開啟匯流排總覽及每台驅動器的趨勢圖。</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="80"/>
        <source>Monitoring poll interval in milliseconds.</source>
        <translation>監視輪詢間隔，單位 ms。</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="83"/>
        <source>Quit after this many seconds and print the monitoring statistics (for measurements).</source>
        <translation>經過此秒數後結束，並輸出監視統計 (供量測用)。</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="87"/>
        <source>Print the monitoring totals every this many seconds (for measurements).</source>
        <translation>每隔此秒數輸出一次監視累計 (供量測用)。</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="97"/>
        <source>--poll-ms needs a number of milliseconds</source>
        <translation>--poll-ms 需要毫秒數</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="102"/>
        <source>--quit-after needs a number of seconds</source>
        <translation>--quit-after 需要秒數</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="107"/>
        <source>--stats-every needs a number of seconds</source>
        <translation>--stats-every 需要秒數</translation>
    </message>
    <message>
        <location filename="../app/gui/StartupProbe.cpp" line="23"/>
        <source>Print how long the start took once the window shows the bus&apos;s drives, then quit (for measurements).</source>
        <translation>在視窗顯示匯流排上的驅動器後，輸出啟動所花的時間，然後結束 (供量測用)。</translation>
    </message>
</context>
<context>
    <name>opentop</name>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="71"/>
        <source>not read</source>
        <translation>未讀取</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="91"/>
        <source>No alarm is active.</source>
        <translation>目前無警報。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="93"/>
        <source>Alarm active: %1 %2.</source>
        <translation>警報發生中：%1 %2。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="96"/>
        <source>An alarm is active.</source>
        <translation>有警報發生中。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="99"/>
        <source>This drive is set to clear alarms by a power restart only (%1): Alarm-Reset clears none of them.</source>
        <translation>此驅動器設定為僅能斷電重新上電解除警報 (%1)：Alarm-Reset 無法解除任何警報。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="106"/>
        <source>%1: could not be read: %2</source>
        <translation>%1：無法讀取：%2</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="110"/>
        <source>%1: no records.</source>
        <translation>%1：無記錄。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="113"/>
        <source>%1: %2 of %3 records, newest first</source>
        <translation>%1：共 %3 筆記錄中的 %2 筆，最新的在前</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="118"/>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="118"/>
        <source>Code</source>
        <translation>代碼</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="118"/>
        <source>Panel</source>
        <translation>面板</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="118"/>
        <source>Name</source>
        <translation>名稱</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="118"/>
        <source>Cleared by</source>
        <translation>解除方式</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="125"/>
        <source>unknown code</source>
        <translation>未知代碼</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="132"/>
        <source>Cause: %1</source>
        <translation>原因：%1</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="134"/>
        <source>Remedy: %1</source>
        <translation>對策：%1</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="136"/>
        <source>To clear: %1</source>
        <translation>解除方法：%1</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="142"/>
        <source>Communication error register (%1): could not be read.</source>
        <translation>通訊錯誤暫存器 (%1)：無法讀取。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="146"/>
        <source>Communication error register (%1): none (0).</source>
        <translation>通訊錯誤暫存器 (%1)：無 (0)。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="149"/>
        <source>Communication error register (%1): %2, not a known code.</source>
        <translation>通訊錯誤暫存器 (%1)：%2，非已知代碼。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="153"/>
        <source>Communication error register (%1): %2 %3
  Cause: %4
  Remedy: %5</source>
        <translation>通訊錯誤暫存器 (%1)：%2 %3
  原因：%4
  對策：%5</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="27"/>
        <source>Machine-readable JSON on standard output.</source>
        <translation>在標準輸出上輸出機器可讀的 JSON。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="28"/>
        <source>Print every frame sent and received on standard error.</source>
        <translation>在標準錯誤輸出上印出每個收發的訊框。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="30"/>
        <source>Drive variant where the drive does not report it: VARIANT, or ID=VARIANT,... (e.g. dbu400, 150=dbu400).</source>
        <translation>驅動器未回報機型時使用的機型：VARIANT，或 ID=VARIANT,... (例如 dbu400, 150=dbu400)。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="32"/>
        <source>VARIANT</source>
        <translation>VARIANT</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="34"/>
        <source>The drives on the bus, e.g. 1,3,5-7 (default: OPENTOP_BUS_DRIVES, else the drives the last scan of this connection found): before a write or command, their communication group is read to name every drive it also reaches.</source>
        <translation>匯流排上的驅動器，例如 1,3,5-7 (預設：OPENTOP_BUS_DRIVES，否則為此連線上次掃描找到的驅動器)：寫入或下指令前會讀取其通訊群組，以列出指令同時送達的每台驅動器。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="37"/>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="39"/>
        <source>Write or command a drive that can be a communication group parent although the drives on the bus are not known (no --bus-drives and no scan of this connection): drives in its group execute it too, unnamed.</source>
        <translation>即使不知道匯流排上有哪些驅動器 (沒有 --bus-drives，此連線也未曾掃描)，仍寫入或下指令給可能為通訊群組主站的驅動器：其群組內的驅動器也會執行，且不會列出。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="43"/>
        <source>Show this help, or a command&apos;s help after the command.</source>
        <translation>顯示此說明；放在指令之後則顯示該指令的說明。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="44"/>
        <source>Show the version.</source>
        <translation>顯示版本。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="48"/>
        <source>Language of the human output: en, zh_TW, zh_CN, ko, ja (default: the system&apos;s). --json output is the same in every language.</source>
        <translation>供人閱讀之輸出的語言：en、zh_TW、zh_CN、ko、ja（預設：系統語言）。--json 輸出在各語言中都相同。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="50"/>
        <source>CODE</source>
        <translation>CODE</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="28"/>
        <source>stopped</source>
        <translation>已停止</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="30"/>
        <source>STILL RUNNING</source>
        <translation>仍在運轉</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="32"/>
        <source>no answer</source>
        <translation>無回應</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="38"/>
        <source>top level</source>
        <translation>最上層</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="41"/>
        <source>&quot;schema&quot; must be 1</source>
        <translation>&quot;schema&quot; 必須為 1</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="52"/>
        <source>&quot;family&quot; must be a lower-case id</source>
        <translation>&quot;family&quot; 必須是小寫的 id</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="60"/>
        <source>serial.parity must be N, E or O</source>
        <translation>serial.parity 必須為 N、E 或 O</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="64"/>
        <source>serial: baud must be 1200–115200 and stopBits 1 or 2</source>
        <translation>serial：baud 必須為 1200–115200，stopBits 必須為 1 或 2</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="76"/>
        <source>serial.formats: &quot;%1&quot; is not a format such as 8N1 or 8E1</source>
        <translation>serial.formats：「%1」不是 8N1 或 8E1 這類的格式</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="80"/>
        <source>serial.formats must hold the default format %1</source>
        <translation>serial.formats 必須包含預設格式 %1</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="84"/>
        <source>serial.powerOnDelayMs must be 0–60000</source>
        <translation>serial.powerOnDelayMs 必須為 0–60000</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="97"/>
        <source>limits: maxReadRegisters 1–125, maxWriteRegisters 1–123</source>
        <translation>limits：maxReadRegisters 須為 1–125，maxWriteRegisters 須為 1–123</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="99"/>
        <source>limits: slaves must lie in 1–247</source>
        <translation>limits：slaves 必須在 1–247 範圍內</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="114"/>
        <source>variants[%1] needs id, model and label</source>
        <translation>variants[%1] 需要 id、model 與 label</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="116"/>
        <source>variants[%1]: id &quot;%2&quot; repeated</source>
        <translation>variants[%1]：id &quot;%2&quot; 重複</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="127"/>
        <source>groups[%1] needs a unique id and a label</source>
        <translation>groups[%1] 需要唯一的 id 與 label</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="138"/>
        <source>readBlocks[%1] needs function 3 or 4 and first ≤ last</source>
        <translation>readBlocks[%1] 需要功能碼 3 或 4，且 first ≤ last</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="182"/>
        <source>%1 has no name</source>
        <translation>%1 沒有名稱</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="184"/>
        <source>%1: reset must be one of %2</source>
        <translation>%1：reset 必須是 %2 其中之一</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="187"/>
        <source>%1: code %2 repeated</source>
        <translation>%1：代碼 %2 重複</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="203"/>
        <source>%1: unknown parameter &quot;%2&quot;</source>
        <translation>%1：未知參數 &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="231"/>
        <source>%1 must be a parameter name, a list of names or an object</source>
        <translation>%1 必須是參數名稱、名稱清單或物件</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="240"/>
        <source>%1: &quot;%2&quot; has no bit field &quot;%3&quot;</source>
        <translation>%1：&quot;%2&quot; 沒有位元欄位 &quot;%3&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="246"/>
        <source>%1: %2 is not a value &quot;%3&quot; can be written with</source>
        <translation>%1：%2 不是 &quot;%3&quot; 可寫入的值</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="264"/>
        <source>decelerationKnobs need the &quot;selected&quot; role</source>
        <translation>decelerationKnobs 需要 &quot;selected&quot; 角色</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="280"/>
        <source>%1 needs &quot;selected&quot; and &quot;maxSeconds&quot;</source>
        <translation>%1 需要 &quot;selected&quot; 與 &quot;maxSeconds&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="283"/>
        <source>%1: &quot;selected&quot; %2 is not a value of the &quot;selected&quot; role, or repeated</source>
        <translation>%1：&quot;selected&quot; %2 不是 &quot;selected&quot; 角色的值，或重複出現</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="288"/>
        <source>%1: &quot;maxSeconds&quot; must be more than 0 and at most 600</source>
        <translation>%1：&quot;maxSeconds&quot; 必須大於 0 且不超過 600</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="320"/>
        <source>%1: &quot;light&quot; must be one of %2, each once</source>
        <translation>%1：&quot;light&quot; 必須是 %2 其中之一，且每個只能出現一次</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="323"/>
        <source>%1: &quot;colour&quot; must be #rrggbb</source>
        <translation>%1：&quot;colour&quot; 必須為 #rrggbb</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="325"/>
        <source>%1: &quot;label&quot; and &quot;meaning&quot; must not be empty</source>
        <translation>%1：&quot;label&quot; 與 &quot;meaning&quot; 不可為空</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="57"/>
        <source> and %1 more</source>
        <translation> 及另外 %1 個</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="28"/>
        <source>not reached</source>
        <translation>未達到</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="35"/>
        <source>error: %1</source>
        <translation>錯誤：%1</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="36"/>
        <source>nothing was written</source>
        <translation>未寫入任何資料</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="60"/>
        <source>NOT RECORDED (%1)</source>
        <translation>未記錄（%1）</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="62"/>
        <source>%1 (kept on this station)</source>
        <translation>%1（保存在本工作站）</translation>
    </message>
</context>
<context>
    <name>opentop::AboutDialog</name>
    <message>
        <location filename="../ui/help/AboutDialog.cpp" line="20"/>
        <source>About OpenTOP</source>
        <translation>關於 OpenTOP</translation>
    </message>
    <message>
        <location filename="../ui/help/AboutDialog.cpp" line="22"/>
        <source>&lt;h2&gt;OpenTOP %1&lt;/h2&gt;&lt;p&gt;Commissioning tool for RS-485 Modbus-RTU motor drives: TROY DBU brushless drives and a DC motor PID controller.&lt;/p&gt;&lt;p&gt;Copyright © the OpenTOP developers.&lt;br&gt;Licence: GNU General Public License, version 3 or any later version (GPL-3.0-or-later). This program comes with ABSOLUTELY NO WARRANTY; it is free software, and you are welcome to redistribute it under the terms of that licence.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Built with&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;Qt %2 (run time; built with %3): GNU Lesser General Public License, version 3 (LGPL-3.0-only); Qt Charts: GNU General Public License, version 3 (GPL-3.0-only)&lt;/li&gt;&lt;li&gt;libmodbus %4: GNU Lesser General Public License, version 2.1 or later (LGPL-2.1-or-later)&lt;/li&gt;&lt;li&gt;GoogleTest (tests only): BSD 3-Clause licence&lt;/li&gt;&lt;/ul&gt;</source>
        <translation>&lt;h2&gt;OpenTOP %1&lt;/h2&gt;&lt;p&gt;RS-485 Modbus-RTU 馬達驅動器試車調機工具：支援 TROY DBU 無刷馬達驅動器及 DC 馬達 PID 控制器。&lt;/p&gt;&lt;p&gt;Copyright © OpenTOP 開發者。&lt;br&gt;授權條款：GNU 通用公共授權條款第 3 版或任何更新版本 (GPL-3.0-or-later)。本程式不提供任何擔保；本程式為自由軟體，歡迎依該授權條款再散布。&lt;/p&gt;&lt;p&gt;&lt;b&gt;使用元件&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;Qt %2 (執行時；建置時為 %3)：GNU 較寬鬆通用公共授權條款第 3 版 (LGPL-3.0-only)；Qt Charts：GNU 通用公共授權條款第 3 版 (GPL-3.0-only)&lt;/li&gt;&lt;li&gt;libmodbus %4：GNU 較寬鬆通用公共授權條款第 2.1 版或更新版本 (LGPL-2.1-or-later)&lt;/li&gt;&lt;li&gt;GoogleTest (僅用於測試)：BSD 3-Clause 授權條款&lt;/li&gt;&lt;/ul&gt;</translation>
    </message>
    <message>
        <location filename="../ui/help/AboutDialog.cpp" line="45"/>
        <source>About &amp;Qt</source>
        <translation>關於 Qt(&amp;Q)</translation>
    </message>
</context>
<context>
    <name>opentop::AccessCheck</name>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="27"/>
        <source>%1 (%2) may not %3: it needs the %4 role or higher</source>
        <translation>%1（%2）不可%3：需要%4或更高角色</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="39"/>
        <location filename="../model/access/AccessCheck.cpp" line="49"/>
        <location filename="../model/access/AccessCheck.cpp" line="122"/>
        <source>the users cannot be read from the results database: %1</source>
        <translation>無法從結果資料庫讀取使用者：%1</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="54"/>
        <source>wrong user name or password</source>
        <translation>使用者名稱或密碼錯誤</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="56"/>
        <source>user &quot;%1&quot;: wrong user name or password</source>
        <translation>使用者「%1」：使用者名稱或密碼錯誤</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="60"/>
        <source>user %1 is disabled</source>
        <translation>使用者 %1 已停用</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="98"/>
        <source>logged in as %1</source>
        <translation>以%1身分登入</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="123"/>
        <source>user %1 is not an active user</source>
        <translation>使用者 %1 不是啟用中的使用者</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="136"/>
        <source>recipe %1 rev. %2, checksum %3</source>
        <translation>配方 %1 版次 %2，校驗碼 %3</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="142"/>
        <source>this station has no users yet: an approval names its approver, so add users first (opentop-cli eol user add)</source>
        <translation>此工站尚無使用者：核准須記名核准人，請先新增使用者（opentop-cli eol user add）</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="151"/>
        <source>the approval was not recorded: %1</source>
        <translation>核准未被記錄：%1</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="155"/>
        <source>%1; approval %2</source>
        <translation>%1；核准 %2</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="184"/>
        <source>the first user must be an administrator (--role administrator): they add everyone else</source>
        <translation>第一位使用者必須是管理員（--role administrator）：由其新增其他所有人</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="189"/>
        <source>add user %1</source>
        <translation>新增使用者 %1</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="196"/>
        <source>user %1 exists already</source>
        <translation>使用者 %1 已存在</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="202"/>
        <source>user %1 (%2) added as %3</source>
        <translation>已新增使用者 %1（%2），角色 %3</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="214"/>
        <source>enable user %1</source>
        <translation>啟用使用者 %1</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="214"/>
        <source>disable user %1</source>
        <translation>停用使用者 %1</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="216"/>
        <location filename="../model/access/AccessCheck.cpp" line="256"/>
        <source>there are no users yet</source>
        <translation>尚無任何使用者</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="223"/>
        <location filename="../model/access/AccessCheck.cpp" line="262"/>
        <source>no user %1</source>
        <translation>沒有使用者 %1</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="228"/>
        <source>%1 is the last active administrator: add another first</source>
        <translation>%1 是最後一位啟用中的管理員：請先新增另一位</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="254"/>
        <source>set the password of %1</source>
        <translation>設定 %1 的密碼</translation>
    </message>
</context>
<context>
    <name>opentop::AccessPolicy</name>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="76"/>
        <source>operator</source>
        <translation>作業員</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="78"/>
        <source>technician</source>
        <translation>技術員</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="80"/>
        <source>engineer</source>
        <translation>工程師</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="84"/>
        <source>administrator</source>
        <translation>管理員</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="96"/>
        <source>test units</source>
        <translation>測試產品</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="98"/>
        <source>reset an alarm and retry</source>
        <translation>重置警報並重試</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="100"/>
        <source>override a retest limit</source>
        <translation>解除重測次數上限</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="102"/>
        <source>leave production mode</source>
        <translation>離開生產模式</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="104"/>
        <source>open or edit a recipe</source>
        <translation>開啟或編輯配方</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="106"/>
        <source>approve a recipe</source>
        <translation>核准配方</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="110"/>
        <source>manage users</source>
        <translation>管理使用者</translation>
    </message>
</context>
<context>
    <name>opentop::AddressSwitches</name>
    <message>
        <location filename="../model/profile/AddressSwitches.cpp" line="66"/>
        <source>address.names: every switch needs a name</source>
        <translation>address.names：每個開關都需要名稱</translation>
    </message>
    <message>
        <location filename="../model/profile/AddressSwitches.cpp" line="74"/>
        <source>address.switches must be &quot;hex-rotary&quot; or &quot;binary-dip&quot;</source>
        <translation>address.switches 必須為 &quot;hex-rotary&quot; 或 &quot;binary-dip&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/AddressSwitches.cpp" line="78"/>
        <source>address.names: 1–%1 switches for this notation</source>
        <translation>address.names：此表示法需 1–%1 個開關</translation>
    </message>
    <message>
        <location filename="../model/profile/AddressSwitches.cpp" line="81"/>
        <source>address: the switches (%1) cannot set machine number %2</source>
        <translation>address：這些開關 (%1) 無法設定機號 %2</translation>
    </message>
</context>
<context>
    <name>opentop::AlarmBanner</name>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="16"/>
        <source>Show</source>
        <translation>顯示</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="17"/>
        <source>Dismiss</source>
        <translation>略過</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="24"/>
        <source>Open the drive&apos;s alarm history</source>
        <translation>開啟此驅動器的警報記錄</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="25"/>
        <source>Hide this alarm until it is cleared; a new alarm shows again</source>
        <translation>在此警報解除前不再顯示；發生新警報時會再次顯示</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="85"/>
        <source>Machine %1: %2 %3 — %4</source>
        <translation>機號 %1：%2 %3 — %4</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="89"/>
        <source>Machine %1: %2 %3</source>
        <translation>機號 %1：%2 %3</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="91"/>
        <source>Machine %1: alarm %2h (not in the alarm table)</source>
        <translation>機號 %1：警報 %2h (不在警報表中)</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="95"/>
        <source>Machine %1: an alarm is active</source>
        <translation>機號 %1：有警報發生中</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/alarms/AlarmBanner.cpp" line="98"/>
        <source>(%n more drive(s) with an alarm)</source>
        <translation>
            <numerusform>(另有 %n 台驅動器發生警報)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::AlarmExport</name>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="50"/>
        <source>Machine</source>
        <translation>機號</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="50"/>
        <source>Model</source>
        <translation>型號</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="50"/>
        <source>Kind</source>
        <translation>類別</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="50"/>
        <source>Record</source>
        <translation>記錄</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="50"/>
        <source>Code</source>
        <translation>代碼</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="50"/>
        <source>Machine name</source>
        <translation>機器名稱</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="51"/>
        <source>Panel code</source>
        <translation>面板代碼</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="51"/>
        <source>Name</source>
        <translation>名稱</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="51"/>
        <source>Cleared by</source>
        <translation>解除方式</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="51"/>
        <source>Cause</source>
        <translation>原因</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="51"/>
        <source>Remedy</source>
        <translation>對策</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="54"/>
        <source>alarm</source>
        <translation>警報</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="55"/>
        <source>warning</source>
        <translation>警告</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="63"/>
        <source>unknown code</source>
        <translation>未知代碼</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="109"/>
        <source>machine %1: %2</source>
        <translation>機號 %1：%2</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/alarms/AlarmExport.cpp" line="132"/>
        <source>%n record(s) of %1 drive(s) written to %2.</source>
        <translation>
            <numerusform>已將 %1 台驅動器的 %n 筆記錄寫入 %2。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="137"/>
        <source>Not everything could be read: %1</source>
        <translation>部分資料無法讀取：%1</translation>
    </message>
</context>
<context>
    <name>opentop::AlarmHistory</name>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="68"/>
        <source>%1: erases the %2</source>
        <translation>%1：清除%2</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="107"/>
        <source>%1 drives have no alarm reset command</source>
        <translation>%1 驅動器沒有警報重置指令</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="182"/>
        <source>The alarm</source>
        <translation>此警報</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="184"/>
        <source>%1 is cleared.</source>
        <translation>%1 已解除。</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="185"/>
        <source>No alarm was active; nothing to clear.</source>
        <translation>沒有發生中的警報，無需解除。</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="188"/>
        <source>%1 is still active: only a power cycle clears it. %2</source>
        <translation>%1 仍在發生中：只能斷電重新上電解除。%2</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="193"/>
        <source>%1 is still active: the drive is set to clear alarms by a power restart only (%2). Remove the cause, turn the power off, wait 5 s and turn it on again; or change that setting to allow the reset command.</source>
        <translation>%1 仍在發生中：此驅動器設定為僅能斷電重新上電解除警報 (%2)。請排除原因，關閉電源，等待 5 s 後再開啟；或變更該設定以允許重置指令。</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="199"/>
        <source>%1 is still active: its cause is still present%2. Remove the cause and turn off the start signal, then reset again.</source>
        <translation>%1 仍在發生中：原因仍然存在%2。請排除原因並關閉啟動訊號，然後再次重置。</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="205"/>
        <source>The reset was accepted; whether an alarm is still active could not be read.</source>
        <translation>重置已被接受，但無法讀取是否仍有警報發生中。</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="207"/>
        <source>The reset failed: %1</source>
        <translation>重置失敗：%1</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="210"/>
        <source>(The drive refused the reset: %1)</source>
        <translation>(驅動器拒絕重置：%1)</translation>
    </message>
</context>
<context>
    <name>opentop::AlarmRecords</name>
    <message>
        <location filename="../model/alarms/AlarmRecords.cpp" line="90"/>
        <location filename="../model/alarms/AlarmRecords.cpp" line="101"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
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
        <translation>代碼</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="50"/>
        <source>Panel</source>
        <translation>面板</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="50"/>
        <source>Name</source>
        <translation>名稱</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="50"/>
        <source>Cleared by</source>
        <translation>解除方式</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="67"/>
        <source>Cause and remedy</source>
        <translation>原因與對策</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="68"/>
        <source>Communication error register</source>
        <translation>通訊錯誤暫存器</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="75"/>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="115"/>
        <source>Select a record to see its cause and remedy.</source>
        <translation>選擇一筆記錄以查看其原因與對策。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="76"/>
        <source>Not read yet.</source>
        <translation>尚未讀取。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="126"/>
        <source>This drive has no communication error register.</source>
        <translation>此驅動器沒有通訊錯誤暫存器。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="128"/>
        <source>%1: could not be read.</source>
        <translation>%1：無法讀取。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="130"/>
        <source>%1: no error (0).</source>
        <translation>%1：無錯誤 (0)。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="133"/>
        <source>%1: %2, not a known code.</source>
        <translation>%1：%2，非已知代碼。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="135"/>
        <source>%1: %2 %3
Cause: %4
Remedy: %5</source>
        <translation>%1：%2 %3
原因：%4
對策：%5</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="147"/>
        <source>No alarm records</source>
        <translation>無警報記錄</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="147"/>
        <source>No warning records</source>
        <translation>無警告記錄</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="153"/>
        <source>%1: could not be read: %2</source>
        <translation>%1：無法讀取：%2</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="156"/>
        <source>%1: %2 of %3 records, newest first</source>
        <translation>%1：共 %3 筆記錄中的 %2 筆，最新的在前</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="167"/>
        <source>unknown code</source>
        <translation>未知代碼</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="196"/>
        <source>Record %1: code %2 is not in the %3 table.</source>
        <translation>記錄 %1：代碼 %2 不在%3表中。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="201"/>
        <source>%1 %2 (record %3)</source>
        <translation>%1 %2 (記錄 %3)</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="203"/>
        <source>Cause: %1</source>
        <translation>原因：%1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="205"/>
        <source>Remedy: %1</source>
        <translation>對策：%1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="207"/>
        <source>To clear: %1</source>
        <translation>解除方法：%1</translation>
    </message>
</context>
<context>
    <name>opentop::AlarmsCommand</name>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="165"/>
        <source>Show alarm and warning histories with causes and remedies; reset, erase</source>
        <translation>顯示警報與警告記錄及其原因與對策；重置、清除</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="172"/>
        <source>Send the alarm reset command, then tell whether the alarm is cleared or needs a power cycle (needs --yes; exit 4 when it stays active).</source>
        <translation>送出警報重置指令，並告知警報是否已解除或需斷電重新上電 (需要 --yes；警報仍存在時結束碼為 4)。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="174"/>
        <source>Erase the alarm and warning records (needs --yes).</source>
        <translation>清除警報與警告記錄 (需要 --yes)。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="175"/>
        <source>Confirm --reset and --clear-records.</source>
        <translation>確認 --reset 與 --clear-records。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="186"/>
        <source>error: usage: %1 (one machine number)</source>
        <translation>錯誤：用法：%1 (一個機號)</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="194"/>
        <source>error: %1</source>
        <translation>錯誤：%1</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="200"/>
        <source>error: machine number %1 (%2) keeps no alarm or warning records</source>
        <translation>錯誤：機號 %1 (%2) 不保存警報或警告記錄</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="207"/>
        <source>error: %1 drives have no %2 command</source>
        <translation>錯誤：%1 驅動器沒有%2指令</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="209"/>
        <source>alarm reset</source>
        <translation>警報重置</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="209"/>
        <source>record erase</source>
        <translation>記錄清除</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="220"/>
        <source>These change machine number %1; add --yes to send them:</source>
        <translation>以下指令將作用於機號 %1；加上 --yes 才會送出：</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="224"/>
        <source>— clears the active alarm if its cause is gone and it is not one that only a power cycle clears</source>
        <translation>— 若原因已排除，且不屬於僅能斷電重新上電解除的警報，即解除發生中的警報</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="249"/>
        <source>Machine number %1 (%2)</source>
        <translation>機號 %1 (%2)</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="277"/>
        <source>Alarm reset: %1</source>
        <translation>警報重置：%1</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="300"/>
        <source>Erased: %1 (%2 records); %3</source>
        <translation>已清除：%1 (%2 筆記錄)；%3</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="303"/>
        <source>read back empty.</source>
        <translation>回讀為空。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="304"/>
        <source>NOT empty when read back.</source>
        <translation>回讀結果「不是」空的。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="307"/>
        <source>Erasing failed: %1</source>
        <translation>清除失敗：%1</translation>
    </message>
</context>
<context>
    <name>opentop::AlarmsPage</name>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="35"/>
        <source>&amp;Re-read</source>
        <translation>重新讀取(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="36"/>
        <source>Reset &amp;alarm…</source>
        <translation>警報重置(&amp;A)…</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="37"/>
        <source>&amp;Clear records…</source>
        <translation>清除記錄(&amp;C)…</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="41"/>
        <source>Alarms and warnings of machine %1 (%2)</source>
        <translation>機號 %1 (%2) 的警報與警告</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="67"/>
        <source>Send the alarm reset command; tells whether the alarm is cleared or only a power cycle clears it</source>
        <translation>送出警報重置指令，並告知警報是否已解除或只能斷電重新上電解除</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="69"/>
        <source>Erase the alarm and warning records kept by the drive</source>
        <translation>清除驅動器保存的警報與警告記錄</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="75"/>
        <source>This drive keeps no alarm or warning records.</source>
        <translation>此驅動器不保存警報或警告記錄。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="105"/>
        <source>Alarm state: %1</source>
        <translation>警報狀態：%1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="187"/>
        <source>Reading the records…</source>
        <translation>正在讀取記錄…</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="203"/>
        <source>No alarm is active.</source>
        <translation>目前無警報。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="205"/>
        <source>Alarm active: %1 %2.</source>
        <translation>警報發生中：%1 %2。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="207"/>
        <source>An alarm is active.</source>
        <translation>有警報發生中。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="210"/>
        <source>This drive is set to clear alarms by a power restart only (%1): Alarm-Reset clears none of them.</source>
        <translation>此驅動器設定為僅能斷電重新上電解除警報 (%1)：Alarm-Reset 無法解除任何警報。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="214"/>
        <source>Could not be read: %1</source>
        <translation>無法讀取：%1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="252"/>
        <source>Writes: %1</source>
        <translation>寫入：%1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="253"/>
        <source>This clears the active alarm if its cause is gone. Some alarms are cleared only by a power cycle; the result tells.</source>
        <translation>若原因已排除，即可解除發生中的警報。部分警報只能斷電重新上電解除；結果會顯示是哪一種。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="256"/>
        <source>This drive is set to clear alarms by a power restart only (%1).</source>
        <translation>此驅動器設定為僅能斷電重新上電解除警報 (%1)。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="258"/>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="260"/>
        <source>Reset alarm</source>
        <translation>警報重置</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="259"/>
        <source>Send the alarm reset command to machine %1?</source>
        <translation>要對機號 %1 送出警報重置指令嗎？</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="267"/>
        <source>Sending the alarm reset…</source>
        <translation>正在送出警報重置…</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="273"/>
        <source>Alarm reset: %1</source>
        <translation>警報重置：%1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="276"/>
        <source>Turn the drive&apos;s power off, wait 5 s and turn it on again.</source>
        <translation>請關閉驅動器電源，等待 5 s 後再開啟。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="287"/>
        <source>%1 (%2 records)</source>
        <translation>%1 (%2 筆記錄)</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="289"/>
        <source>the alarm and warning records</source>
        <translation>警報與警告記錄</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="291"/>
        <source>Clear records</source>
        <translation>清除記錄</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="292"/>
        <source>Erase %1 of machine %2?</source>
        <translation>要清除機號 %2 的%1嗎？</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="292"/>
        <source> and </source>
        <translation> 與 </translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="293"/>
        <source>The records cannot be restored. Writes: %1</source>
        <translation>記錄清除後無法復原。寫入：%1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="295"/>
        <source>Erase</source>
        <translation>清除</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="302"/>
        <source>Erasing the records…</source>
        <translation>正在清除記錄…</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="310"/>
        <source>Erased: %1 (%2 records); %3</source>
        <translation>已清除：%1 (%2 筆記錄)；%3</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="313"/>
        <source>read back empty.</source>
        <translation>回讀為空。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="314"/>
        <source>NOT empty when read back.</source>
        <translation>回讀結果「不是」空的。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="316"/>
        <source>Erasing failed: %1</source>
        <translation>清除失敗：%1</translation>
    </message>
</context>
<context>
    <name>opentop::AutotunePanel</name>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="24"/>
        <source>Autotune…</source>
        <translation>自動調諧…</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="28"/>
        <source>Accept</source>
        <translation>接受</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="29"/>
        <source>Reject</source>
        <translation>拒絕</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="30"/>
        <source>Store in the drive</source>
        <translation>保存至驅動器</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="48"/>
        <source>Writes the proposed gains to the drive (temporary until stored) and offers a step test to compare with the prediction</source>
        <translation>將建議增益寫入驅動器 (保存前僅暫時有效)，並提供步階測試以與預測結果比較</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="50"/>
        <source>Writes back the gains the drive had before</source>
        <translation>將驅動器原本的增益寫回</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="51"/>
        <source>Stores the gains in the drive so that they survive a power cycle; asks first unless the step after Accept passed the check</source>
        <translation>將增益保存至驅動器，斷電重新上電後仍保留；接受後的步階未通過檢查時，會先詢問</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="57"/>
        <source>Operating speed:</source>
        <translation>運轉速度：</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="58"/>
        <source>Relay amplitude:</source>
        <translation>繼電器振幅：</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="59"/>
        <source>%</source>
        <translation>%</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="60"/>
        <source>Rule:</source>
        <translation>調諧規則：</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="64"/>
        <source>Present</source>
        <translation>目前</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="65"/>
        <source>Proposed</source>
        <translation>建議</translation>
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
        <translation>D 週期</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="113"/>
        <source>Enter an operating speed above 0 %1.</source>
        <translation>請輸入大於 0 %1 的運轉速度。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="117"/>
        <source>Enter a relay amplitude of 1–50 %.</source>
        <translation>請輸入 1–50 % 的繼電器振幅。</translation>
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
        <translation>尚無自動調諧結果。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="153"/>
        <source>Autotune failed: %1</source>
        <translation>自動調諧失敗：%1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="155"/>
        <source>What to change: %1</source>
        <translation>應變更的項目：%1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="165"/>
        <source>Relay: Ku %1 %/%2, Tu %3 ms measured, %4 readings per period (one every %5 ms)</source>
        <translation>繼電器：Ku %1 %/%2，實測 Tu %3 ms，每週期讀取 %4 次 (每 %5 ms 一次)</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="175"/>
        <source>The drive&apos;s own loop (model): Ku %1 %/%2, Tu %3 ms</source>
        <translation>驅動器本身的迴路 (模型)：Ku %1 %/%2，Tu %3 ms</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="180"/>
        <source>Proposal: the rule&apos;s P × %1, Ti × %2; predicted overshoot %3 %, settling %4</source>
        <translation>建議值：規則的 P × %1，Ti × %2；預測超調 %3 %，安定 %4</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="184"/>
        <source>not within the record</source>
        <translation>記錄時間內未安定</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="208"/>
        <source>Check after Accept: passed.</source>
        <translation>接受後的檢查：通過。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="209"/>
        <source>Check after Accept: FAILED. Reject writes back the gains the drive had.</source>
        <translation>接受後的檢查：未通過。按「拒絕」會寫回驅動器原本的增益。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="171"/>
        <source>Model: K %1 %2/%, τ %3 ms, dead time %4 ms</source>
        <translation>模型：K %1 %2/%，τ %3 ms，延遲時間 %4 ms</translation>
    </message>
</context>
<context>
    <name>opentop::BackupCommand</name>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="37"/>
        <source>Save every setting of drives to a backup file (written only when all were read)</source>
        <translation>將驅動器的所有設定儲存至備份檔 (全部讀取成功才寫入)</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="43"/>
        <source>The backup file to write (replaced atomically).</source>
        <translation>要寫入的備份檔 (整個檔案一次取代)。</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="44"/>
        <source>FILE</source>
        <translation>FILE</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="46"/>
        <source>Every drive the connection knows (a simulated bus), or every drive a scan finds.</source>
        <translation>連線已知的所有驅動器 (模擬匯流排)，或掃描找到的所有驅動器。</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="54"/>
        <source>error: name the machine numbers, or give --all: backup ID... -o FILE</source>
        <translation>錯誤：請指定機號，或使用 --all：backup ID... -o FILE</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="63"/>
        <location filename="../cli/BackupCommand.cpp" line="245"/>
        <location filename="../cli/BackupCommand.cpp" line="251"/>
        <source>error: %1</source>
        <translation>錯誤：%1</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="72"/>
        <source>scanning the bus for drives…</source>
        <translation>正在掃描匯流排上的驅動器…</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="87"/>
        <source>warning: machine number %1 answered, but its identification failed: it is not backed up; name it to try again (backup %1 -o FILE).</source>
        <translation>警告：機號 %1 有回應，但識別失敗：未備份它；請指定這個機號再試一次 (backup %1 -o FILE)。</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="108"/>
        <source>error: the port %1 was lost while reading %2 (%3)</source>
        <translation>錯誤：讀取 %2 時連接埠 %1 中斷 (%3)</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="112"/>
        <location filename="../cli/BackupCommand.cpp" line="247"/>
        <source>nothing written to %1</source>
        <translation>未寫入任何資料至 %1</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="120"/>
        <source>error: give the file to write: backup ID... -o FILE</source>
        <translation>錯誤：請指定要寫入的檔案：backup ID... -o FILE</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="124"/>
        <source>error: %1; nothing read</source>
        <translation>錯誤：%1；未讀取任何資料</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="136"/>
        <source>interrupted: nothing written</source>
        <translation>已中斷：未寫入任何資料</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="140"/>
        <source>error: no drive answers on %1; nothing written</source>
        <translation>錯誤：%1 上沒有驅動器回應；未寫入任何資料</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="166"/>
        <source>machine number %1</source>
        <translation>機號 %1</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="226"/>
        <source>interrupted while reading machine number %1: nothing written</source>
        <translation>讀取機號 %1 時中斷：未寫入任何資料</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="188"/>
        <source>%1: %2 settings read in %3 requests, %4 ms</source>
        <translation>%1：以 %3 次請求讀取 %2 項設定，%4 ms</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="196"/>
        <source>%1: reading failed, %2 of %3 settings read (%4 requests, %5 ms)</source>
        <translation>%1：讀取失敗，已讀取 %3 項設定中的 %2 項 (%4 次請求，%5 ms)</translation>
    </message>
</context>
<context>
    <name>opentop::BackupDialog</name>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="29"/>
        <source>&amp;Cancel</source>
        <translation>取消(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="30"/>
        <source>&amp;Save the drives read</source>
        <translation>儲存已讀取的驅動器(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="31"/>
        <source>C&amp;lose</source>
        <translation>關閉(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="44"/>
        <source>Back up drives</source>
        <translation>備份驅動器</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="46"/>
        <source>Machine number</source>
        <translation>機號</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="46"/>
        <source>Model</source>
        <translation>型號</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="46"/>
        <source>Progress</source>
        <translation>進度</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="46"/>
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="54"/>
        <source>Save only the drives that were read; the others are left out</source>
        <translation>僅儲存已讀取的驅動器；其餘略過</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="56"/>
        <source>Stop after the drive being read</source>
        <translation>讀完目前這台驅動器後停止</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="84"/>
        <source>Nothing was read: %1.</source>
        <translation>未讀取任何資料：%1。</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="107"/>
        <source>Waiting</source>
        <translation>等待中</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="111"/>
        <source>%v of %m drives</source>
        <translation>%v / %m 台驅動器</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/BackupDialog.cpp" line="112"/>
        <source>Reading the settings of %n drive(s)…</source>
        <translation>
            <numerusform>正在讀取 %n 台驅動器的設定…</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="123"/>
        <source>Stopping after the drive being read…</source>
        <translation>讀完目前這台驅動器後將停止…</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="161"/>
        <source>Not read (cancelled)</source>
        <translation>未讀取 (已取消)</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="37"/>
        <source>drive %1: not identified, nothing read</source>
        <translation>驅動器 %1：無法識別，未讀取任何資料</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="166"/>
        <source>Not identified</source>
        <translation>無法識別</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="139"/>
        <source>Reading…</source>
        <translation>讀取中…</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/BackupDialog.cpp" line="153"/>
        <source>%n setting(s) read in %1 ms</source>
        <translation>
            <numerusform>於 %1 ms 內讀取 %n 項設定</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="167"/>
        <source>Value not allowed</source>
        <translation>不允許的值</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="168"/>
        <source>Read failed</source>
        <translation>讀取失敗</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="184"/>
        <source>Not read: drive(s) %1. Nothing has been saved yet.</source>
        <translation>未讀取：驅動器 %1。尚未儲存任何資料。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/BackupDialog.cpp" line="190"/>
        <source>Save the %n drive(s) that were read?</source>
        <translation>
            <numerusform>要儲存已讀取的 %n 台驅動器嗎？</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/BackupDialog.cpp" line="214"/>
        <source>Saved %n drive(s) to %1.</source>
        <translation>
            <numerusform>已將 %n 台驅動器儲存至 %1。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="220"/>
        <source>Left out (not read): drive(s) %1.</source>
        <translation>已略過 (未讀取)：驅動器 %1。</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="224"/>
        <source>Could not save %1: %2</source>
        <translation>無法儲存 %1：%2</translation>
    </message>
</context>
<context>
    <name>opentop::BackupFile</name>
    <message>
        <location filename="../model/files/BackupFile.cpp" line="309"/>
        <source>%1 is larger than %2 MB, the most a backup file may hold (a backup of 247 drives is far smaller); not a backup file</source>
        <translation>%1 大於備份檔上限 %2 MB (即使 247 台驅動器的備份也遠小於此)；不是備份檔</translation>
    </message>
</context>
<context>
    <name>opentop::BackupFileParser</name>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="49"/>
        <source>not a JSON file: %1 at byte %2</source>
        <translation>不是 JSON 檔：%1 (第 %2 位元組)</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="53"/>
        <source>not an OpenTOP backup file: the JSON is not an object</source>
        <translation>不是 OpenTOP 備份檔：JSON 不是物件</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="63"/>
        <source>&quot;created&quot; is not an ISO 8601 date and time</source>
        <translation>&quot;created&quot; 不是 ISO 8601 日期時間</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="75"/>
        <source>the file holds no drives (&quot;devices&quot; must be a non-empty list)</source>
        <translation>檔案中沒有驅動器 (&quot;devices&quot; 必須是非空的清單)</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="82"/>
        <source>%1: not a drive</source>
        <translation>%1：不是驅動器</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="84"/>
        <source>machine number %1 appears twice</source>
        <translation>機號 %1 出現兩次</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="98"/>
        <source>not an OpenTOP backup file (&quot;format&quot; is &quot;%1&quot;, not &quot;%2&quot;)</source>
        <translation>不是 OpenTOP 備份檔 (&quot;format&quot; 為 &quot;%1&quot;，而非 &quot;%2&quot;)</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="100"/>
        <source>not an OpenTOP backup file (no &quot;format&quot;: &quot;%1&quot;)</source>
        <translation>不是 OpenTOP 備份檔 (沒有 &quot;format&quot;: &quot;%1&quot;)</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="105"/>
        <source>&quot;formatVersion&quot; must be a whole number from 1</source>
        <translation>&quot;formatVersion&quot; 必須是 1 以上的整數</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="107"/>
        <source>written by a newer OpenTOP (format version %1); this version reads format version %2</source>
        <translation>由較新版的 OpenTOP 寫入 (格式版本 %1)；此版本可讀取格式版本 %2</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="113"/>
        <source>the file has no checksum (&quot;checksum&quot;: &quot;sha256:…&quot;); it was not written by OpenTOP or was changed afterwards</source>
        <translation>檔案沒有檢查碼 (&quot;checksum&quot;: &quot;sha256:…&quot;)；並非由 OpenTOP 寫入，或寫入後曾被修改</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="118"/>
        <source>the file was changed after it was written (checksum mismatch)</source>
        <translation>檔案寫入後曾被修改 (檢查碼不符)</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="128"/>
        <source>%1: &quot;slave&quot; must be a machine number 1–247</source>
        <translation>%1：&quot;slave&quot; 必須是 1–247 的機號</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="129"/>
        <source>%1 (machine number %2)</source>
        <translation>%1 (機號 %2)</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="133"/>
        <source>%1: unknown family &quot;%2&quot;; known: %3</source>
        <translation>%1：未知的系列 &quot;%2&quot;；已知：%3</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="138"/>
        <source>%1: &quot;variant&quot; must be text or null</source>
        <translation>%1：&quot;variant&quot; 必須是文字或 null</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="143"/>
        <source>%1: unknown variant &quot;%2&quot; of family %3; known: %4</source>
        <translation>%1：%3 系列沒有機型 &quot;%2&quot;；已知：%4</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="145"/>
        <source>none</source>
        <translation>無</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="153"/>
        <source>%1: &quot;machineName&quot; must be text</source>
        <translation>%1：&quot;machineName&quot; 必須是文字</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="155"/>
        <source>%1: &quot;machineName&quot;: %2</source>
        <translation>%1：&quot;machineName&quot;：%2</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="160"/>
        <source>%1: &quot;parameters&quot; must be a list</source>
        <translation>%1：&quot;parameters&quot; 必須是清單</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="180"/>
        <source>%1: no &quot;name&quot;</source>
        <translation>%1：沒有 &quot;name&quot;</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="183"/>
        <source>%1 %2: &quot;registers&quot; must be a list</source>
        <translation>%1 %2：&quot;registers&quot; 必須是清單</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="187"/>
        <source>%1 %2: registers must be numbers 0–65535</source>
        <translation>%1 %2：暫存器值必須是 0–65535 的數字</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="193"/>
        <source>%1 %2: address &quot;%3&quot;, but the %4 profile has it at %5</source>
        <translation>%1 %2：位址為 &quot;%3&quot;，但 %4 定義檔中位於 %5</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="218"/>
        <source>%1: %2: &quot;value&quot; %3 does not match its registers (%4)</source>
        <translation>%1：%2：&quot;value&quot; %3 與其暫存器 (%4) 不符</translation>
    </message>
</context>
<context>
    <name>opentop::BackupValidator</name>
    <message>
        <location filename="../model/files/BackupValidator.cpp" line="16"/>
        <source>unknown parameter &quot;%1&quot;: the %2 profile has no such setting</source>
        <translation>未知參數 &quot;%1&quot;：%2 定義檔中沒有此設定</translation>
    </message>
    <message>
        <location filename="../model/files/BackupValidator.cpp" line="21"/>
        <source>&quot;%1&quot; is not a setting that backups hold</source>
        <translation>&quot;%1&quot; 不是備份所保存的設定</translation>
    </message>
    <message>
        <location filename="../model/files/BackupValidator.cpp" line="25"/>
        <source>&quot;%1&quot; appears twice</source>
        <translation>&quot;%1&quot; 出現兩次</translation>
    </message>
    <message>
        <location filename="../model/files/BackupValidator.cpp" line="28"/>
        <source>%1: %2 registers, but the parameter has %3</source>
        <translation>%1：%2 個暫存器，但此參數有 %3 個</translation>
    </message>
    <message>
        <location filename="../model/files/BackupValidator.cpp" line="53"/>
        <source>%1: its allowed values depend on %2, which the file does not hold</source>
        <translation>%1：其允許值取決於 %2，但檔案中沒有該項</translation>
    </message>
</context>
<context>
    <name>opentop::BackupViewer</name>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="24"/>
        <source>Backup file</source>
        <translation>備份檔</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="35"/>
        <source>Parameter</source>
        <translation>參數</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="35"/>
        <source>Label</source>
        <translation>標籤</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="35"/>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="35"/>
        <source>Registers</source>
        <translation>暫存器</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="39"/>
        <source>&amp;Open…</source>
        <translation>開啟(&amp;O)…</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="40"/>
        <source>Open another backup file</source>
        <translation>開啟其他備份檔</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="41"/>
        <source>C&amp;lose</source>
        <translation>關閉(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="62"/>
        <source>%1: no such file</source>
        <translation>%1：檔案不存在</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="68"/>
        <source>the file could not be read</source>
        <translation>無法讀取檔案</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="69"/>
        <source>Backup file %1</source>
        <translation>備份檔 %1</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="77"/>
        <source>Open backup file</source>
        <translation>開啟備份檔</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="78"/>
        <source>OpenTOP backups (*.json);;All files (*)</source>
        <translation>OpenTOP 備份檔 (*.json);;所有檔案 (*)</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="100"/>
        <source>File: %1</source>
        <translation>檔案：%1</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="101"/>
        <source>Refused: %1</source>
        <translation>已拒絕：%1</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="116"/>
        <source>, %1 bit/s, parity %2, %3 stop bit(s)</source>
        <translation>，%1 bit/s，同位元 %2，%3 個停止位元</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="118"/>
        <source>File: %1
Written by %2 on %3 (UTC)
Read from: %4
Drives: %5</source>
        <translation>檔案：%1
由 %2 於 %3 (UTC) 寫入
讀取來源：%4
驅動器：%5</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="127"/>
        <source>%1 %2, firmware %3</source>
        <translation>%1 %2，韌體 %3</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="130"/>
        <source>(variant unknown)</source>
        <translation>(機型未知)</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/BackupViewer.cpp" line="133"/>
        <source>%n setting(s)</source>
        <translation>
            <numerusform>%n 項設定</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::BarHideButton</name>
    <message>
        <location filename="../ui/widgets/BarHideButton.cpp" line="9"/>
        <source>Hide this bar</source>
        <translation>隱藏此列</translation>
    </message>
    <message>
        <location filename="../ui/widgets/BarHideButton.cpp" line="10"/>
        <source>Hide</source>
        <translation>隱藏</translation>
    </message>
</context>
<context>
    <name>opentop::BusDocks</name>
    <message>
        <location filename="../ui/main/BusDocks.cpp" line="28"/>
        <source>Traffic log</source>
        <translation>通訊記錄</translation>
    </message>
    <message>
        <location filename="../ui/main/BusDocks.cpp" line="35"/>
        <source>Bus overview</source>
        <translation>匯流排總覽</translation>
    </message>
    <message>
        <location filename="../ui/main/BusDocks.cpp" line="36"/>
        <source>Trends</source>
        <translation>趨勢圖</translation>
    </message>
    <message>
        <location filename="../ui/main/BusDocks.cpp" line="37"/>
        <source>Communication groups</source>
        <translation>通訊群組</translation>
    </message>
    <message>
        <location filename="../ui/main/BusDocks.cpp" line="40"/>
        <location filename="../ui/main/BusDocks.cpp" line="110"/>
        <source>Not connected</source>
        <translation>未連線</translation>
    </message>
</context>
<context>
    <name>opentop::BusDriveList</name>
    <message>
        <location filename="../cli/BusDriveList.cpp" line="11"/>
        <source>%1 s ago</source>
        <translation>%1 秒前</translation>
    </message>
    <message>
        <location filename="../cli/BusDriveList.cpp" line="13"/>
        <source>%1 min ago</source>
        <translation>%1 分鐘前</translation>
    </message>
    <message>
        <location filename="../cli/BusDriveList.cpp" line="15"/>
        <source>%1 h ago</source>
        <translation>%1 小時前</translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/BusDriveList.cpp" line="16"/>
        <source>%n day(s) ago</source>
        <translation>
            <numerusform>%n 天前</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../cli/BusDriveList.cpp" line="27"/>
        <source>the simulated bus&apos;s drives</source>
        <translation>模擬匯流排的驅動器</translation>
    </message>
    <message>
        <location filename="../cli/BusDriveList.cpp" line="30"/>
        <source>the drives last seen on %1</source>
        <translation>上次在 %1 看到的驅動器</translation>
    </message>
    <message>
        <location filename="../cli/BusDriveList.cpp" line="31"/>
        <source>the drives the last scan of %1 found (%2, %3)</source>
        <translation>上次掃描 %1 找到的驅動器 (%2，%3)</translation>
    </message>
    <message>
        <location filename="../cli/BusDriveList.cpp" line="38"/>
        <source>no list of the drives on the bus</source>
        <translation>沒有匯流排上驅動器的清單</translation>
    </message>
</context>
<context>
    <name>opentop::BusGroups</name>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="109"/>
        <source>machine number %1 is the parent of communication group %1: what is sent to it is also executed by %2 (children do not reply)</source>
        <translation>機號 %1 是通訊群組 %1 的群組母站：送給它的指令也會由 %2 執行 (群組子站不回應)</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="127"/>
        <location filename="../model/bus/BusGroups.cpp" line="136"/>
        <source>%1 and %2</source>
        <translation>%1 與 %2</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="145"/>
        <source>This also reaches machine number %1 (the child of communication group %2; it executes it without replying).</source>
        <translation>此操作也會送達機號 %1 (通訊群組 %2 的群組子站；會執行但不回應)。</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="149"/>
        <source>This also reaches machine numbers %1 (the children of communication group %2; they execute it without replying).</source>
        <translation>此操作也會送達機號 %1 (通訊群組 %2 的群組子站；會執行但不回應)。</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="159"/>
        <source>child of %1</source>
        <translation>群組 %1 子站</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="162"/>
        <source>parent of %1</source>
        <translation>群組 %1 母站</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="170"/>
        <source>machine number %1 is a child of %2 and itself a parent: a child must not be a group parent</source>
        <translation>機號 %1 是群組 %2 的子站，本身又是母站：群組子站不可同時為群組母站</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="175"/>
        <source>machine number %1 is in communication group %2, but no drive %2 is known: frames to %2 reach %1 although nothing answers</source>
        <translation>機號 %1 屬於通訊群組 %2，但找不到機號 %2 的驅動器：送往 %2 的訊框會送達 %1，但不會有任何回應</translation>
    </message>
</context>
<context>
    <name>opentop::BusLeaving</name>
    <message>
        <location filename="../ui/main/BusLeaving.cpp" line="68"/>
        <location filename="../ui/main/BusLeaving.cpp" line="88"/>
        <source>quit</source>
        <translation>結束</translation>
    </message>
    <message>
        <location filename="../ui/main/BusLeaving.cpp" line="77"/>
        <source>Unwritten changes</source>
        <translation>未寫入的變更</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/main/BusLeaving.cpp" line="78"/>
        <source>%n edit(s) have not been written to the drives. Quit and discard them?</source>
        <translation>
            <numerusform>有 %n 項變更尚未寫入驅動器。要結束並捨棄這些變更嗎？</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::BusListMenu</name>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="30"/>
        <source>&amp;Name this machine…</source>
        <translation>為此機器命名(&amp;N)…</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="36"/>
        <source>&amp;Identify again</source>
        <translation>重新識別(&amp;I)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="47"/>
        <source>&amp;Remove from list</source>
        <translation>從清單移除(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="62"/>
        <source>Name of %1 (up to %2 characters; empty removes the name):</source>
        <translation>%1 的名稱 (最多 %2 個字元；留空即刪除名稱)：</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="69"/>
        <source>Name this machine</source>
        <translation>為此機器命名</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="76"/>
        <source>Machine number %1 has no name now.</source>
        <translation>機號 %1 現在沒有名稱。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="77"/>
        <source>Machine number %1 is now named %2.</source>
        <translation>機號 %1 現在名為 %2。</translation>
    </message>
</context>
<context>
    <name>opentop::BusListModel</name>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="76"/>
        <source>Machine number: the drive&apos;s address on the bus (1–247)</source>
        <translation>機號：驅動器在匯流排上的位址（1–247）</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="78"/>
        <source>The drive&apos;s MONITOR LED: red alarm, green ready, orange CW, sky blue CCW, purple external interrupt, blue memory or communication error, grey no answer</source>
        <translation>驅動器的 MONITOR LED：紅色為警報、綠色為就緒、橘色為 CW、天藍色為 CCW、紫色為外部中斷、藍色為記憶體或通訊錯誤、灰色為無回應</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="85"/>
        <source>LED</source>
        <translation>LED</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="87"/>
        <source>No.</source>
        <translation>機號</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="91"/>
        <source>Family</source>
        <translation>系列</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="93"/>
        <source>Model</source>
        <translation>型號</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="95"/>
        <source>Firmware</source>
        <translation>韌體</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="97"/>
        <source>State</source>
        <translation>狀態</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="99"/>
        <source>Control priority</source>
        <translation>控制優先權</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="73"/>
        <source>How each drive&apos;s machine number is set on its switches:
%1</source>
        <translation>各驅動器的機號在其開關上的設定方式：
%1</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="89"/>
        <source>Switches</source>
        <translation>開關</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="101"/>
        <source>Name</source>
        <translation>名稱</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="113"/>
        <source>Two drives may share machine number %1 (%2): check the address switches of every drive on the line, give each drive its own number and restart its power; a bad termination or a swapped A/B pair also corrupts replies.</source>
        <translation>可能有兩台驅動器共用機號 %1 (%2)：請檢查線路上每台驅動器的位址開關，為每台驅動器設定不同的機號並重新上電；終端電阻不良或 A/B 接反也會使回應損壞。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="134"/>
        <source>%1 at %2</source>
        <translation>%1，%2</translation>
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
        <translation>%1 — 機型未知</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="142"/>
        <source>V%1</source>
        <translation>V%1</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="171"/>
        <source>Status light %1: %2 (%3)</source>
        <translation>狀態燈 %1：%2 (%3)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="175"/>
        <source>The drive&apos;s manual: %1</source>
        <translation>驅動器手冊：%1</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="178"/>
        <source>Status light grey: not live — %1</source>
        <translation>狀態燈灰色：非即時 — %1</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="186"/>
        <source>No name yet: Name… in the context menu (F2) names this machine</source>
        <translation>尚無名稱：在右鍵選單中選「命名…」(F2) 為此機器命名</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="187"/>
        <source>%1: the name given to this machine (F2 changes it)</source>
        <translation>%1：此機器的名稱 (F2 可變更)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="190"/>
        <source>Requests to this drive go out at %1, its own line format, not the port&apos;s: the line is switched to it and back between transactions. Change it with Line format… in the context menu.</source>
        <translation>送往此驅動器的要求以它自己的通訊格式 %1 送出，而非連接埠的格式：線路在交易之間切換過去再切換回來。可在右鍵選單的「通訊格式…」中變更。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="197"/>
        <source>The drive does not report its variant. Choose it from the context menu (Variant) so that values are checked against the right limits.</source>
        <translation>此驅動器不回報機型。請從右鍵選單 (機型) 中選擇，以便依正確的範圍檢查數值。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="206"/>
        <source>The drive takes run commands from its I/O terminals; test runs over the bus need communication priority.</source>
        <translation>此驅動器由 I/O 端子接收運轉指令；要透過匯流排試運轉，需設為通訊優先。</translation>
    </message>
</context>
<context>
    <name>opentop::BusMemory</name>
    <message>
        <location filename="../model/bus/BusMemory.cpp" line="79"/>
        <source>the simulated bus</source>
        <translation>模擬匯流排</translation>
    </message>
</context>
<context>
    <name>opentop::BusOverview</name>
    <message>
        <location filename="../ui/bus/BusOverview.cpp" line="37"/>
        <source>Double-click a drive to open its pages.</source>
        <translation>按兩下驅動器以開啟其頁面。</translation>
    </message>
</context>
<context>
    <name>opentop::BusOverviewModel</name>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="133"/>
        <source>Drive</source>
        <translation>驅動器</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="135"/>
        <source>State</source>
        <translation>狀態</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="137"/>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="139"/>
        <source>Display</source>
        <translation>顯示</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="141"/>
        <source>Target</source>
        <translation>目標</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="143"/>
        <source>Load</source>
        <translation>負載</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="145"/>
        <source>Alarm</source>
        <translation>警報</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="147"/>
        <source>Last answer</source>
        <translation>最後回應</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="174"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="164"/>
        <source>connection lost; %1</source>
        <translation>連線中斷；%1</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="166"/>
        <source>no answer: %1; %2</source>
        <translation>無回應：%1；%2</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="203"/>
        <source>none</source>
        <translation>無</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="206"/>
        <source>active</source>
        <translation>發生中</translation>
    </message>
</context>
<context>
    <name>opentop::BusPanel</name>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="35"/>
        <source>&amp;Scan</source>
        <translation>掃描(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="38"/>
        <source>A&amp;dd drive…</source>
        <translation>新增驅動器(&amp;D)…</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="40"/>
        <source>Ca&amp;ncel</source>
        <translation>取消(&amp;N)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="50"/>
        <source>Ask every machine number of the range who answers</source>
        <translation>逐一詢問範圍內的每個機號是否有回應</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="52"/>
        <source>&amp;from</source>
        <translation>從(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="54"/>
        <source>&amp;to</source>
        <translation>到(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="77"/>
        <source>Identify one machine number and add it to the list</source>
        <translation>識別一個機號並加入清單</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="82"/>
        <location filename="../ui/bus/BusPanel.cpp" line="221"/>
        <source>%v of %m</source>
        <translation>%v / %m</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="83"/>
        <source>Scan progress</source>
        <translation>掃描進度</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="85"/>
        <source>Stop the scan after the request on the wire</source>
        <translation>目前線上的請求完成後停止掃描</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="95"/>
        <source>Rescan at %1</source>
        <translation>以 %1 重新掃描</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="135"/>
        <source>Drives on the bus</source>
        <translation>匯流排上的驅動器</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="151"/>
        <source>Name this machine…</source>
        <translation>為此機器命名…</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="207"/>
        <source>%v of %m (machine number %1)</source>
        <translation>%v / %m (機號 %1)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="211"/>
        <source>Machine number %1 answered, identification failed: retrying (%2 of %3)… Polling waits until the scan is over.</source>
        <translation>機號 %1 有回應，但識別失敗：重試中 (第 %2 次，共 %3 次)… 輪詢會等到掃描結束。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="223"/>
        <source>Scanning machine numbers %1–%2 on %3, %4 ms each… Polling waits until the scan is over.</source>
        <translation>正在 %3 上掃描機號 %1–%2，每個 %4 ms… 輪詢會等到掃描結束。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="295"/>
        <source>If one is on this bus, add it with Add drive and its line format.</source>
        <translation>若匯流排上有這種驅動器，請用「新增驅動器」連同它的通訊格式加入。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="300"/>
        <source>Machine number %1 answered, but its identification failed, also when asked again: add it by hand with Add drive…, or check its line settings and scan again.</source>
        <translation>機號 %1 有回應，但識別失敗，重新詢問也一樣：請用「新增驅動器…」手動加入，或檢查它的通訊設定後重新掃描。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="243"/>
        <source>Cancelling after the request on the wire…</source>
        <translation>目前線上的請求完成後取消…</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="59"/>
        <source>Machine numbers 1–247, as set on each drive&apos;s switches:
%1</source>
        <translation>機號 1–247，依各驅動器開關的設定：
%1</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="261"/>
        <source>Did not answer the last scan.</source>
        <translation>上次掃描未回應。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="267"/>
        <source>The scan stopped at machine number %1: %2</source>
        <translation>掃描在機號 %1 停止：%2</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/bus/BusPanel.cpp" line="272"/>
        <source>Scan cancelled after machine numbers %1–%2 (%3 of %4): %n drive(s) found.</source>
        <translation>
            <numerusform>掃描於機號 %1–%2 後取消 (%3 / %4)：找到 %n 台驅動器。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/bus/BusPanel.cpp" line="280"/>
        <source>%n drive(s) found on machine numbers %1–%2 in %3 s.</source>
        <translation>
            <numerusform>在機號 %1–%2 中找到 %n 台驅動器，耗時 %3 s。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="321"/>
        <source>Asking machine number %1…</source>
        <translation>正在詢問機號 %1…</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="326"/>
        <source>Machine number %1: %2 added.</source>
        <translation>機號 %1：已新增 %2。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="328"/>
        <source>Machine number %1: %2 %3</source>
        <translation>機號 %1：%2 %3</translation>
    </message>
    <message>
        <location filename="../ui/bus/VariantMenu.cpp" line="26"/>
        <source>&amp;Variant</source>
        <translation>機型(&amp;V)</translation>
    </message>
</context>
<context>
    <name>opentop::BusRecallBar</name>
    <message>
        <location filename="../ui/bus/BusRecallBar.cpp" line="21"/>
        <source>&amp;Scan the bus</source>
        <translation>掃描匯流排(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusRecallBar.cpp" line="44"/>
        <source>Last time on %1: %2.</source>
        <translation>上次在 %1：%2。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusRecallBar.cpp" line="46"/>
        <source>&amp;Restore the drive last seen</source>
        <translation>恢復上次出現的驅動器(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusRecallBar.cpp" line="47"/>
        <source>&amp;Restore the %1 drives last seen</source>
        <translation>恢復上次出現的 %1 台驅動器(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusRecallBar.cpp" line="48"/>
        <source>Identify the drives at these machine numbers again, with the variants set last time</source>
        <translation>以上次設定的機型，重新識別這些機號上的驅動器</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusRecallBar.cpp" line="62"/>
        <source>No drive is known on %1 yet. Scan the bus to find the drives.</source>
        <translation>%1 上尚無已知的驅動器。請掃描匯流排以尋找驅動器。</translation>
    </message>
</context>
<context>
    <name>opentop::BusRestore</name>
    <message>
        <location filename="../model/files/BusRestore.cpp" line="26"/>
        <source>machine number %1 is not a drive on the bus</source>
        <translation>機號 %1 不是匯流排上的驅動器</translation>
    </message>
    <message>
        <location filename="../model/files/BusRestore.cpp" line="97"/>
        <source>not attempted</source>
        <translation>未執行</translation>
    </message>
</context>
<context>
    <name>opentop::BusScanner</name>
    <message>
        <location filename="../model/bus/BusScanner.cpp" line="152"/>
        <source>garbled replies twice (%1): two drives probably share machine number %2; check their address switches (%3)</source>
        <translation>兩次收到損壞的回應 (%1)：可能有兩台驅動器共用機號 %2；請檢查其位址開關 (%3)</translation>
    </message>
    <message>
        <location filename="../model/bus/BusScanner.cpp" line="158"/>
        <source>answers, but none of the device profiles matches (%1)</source>
        <translation>有回應，但沒有符合的定義檔 (%1)</translation>
    </message>
    <message>
        <location filename="../model/bus/BusScanner.cpp" line="171"/>
        <source>answered, but its identification read got no reply (%1), also when asked %2 more times: add it by hand, or scan with a longer wait</source>
        <translation>有回應，但識別讀取沒有回覆 (%1)，再詢問 %2 次也一樣：請手動新增，或以較長的等待時間重新掃描</translation>
    </message>
    <message>
        <location filename="../model/bus/BusScanner.cpp" line="243"/>
        <source>answered late at first (after the %1 ms wait); a longer wait makes scans of this bus reliable</source>
        <translation>第一次回應過慢 (超過 %1 ms 等待時間)；加長等待時間可使此匯流排的掃描更可靠</translation>
    </message>
</context>
<context>
    <name>opentop::BusSpec</name>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="57"/>
        <source>&quot;%1&quot;: the braces do not pair; a drive&apos;s defects are written in braces after its number, e.g. dbu200@3{firmware=1.4,stall}</source>
        <translation>&quot;%1&quot;：大括號不成對；驅動器的缺陷寫在其機號後的大括號內，例如 dbu200@3{firmware=1.4,stall}</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="62"/>
        <source>empty device list; write TYPE@ID[,TYPE@ID...], e.g. dbu200@1,dcpid@7 (types: %1)</source>
        <translation>裝置清單為空；請寫成 TYPE@ID[,TYPE@ID...]，例如 dbu200@1,dcpid@7 (類型：%1)</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="70"/>
        <source>&quot;%1&quot;: the defects in braces end the item, e.g. dbu200@3{stall}</source>
        <translation>&quot;%1&quot;：大括號內的缺陷必須放在項目最後，例如 dbu200@3{stall}</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="78"/>
        <source>&quot;%1&quot;: write TYPE@ID or TYPE@FIRST-LAST, e.g. dbu200@1</source>
        <translation>&quot;%1&quot;：請寫成 TYPE@ID 或 TYPE@FIRST-LAST，例如 dbu200@1</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="83"/>
        <source>&quot;%1&quot;: unknown device type &quot;%2&quot;; known types: %3</source>
        <translation>&quot;%1&quot;：未知的裝置類型 &quot;%2&quot;；已知類型：%3</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="90"/>
        <source>&quot;%1&quot;: the machine number must be a number or a range such as 1-16</source>
        <translation>&quot;%1&quot;：機號必須是數字或 1-16 這樣的範圍</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="94"/>
        <source>&quot;%1&quot;: machine number %2 is outside %3–%4 for %5</source>
        <translation>&quot;%1&quot;：機號 %2 超出 %5 的範圍 %3–%4</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="101"/>
        <source>machine number %1 is given twice</source>
        <translation>機號 %1 重複指定</translation>
    </message>
</context>
<context>
    <name>opentop::CertificateHtml</name>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="48"/>
        <source>PASS</source>
        <translation>合格</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="50"/>
        <location filename="../model/eol/CertificateHtml.cpp" line="144"/>
        <source>FAIL</source>
        <translation>不合格</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="52"/>
        <source>ABORTED</source>
        <translation>已中止</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="54"/>
        <source>STATION ERROR</source>
        <translation>工站錯誤</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="56"/>
        <source>INTERRUPTED</source>
        <translation>已中斷</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="58"/>
        <source>NOT FINISHED</source>
        <translation>未完成</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="71"/>
        <source>none</source>
        <translation>無</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="78"/>
        <source>End-of-line test certificate</source>
        <translation>終檢測試證書</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="81"/>
        <source>Serial number</source>
        <translation>序號</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="82"/>
        <location filename="../model/eol/CertificateHtml.cpp" line="148"/>
        <source>Recipe</source>
        <translation>配方</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="82"/>
        <source>%1, revision %2</source>
        <translation>%1，版次 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="83"/>
        <source>Recipe checksum</source>
        <translation>配方檢查碼</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="84"/>
        <source>Recipe approved by</source>
        <translation>配方核准人</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="85"/>
        <source>not approved (station without users)</source>
        <translation>未核准（工站無使用者）</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="86"/>
        <source>%1 (approval %2)</source>
        <translation>%1（核准 %2）</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="87"/>
        <source>Station</source>
        <translation>工站</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="88"/>
        <source>Operator</source>
        <translation>作業員</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="89"/>
        <location filename="../model/eol/CertificateHtml.cpp" line="148"/>
        <source>Attempt</source>
        <translation>測試次數</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="90"/>
        <source>%1 (tests of this serial under this recipe)</source>
        <translation>第 %1 次（此序號在此配方下的測試）</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="91"/>
        <source>not counted (recorded before attempts were)</source>
        <translation>未計次（記錄時尚未統計測試次數）</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="92"/>
        <location filename="../model/eol/CertificateHtml.cpp" line="148"/>
        <source>Started</source>
        <translation>開始時間</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="93"/>
        <source>Ended</source>
        <translation>結束時間</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="94"/>
        <source>Record</source>
        <translation>記錄</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="103"/>
        <source>First failure:</source>
        <translation>首個不合格項目：</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/eol/CertificateHtml.cpp" line="121"/>
        <source>This serial failed %n earlier test(s); they are listed below.</source>
        <translation>
            <numerusform>此序號先前有 %n 次測試不合格，列於下方。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="124"/>
        <source>Drives</source>
        <translation>驅動器</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="125"/>
        <source>Machine number</source>
        <translation>機號</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="125"/>
        <source>Model</source>
        <translation>型號</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="125"/>
        <source>Variant</source>
        <translation>機型</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="125"/>
        <source>Firmware</source>
        <translation>韌體</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="125"/>
        <source>How known</source>
        <translation>如何得知</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="130"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="133"/>
        <source>Settings</source>
        <translation>設定</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="133"/>
        <location filename="../model/eol/CertificateHtml.cpp" line="141"/>
        <source>Drive</source>
        <translation>驅動器</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="133"/>
        <source>Setting</source>
        <translation>設定</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="133"/>
        <location filename="../model/eol/CertificateHtml.cpp" line="141"/>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="133"/>
        <source>Written</source>
        <translation>寫入值</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="134"/>
        <source>Read back</source>
        <translation>回讀值</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="134"/>
        <source>Verified</source>
        <translation>已驗證</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="137"/>
        <source>written</source>
        <translation>已寫入</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="137"/>
        <source>already set</source>
        <translation>原已設定</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="138"/>
        <source>yes</source>
        <translation>是</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="138"/>
        <source>NO</source>
        <translation>否</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="140"/>
        <source>Measurements</source>
        <translation>量測值</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="141"/>
        <source>Step</source>
        <translation>步驟</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="141"/>
        <source>Quantity</source>
        <translation>量測項目</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="141"/>
        <source>Limits</source>
        <translation>限值</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="141"/>
        <location filename="../model/eol/CertificateHtml.cpp" line="148"/>
        <source>Verdict</source>
        <translation>判定</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="144"/>
        <source>pass</source>
        <translation>合格</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="147"/>
        <source>Earlier tests of this serial</source>
        <translation>此序號先前的測試</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="148"/>
        <source>Reason</source>
        <translation>原因</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="150"/>
        <source>%1 rev. %2</source>
        <translation>%1 版次 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="151"/>
        <source>–</source>
        <translation>–</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="161"/>
        <source>Bus traffic around the failure</source>
        <translation>不合格前後的匯流排通訊</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="176"/>
        <source>read from the drive</source>
        <translation>從驅動器讀取</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="178"/>
        <source>proven by the variant probe</source>
        <translation>由機型探測證實</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="180"/>
        <source>confirmed by a person</source>
        <translation>由人員確認</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="182"/>
        <source>ASSUMED, not proven</source>
        <translation>推定，未證實</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="186"/>
        <location filename="../model/eol/CertificateHtml.cpp" line="192"/>
        <source>not known</source>
        <translation>未知</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="194"/>
        <source>%1 (assumed)</source>
        <translation>%1（推定）</translation>
    </message>
</context>
<context>
    <name>opentop::CertificatePdf</name>
    <message>
        <location filename="../report/CertificatePdf.cpp" line="26"/>
        <source>End-of-line certificate %1</source>
        <translation>終檢測試證書 %1</translation>
    </message>
    <message>
        <location filename="../report/CertificatePdf.cpp" line="57"/>
        <source>%1 · %2 · page %3 of %4</source>
        <translation>%1 · %2 · 第 %3 頁，共 %4 頁</translation>
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
        <translation>用法：%1 [選項] COMMAND [引數]

RS-485 Modbus-RTU 馬達驅動器試車調機工具。

指令：
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
連線 (所有與驅動器通訊的指令)：
  --port PATH | --tcp HOST:PORT | --sim SPEC
  --family F  --baud N  --parity N|E|O  --stop-bits N  --timeout MS  --retries N
  預設值依系列而定：dbu 19200 8N1，dcpid 9600 8E1；--timeout 200，
  --retries 3 (線路雜訊多時再加 2 次：即最近有請求需要重試時)。
  僅限序列埠：--rs485 off|auto|kernel|rts (由誰切換 RS-485
  收發方向；off：轉接器)，--rts-polarity high|low，--rts-delay US，
  --low-latency on|off (預設 on)。scan 會顯示驅動程式接受的設定。
輸出：--json  --trace  --variant VARIANT  --lang CODE
群組：寫入或下指令前，會讀取匯流排上驅動器的通訊群組：--bus-drives LIST
(或 OPENTOP_BUS_DRIVES)，否則為此連線上次掃描找到的驅動器 (在此或在視窗中)；
兩者皆無時，寫入可能為群組主站的驅動器會被拒絕，除非加上 --no-group-check

結束碼：0 成功，1 通訊失敗，2 用法錯誤，3 值或檔案無效
(未寫入任何資料)，4 驗證不符或驅動器未停止，
5 eol run 不合格，6 eol run 工站錯誤 (未對產品作出判定)，
130 被 Ctrl-C、SIGTERM 或 SIGHUP 中斷 (會回報已完成的操作)。

&quot;%1 help COMMAND&quot; 顯示指令的選項。
</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="125"/>
        <source>note: standard output could not be written (closed early, or the disk is full): what the command printed there is lost; the work itself ran to its end and exit status %1 says how it ended</source>
        <translation>注意：無法寫入標準輸出 (提早關閉或磁碟已滿)：指令在該處輸出的內容已遺失；工作本身已執行完畢，結束狀態 %1 表示其結果</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="190"/>
        <location filename="../cli/CliApp.cpp" line="245"/>
        <source>Try &quot;%1 --help&quot;.</source>
        <translation>請執行 &quot;%1 --help&quot;。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="210"/>
        <source>%1: unknown command &quot;%2&quot;; commands: </source>
        <translation>%1：未知指令 &quot;%2&quot;；可用指令： </translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="219"/>
        <source>Usage: %1 [options] %2
%3
</source>
        <translation>用法：%1 [選項] %2
%3
</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="233"/>
        <source>%1 %2: --%3 is not an option of this command; see &quot;%1 help %2&quot;</source>
        <translation>%1 %2：--%3 不是此指令的選項；請參閱 &quot;%1 help %2&quot;</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="244"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
</context>
<context>
    <name>opentop::CliContext</name>
    <message>
        <location filename="../cli/CliContext.cpp" line="127"/>
        <location filename="../cli/CliContext.cpp" line="141"/>
        <location filename="../cli/CliContext.cpp" line="149"/>
        <source>error: %1</source>
        <translation>錯誤：%1</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="154"/>
        <source>serial line: %1</source>
        <translation>序列線路：%1</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="177"/>
        <source>%1 &quot;%2&quot;: %3</source>
        <translation>%1 &quot;%2&quot;：%3</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="289"/>
        <source>machine number %1: no connection</source>
        <translation>機號 %1：未連線</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="294"/>
        <source>machine number %1: %2%3</source>
        <translation>機號 %1：%2%3</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="352"/>
        <source>--variant %1: &quot;%2&quot; is not a machine number 1–247</source>
        <translation>--variant %1：&quot;%2&quot; 不是 1–247 的機號</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="356"/>
        <source>--variant %1: &quot;%2&quot; is not a drive variant; use one of %3</source>
        <translation>--variant %1：&quot;%2&quot; 不是驅動器機型；請使用下列其中之一：%3</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="374"/>
        <source>&quot;%1&quot; is not a machine number 1–247 or a range such as 3-8</source>
        <translation>&quot;%1&quot; 不是 1–247 的機號，也不是 3-8 這樣的範圍</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="384"/>
        <source>no machine number given</source>
        <translation>未指定機號</translation>
    </message>
</context>
<context>
    <name>opentop::CliIdentity</name>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="73"/>
        <source>Who does it (a user of the results database); the password comes from OPENTOP_PASSWORD or is asked on the terminal.</source>
        <translation>執行者（結果資料庫的使用者）；密碼取自 OPENTOP_PASSWORD，否則在終端機上詢問。</translation>
    </message>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="75"/>
        <source>NAME</source>
        <translation>名稱</translation>
    </message>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="86"/>
        <source>error: no password: set %1 or run on a terminal</source>
        <translation>錯誤：沒有密碼：請設定 %1 或在終端機上執行</translation>
    </message>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="91"/>
        <source>Again: </source>
        <translation>再輸入一次：</translation>
    </message>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="93"/>
        <source>error: the passwords differ; nothing was changed</source>
        <translation>錯誤：兩次密碼不同；未做任何變更</translation>
    </message>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="104"/>
        <source>error: name who does it with --user NAME</source>
        <translation>錯誤：請以 --user NAME 指定執行者</translation>
    </message>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="108"/>
        <source>Password for %1: </source>
        <translation>%1 的密碼：</translation>
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
        <translation>斷電重新上電</translation>
    </message>
    <message>
        <location filename="../model/profile/CodeTable.cpp" line="14"/>
        <source>by itself</source>
        <translation>自動解除</translation>
    </message>
    <message>
        <location filename="../model/profile/CodeTable.cpp" line="15"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location filename="../model/profile/CodeTable.cpp" line="24"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../model/profile/CodeTable.cpp" line="29"/>
        <source>What to do: %1</source>
        <translation>處理方式：%1</translation>
    </message>
</context>
<context>
    <name>opentop::CommLossArm</name>
    <message>
        <location filename="../model/eol/CommLossArm.cpp" line="29"/>
        <source>cannot read %1: %2</source>
        <translation>無法讀取 %1：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/CommLossArm.cpp" line="40"/>
        <source>the communication-loss stop cannot be armed (%1 = %2 s): %3; the motor is not started without it</source>
        <translation>無法啟用通訊中斷停止（%1 = %2 s）：%3；沒有它不會啟動馬達</translation>
    </message>
</context>
<context>
    <name>opentop::CommandReadBack</name>
    <message>
        <location filename="../ui/run/CommandReadBack.cpp" line="43"/>
        <source>Read back after the command at %1:</source>
        <translation>%1 指令後回讀：</translation>
    </message>
    <message>
        <location filename="../ui/run/CommandReadBack.cpp" line="46"/>
        <source>The motor is running.</source>
        <translation>馬達運轉中。</translation>
    </message>
    <message>
        <location filename="../ui/run/CommandReadBack.cpp" line="46"/>
        <source>The motor is stopped.</source>
        <translation>馬達已停止。</translation>
    </message>
    <message>
        <location filename="../ui/run/CommandReadBack.cpp" line="48"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../ui/run/CommandReadBack.cpp" line="50"/>
        <source>(not read: %1)</source>
        <translation>(未讀取：%1)</translation>
    </message>
    <message>
        <location filename="../ui/run/CommandReadBack.cpp" line="57"/>
        <source>The drives of its communication group, read after the command:</source>
        <translation>指令後讀取的通訊群組驅動器：</translation>
    </message>
</context>
<context>
    <name>opentop::CompareCommand</name>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="36"/>
        <source>Show the settings that differ; A, B: a machine number, FILE or FILE:ID (exit 0 whether or not they differ)</source>
        <translation>顯示不同的設定；A、B：機號、FILE 或 FILE:ID (無論是否有差異，結束碼皆為 0)</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="43"/>
        <source>Compare A with the profile&apos;s factory defaults; settings the manual gives no default for are listed, never counted as differences.</source>
        <translation>將 A 與定義檔中的出廠預設值比較；手冊未列預設值的設定會列出，但不計為差異。</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="70"/>
        <location filename="../cli/CompareCommand.cpp" line="87"/>
        <location filename="../cli/CompareCommand.cpp" line="146"/>
        <source>error: %1</source>
        <translation>錯誤：%1</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="64"/>
        <source>interrupted</source>
        <translation>已中斷</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="74"/>
        <source>drive %1</source>
        <translation>驅動器 %1</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="106"/>
        <source>error: %1 holds several drives (%2): name one as %1:ID</source>
        <translation>錯誤：%1 含有多台驅動器 (%2)：請以 %1:ID 指定其中一台</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="110"/>
        <source>error: %1 holds no drive with machine number %2; it holds %3</source>
        <translation>錯誤：%1 中沒有機號 %2 的驅動器；檔案中有 %3</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="126"/>
        <source>error: compare A B, or compare A --defaults (A, B: a machine number, FILE or FILE:ID)</source>
        <translation>錯誤：compare A B，或 compare A --defaults (A、B：機號、FILE 或 FILE:ID)</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="144"/>
        <source>factory defaults</source>
        <translation>出廠預設值</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="172"/>
        <source>A: %1 (%2)</source>
        <translation>A：%1 (%2)</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="175"/>
        <source>B: %1</source>
        <translation>B：%1</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="180"/>
        <source>parameter</source>
        <translation>參數</translation>
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
        <translation>(未包含)</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="186"/>
        <source> in %1 settings compared</source>
        <translation> (共比較 %1 項設定)</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="188"/>
        <source>no differences (%1 settings compared)</source>
        <translation>無差異 (共比較 %1 項設定)</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="195"/>
        <source>note: %1</source>
        <translation>注意：%1</translation>
    </message>
</context>
<context>
    <name>opentop::CompareDialog</name>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="33"/>
        <source>&amp;Differences only</source>
        <translation>僅顯示差異(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="37"/>
        <source>Co&amp;mpare</source>
        <translation>比較(&amp;M)</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="39"/>
        <source>Compare settings</source>
        <translation>比較設定</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="40"/>
        <source>Side A</source>
        <translation>A 側</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="41"/>
        <source>Side B</source>
        <translation>B 側</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="57"/>
        <location filename="../ui/files/CompareDialog.cpp" line="227"/>
        <source>Setting</source>
        <translation>設定</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="57"/>
        <location filename="../ui/files/CompareDialog.cpp" line="227"/>
        <source>Parameter</source>
        <translation>參數</translation>
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
        <translation>依設定或參數名稱篩選</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="65"/>
        <source>Read the chosen sides and compare them (drives are read fresh)</source>
        <translation>讀取所選的兩側並比較 (驅動器會重新讀取)</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="78"/>
        <source>C&amp;lose</source>
        <translation>關閉(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="111"/>
        <source>%1 refused: %2</source>
        <translation>%1 被拒絕：%2</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="125"/>
        <source>Reading…</source>
        <translation>讀取中…</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="150"/>
        <source>side A</source>
        <translation>A 側</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="150"/>
        <source>side B</source>
        <translation>B 側</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="154"/>
        <source>Factory defaults</source>
        <translation>出廠預設值</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="161"/>
        <source>Choose a backup file and a drive in it for %1.</source>
        <translation>請為 %1 選擇備份檔及其中的驅動器。</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="165"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="175"/>
        <source>Choose an identified drive on the bus for %1.</source>
        <translation>請為 %1 選擇匯流排上已識別的驅動器。</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="183"/>
        <source>%1: cannot read %2</source>
        <translation>%1：無法讀取 %2</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="208"/>
        <source>Unknown family %1</source>
        <translation>未知系列 %1</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="227"/>
        <source>A: %1</source>
        <translation>A：%1</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="228"/>
        <source>B: %1</source>
        <translation>B：%1</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="229"/>
        <source>factory defaults (%1)</source>
        <translation>出廠預設值 (%1)</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="239"/>
        <source>(no documented default)</source>
        <translation>(手冊未列預設值)</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="240"/>
        <location filename="../ui/files/CompareDialog.cpp" line="242"/>
        <source>(not held)</source>
        <translation>(未包含)</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/CompareDialog.cpp" line="258"/>
        <source>%n difference(s)</source>
        <translation>
            <numerusform>%n 項差異</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="259"/>
        <source> in %1 settings compared</source>
        <translation> (共比較 %1 項設定)</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="262"/>
        <source>Note: %1</source>
        <translation>注意：%1</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="269"/>
        <source>No factory default documented (never counted as a difference): %1</source>
        <translation>手冊未列出廠預設值 (不計為差異)：%1</translation>
    </message>
</context>
<context>
    <name>opentop::CompareSide</name>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="23"/>
        <source>Browse…</source>
        <translation>瀏覽…</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="27"/>
        <source>Drive on the bus</source>
        <translation>匯流排上的驅動器</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="28"/>
        <source>Drive in a backup file</source>
        <translation>備份檔中的驅動器</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="30"/>
        <source>Factory defaults</source>
        <translation>出廠預設值</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="34"/>
        <source>Drive %1 (%2)</source>
        <translation>驅動器 %1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="41"/>
        <source>Backup file</source>
        <translation>備份檔</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="46"/>
        <source>Source:</source>
        <translation>來源：</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="47"/>
        <source>Drive:</source>
        <translation>驅動器：</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="48"/>
        <source>File:</source>
        <translation>檔案：</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="49"/>
        <source>Drive in file:</source>
        <translation>檔案中的驅動器：</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="170"/>
        <source>Open backup file</source>
        <translation>開啟備份檔</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="171"/>
        <source>OpenTOP backups (*.json);;All files (*)</source>
        <translation>OpenTOP 備份檔 (*.json);;所有檔案 (*)</translation>
    </message>
</context>
<context>
    <name>opentop::Comparer</name>
    <message>
        <location filename="../model/files/Comparer.cpp" line="15"/>
        <source>nothing to compare: %1 is a %2 drive, %3 a %4 drive</source>
        <translation>無法比較：%1 是 %2 驅動器，%3 是 %4 驅動器</translation>
    </message>
    <message>
        <location filename="../model/files/Comparer.cpp" line="20"/>
        <source>the variants differ: %1 and %2</source>
        <translation>機型不同：%1 與 %2</translation>
    </message>
    <message>
        <location filename="../model/files/Comparer.cpp" line="55"/>
        <source>factory defaults</source>
        <translation>出廠預設值</translation>
    </message>
</context>
<context>
    <name>opentop::ConnectionDialog</name>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="63"/>
        <source>Connect to a bus</source>
        <translation>連線至匯流排</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="68"/>
        <source>&amp;Serial port</source>
        <translation>序列埠(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="68"/>
        <source>Modbus &amp;TCP gateway</source>
        <translation>Modbus TCP 閘道器(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="69"/>
        <source>Si&amp;mulated bus</source>
        <translation>模擬匯流排(&amp;M)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="85"/>
        <source>&amp;Advanced</source>
        <translation>進階(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="108"/>
        <source>&amp;Connect</source>
        <translation>連線(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="129"/>
        <source>&amp;Refresh</source>
        <translation>重新整理(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="130"/>
        <source>List the serial ports again (after plugging in an adapter)</source>
        <translation>重新列出序列埠 (插入轉接器後使用)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="135"/>
        <source>&amp;Port:</source>
        <translation>連接埠(&amp;P)：</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="144"/>
        <source>Custom</source>
        <translation>自訂</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="146"/>
        <source>%1 (%2 %3%4%5)</source>
        <translation>%1 (%2 %3%4%5)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="153"/>
        <source>Fills in the factory line settings of a drive family</source>
        <translation>填入驅動器系列的出廠通訊設定</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="156"/>
        <source>&amp;Family defaults:</source>
        <translation>系列預設值(&amp;F)：</translation>
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
        <translation>鮑率(&amp;B)：</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="163"/>
        <source>None (N)</source>
        <translation>無 (N)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="164"/>
        <source>Even (E)</source>
        <translation>偶同位 (E)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="165"/>
        <source>Odd (O)</source>
        <translation>奇同位 (O)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="166"/>
        <source>P&amp;arity:</source>
        <translation>同位元(&amp;A)：</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="168"/>
        <source>1 bit</source>
        <translation>1 位元</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="169"/>
        <source>2 bits</source>
        <translation>2 位元</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="170"/>
        <source>S&amp;top bits:</source>
        <translation>停止位元(&amp;T)：</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="186"/>
        <source>e.g. 192.168.1.10</source>
        <translation>例如 192.168.1.10</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="187"/>
        <source>&amp;Host:</source>
        <translation>主機(&amp;H)：</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="190"/>
        <source>Modbus TCP uses port 502</source>
        <translation>Modbus TCP 使用連接埠 502</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="191"/>
        <source>TCP p&amp;ort:</source>
        <translation>TCP 連接埠(&amp;O)：</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="203"/>
        <source>Device types and machine numbers: TYPE@NUMBER, comma separated. Types: %1</source>
        <translation>裝置類型與機號：TYPE@NUMBER，以逗號分隔。類型：%1</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="206"/>
        <source>&amp;Devices:</source>
        <translation>裝置(&amp;D)：</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="220"/>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="221"/>
        <source>How long to wait for each reply</source>
        <translation>每次等待回應的時間</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="222"/>
        <source>Response &amp;timeout:</source>
        <translation>回應逾時(&amp;T)：</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="225"/>
        <source>Extra attempts after a request got no valid reply</source>
        <translation>請求未收到有效回應時的額外重試次數</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="226"/>
        <source>R&amp;etries:</source>
        <translation>重試次數(&amp;E)：</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="333"/>
        <source>The device list is not valid.</source>
        <translation>裝置清單無效。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="26"/>
        <source>The port is in use by another program (named above where the system tells it): a terminal program, ModemManager, another OpenTOP window or an opentop-cli command. Close it, or disconnect the other window, and connect again. Nothing was sent on the port.</source>
        <translation>連接埠正被其他程式使用 (若系統有提供，程式名稱顯示於上方)：終端機程式、ModemManager、另一個 OpenTOP 視窗或 opentop-cli 指令。請關閉該程式，或讓另一個視窗中斷連線，然後再次連線。未在連接埠上送出任何資料。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="33"/>
        <source>Your user may not open serial ports: add it to the dialout group with the command above, then log out and in again.</source>
        <translation>您的使用者帳號無權開啟序列埠：請以上方指令將其加入 dialout 群組，然後登出再重新登入。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="36"/>
        <source>Your user may not open serial ports. Add it to the dialout group:
    sudo usermod -aG dialout $USER
then log out and in again (the group applies to new sessions only).</source>
        <translation>您的使用者帳號無權開啟序列埠。請將其加入 dialout 群組：
    sudo usermod -aG dialout $USER
然後登出再重新登入 (群組設定僅對新的登入工作階段生效)。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="41"/>
        <source>The port %1 does not exist: the USB adapter may be unplugged or have come back under another name, or the path is mistyped. Plug it in, press Refresh and pick it from the list; for a pseudo-terminal check that the program serving it (opentop-sim, socat) still runs.</source>
        <translation>連接埠 %1 不存在：USB 轉接器可能已拔除或以其他名稱重新出現，或路徑輸入錯誤。請插上轉接器，按「重新整理」並從清單中選取；若為虛擬終端機，請確認提供它的程式 (opentop-sim、socat) 仍在執行。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="48"/>
        <source>The connection opened but no drive answered. Check that the baud rate, parity and stop bits (%1) match the drives&apos; settings (DBU: 19200 8N1, DC controller: 9600 8E1) — a framing mismatch looks like silence — that the machine number is right, and that the A and B (D+ and D−) wires are not swapped.</source>
        <translation>連線已開啟，但沒有驅動器回應。請確認鮑率、同位元與停止位元 (%1) 與驅動器設定相符 (DBU：19200 8N1，DC 控制器：9600 8E1)——格式不符時看起來就像無回應——並確認機號正確，且 A、B (D+、D−) 線未接反。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="56"/>
        <source>The gateway %1:%2 did not accept the connection: check the address and port (Modbus TCP uses 502), that the gateway is powered and on this network, and that no firewall blocks it.</source>
        <translation>閘道器 %1:%2 未接受連線：請確認位址與連接埠 (Modbus TCP 使用 502)、閘道器已通電且位於此網路中，並確認沒有防火牆阻擋。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="63"/>
        <source>Check that the adapter is plugged in, that %1 is the right port, and that no other program uses it.</source>
        <translation>請確認轉接器已插上、%1 是正確的連接埠，且沒有其他程式正在使用。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="66"/>
        <source>Check the connection settings and try again.</source>
        <translation>請檢查連線設定後再試一次。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="68"/>
        <source>Could not use %1: %2</source>
        <translation>無法使用 %1：%2</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="69"/>
        <source>What to check:</source>
        <translation>檢查項目：</translation>
    </message>
</context>
<context>
    <name>opentop::ConnectionOptions</name>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="30"/>
        <source>--rs485 %1: use off (the adapter switches direction itself), auto, kernel or rts</source>
        <translation>--rs485 %1：請使用 off (由轉接器自行切換方向)、auto、kernel 或 rts</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="36"/>
        <source>--rts-polarity %1: use high or low (the RTS level while sending)</source>
        <translation>--rts-polarity %1：請使用 high 或 low (傳送時的 RTS 準位)</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="44"/>
        <source>--rts-delay %1: use 0–%2 µs (0: the driver&apos;s or libmodbus&apos; own delay)</source>
        <translation>--rts-delay %1：請使用 0–%2 µs (0：使用驅動程式或 libmodbus 本身的延遲)</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="51"/>
        <source>--low-latency %1: use on or off</source>
        <translation>--low-latency %1：請使用 on 或 off</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="61"/>
        <source>--%1 applies to a serial port (--port), not to a Modbus TCP gateway (--tcp)</source>
        <translation>--%1 僅適用於序列埠 (--port)，不適用於 Modbus TCP 閘道器 (--tcp)</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="65"/>
        <source>--%1 applies to a serial port (--port), not to a simulated bus</source>
        <translation>--%1 僅適用於序列埠 (--port)，不適用於模擬匯流排</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="66"/>
        <source>--%1 applies to a serial port only: give it with --port PATH</source>
        <translation>--%1 僅適用於序列埠：請搭配 --port PATH 指定</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="74"/>
        <source>Serial device (e.g. /dev/ttyUSB0 or a pty path).</source>
        <translation>序列裝置 (例如 /dev/ttyUSB0 或 pty 路徑)。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="75"/>
        <source>PATH</source>
        <translation>PATH</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="76"/>
        <source>Modbus TCP gateway, HOST:PORT (port defaults to 502).</source>
        <translation>Modbus TCP 閘道器，HOST:PORT (連接埠預設為 502)。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="77"/>
        <source>HOST:PORT</source>
        <translation>HOST:PORT</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="78"/>
        <source>In-process simulated bus, e.g. dbu200@1,dbu400@150,dcpid@7.</source>
        <translation>程式內建的模擬匯流排，例如 dbu200@1,dbu400@150,dcpid@7。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="79"/>
        <source>SPEC</source>
        <translation>SPEC</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="81"/>
        <source>Device family whose serial defaults apply (dbu: 19200 8N1, dcpid: 9600 8E1).</source>
        <translation>套用其序列埠預設值的裝置系列 (dbu：19200 8N1，dcpid：9600 8E1)。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="82"/>
        <source>FAMILY</source>
        <translation>FAMILY</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="83"/>
        <source>Baud rate, 1200–115200.</source>
        <translation>鮑率，1200–115200。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="83"/>
        <source>BAUD</source>
        <translation>BAUD</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="84"/>
        <source>Parity: N, E or O.</source>
        <translation>同位元：N、E 或 O。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="84"/>
        <source>N|E|O</source>
        <translation>N|E|O</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="85"/>
        <source>Stop bits: 1 or 2.</source>
        <translation>停止位元：1 或 2。</translation>
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
        <translation>使用與連接埠不同通訊格式的驅動器，在交易之間切換：ID=[BAUD:]FORMAT,...，例如 7=9600:8E1 或 7=8N2（BAUD 預設為連接埠的鮑率）。DBU 只能用 8N1；DC 控制器用 8E1、8O1 或 8N2。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="90"/>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="92"/>
        <source>Response timeout per attempt in ms, 10–10000 (default 200).</source>
        <translation>每次嘗試的回應逾時，單位 ms，10–10000 (預設 200)。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="92"/>
        <source>MS</source>
        <translation>MS</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="94"/>
        <source>Extra attempts after no reply or a garbled one, 0–10 (default 3; 2 more while the line is noisy).</source>
        <translation>無回應或回應錯亂時的額外重試次數，0–10 (預設 3；線路雜訊多時再加 2 次)。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="98"/>
        <source>Who switches the RS-485 direction (serial port only): off (default: the adapter itself, as USB–RS-485 adapters do), kernel (the driver&apos;s RS-485 mode), rts (RTS from the program) or auto (kernel where the driver has it, else rts).</source>
        <translation>由誰切換 RS-485 收發方向 (僅限序列埠)：off (預設：由轉接器自行切換，USB–RS-485 轉接器即是如此)、kernel (驅動程式的 RS-485 模式)、rts (由程式控制 RTS) 或 auto (驅動程式支援時用 kernel，否則用 rts)。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="101"/>
        <source>MODE</source>
        <translation>MODE</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="103"/>
        <source>RTS level while sending with --rs485 kernel, rts or auto: high (default) or low.</source>
        <translation>使用 --rs485 kernel、rts 或 auto 時，傳送期間的 RTS 準位：high (預設) 或 low。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="104"/>
        <source>high|low</source>
        <translation>high|low</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="106"/>
        <source>RTS delay before and after sending in µs, 0–100000 (default 0: the driver&apos;s, or libmodbus&apos; one character time; the kernel rounds up to whole ms).</source>
        <translation>傳送前後的 RTS 延遲，單位 µs，0–100000 (預設 0：使用驅動程式的延遲，或 libmodbus 的 1 個字元時間；核心會進位到整數 ms)。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="108"/>
        <source>US</source>
        <translation>US</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="110"/>
        <source>Ask the serial driver to pass received bytes on at once (USB adapters otherwise hold them up to 16 ms): on (default) or off.</source>
        <translation>要求序列埠驅動程式立即轉交收到的位元組 (否則 USB 轉接器最多會保留 16 ms)：on (預設) 或 off。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="112"/>
        <source>on|off</source>
        <translation>on|off</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="157"/>
        <source>give only one of --port, --tcp and --sim</source>
        <translation>--port、--tcp 與 --sim 只能指定其中一個</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="159"/>
        <source>no bus given: use --port PATH, --tcp HOST:PORT or --sim SPEC</source>
        <translation>未指定匯流排：請使用 --port PATH、--tcp HOST:PORT 或 --sim SPEC</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="168"/>
        <source>--family %1: unknown family; use one of %2</source>
        <translation>--family %1：未知系列；請使用下列其中之一：%2</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="187"/>
        <source>--tcp: &quot;%1&quot; is not HOST:PORT</source>
        <translation>--tcp：&quot;%1&quot; 不是 HOST:PORT 格式</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="196"/>
        <source>--sim: %1</source>
        <translation>--sim：%1</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="209"/>
        <source>--baud %1: use a baud rate 1200–115200 (e.g. 9600, 19200, 38400)</source>
        <translation>--baud %1：請使用 1200–115200 的鮑率 (例如 9600、19200、38400)</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="213"/>
        <source>--stop-bits %1: use 1 or 2</source>
        <translation>--stop-bits %1：請使用 1 或 2</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="215"/>
        <source>--timeout %1: use a response timeout of 10–10000 ms</source>
        <translation>--timeout %1：回應逾時請使用 10–10000 ms</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="218"/>
        <source>--retries %1: use 0–10 extra attempts</source>
        <translation>--retries %1：額外重試次數請使用 0–10</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="223"/>
        <source>--parity %1: use N (none), E (even) or O (odd)</source>
        <translation>--parity %1：請使用 N (無)、E (偶同位) 或 O (奇同位)</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="229"/>
        <source>--drive-format applies to a serial port (--port) or a simulated bus, not to a Modbus TCP gateway (--tcp): the gateway sets its line itself</source>
        <translation>--drive-format 適用於序列埠（--port）或模擬匯流排，不適用於 Modbus TCP 閘道器（--tcp）：閘道器自行設定它的線路</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="236"/>
        <source>--drive-format: %1</source>
        <translation>--drive-format：%1</translation>
    </message>
</context>
<context>
    <name>opentop::ConnectionStatus</name>
    <message>
        <location filename="../ui/main/ConnectionStatus.cpp" line="21"/>
        <source>SIMULATED BUS — no hardware</source>
        <translation>模擬匯流排 — 無實體硬體</translation>
    </message>
    <message>
        <location filename="../ui/main/ConnectionStatus.cpp" line="22"/>
        <source>These drives exist only in this program; nothing moves.</source>
        <translation>這些驅動器只存在於本程式中；沒有任何馬達會轉動。</translation>
    </message>
    <message>
        <location filename="../ui/main/ConnectionStatus.cpp" line="27"/>
        <location filename="../ui/main/ConnectionStatus.cpp" line="76"/>
        <source>Not connected</source>
        <translation>未連線</translation>
    </message>
    <message>
        <location filename="../ui/main/ConnectionStatus.cpp" line="54"/>
        <source>Connected: %1</source>
        <translation>已連線：%1</translation>
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
        <translation>通訊群組：%1 (匯流排 › 通訊群組)</translation>
    </message>
</context>
<context>
    <name>opentop::DbuSimDevice</name>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="340"/>
        <source>alarm 0x%1</source>
        <translation>警報 0x%1</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="341"/>
        <source>running</source>
        <translation>運轉中</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="342"/>
        <source>stopped</source>
        <translation>已停止</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="343"/>
        <source>%1 %2 r/min (target %3) SPno%4 load %5 % %6, %7 priority, %8%9</source>
        <translation>%1 %2 r/min (目標 %3) SPno%4 負載 %5 % %6，%7優先，%8%9</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="347"/>
        <source>communication</source>
        <translation>通訊</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="347"/>
        <source>I/O</source>
        <translation>I/O</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="348"/>
        <source>offline</source>
        <translation>離線</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="348"/>
        <source>online</source>
        <translation>連線中</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="349"/>
        <source>, ignoring stop</source>
        <translation>，忽略停止指令</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="357"/>
        <source>usage: %1 ID CODE</source>
        <translation>用法：%1 ID CODE</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="360"/>
        <source>warning cleared</source>
        <translation>警告已解除</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="365"/>
        <source>unknown %1 code %2; allowed: %3</source>
        <translation>未知的 %1 代碼 %2；允許：%3</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="373"/>
        <source>%1 0x%2 raised</source>
        <translation>已觸發 %1 0x%2</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="384"/>
        <source>usage: ignore-stop ID on|off</source>
        <translation>用法：ignore-stop ID on|off</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="386"/>
        <source>stop commands are acknowledged and ignored</source>
        <translation>停止指令會回應確認，但被忽略</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="387"/>
        <source>stop commands are obeyed</source>
        <translation>停止指令會被執行</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="403"/>
        <source>usage: %1 ID VALUE with VALUE %2..%3</source>
        <translation>用法：%1 ID VALUE，VALUE 為 %2..%3</translation>
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
        <translation>DC 控制器</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="46"/>
        <source>Re&amp;load stored configuration</source>
        <translation>重新載入已保存的組態(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="68"/>
        <source>Store &amp;configuration</source>
        <translation>保存組態(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="69"/>
        <source>Store P&amp;ID</source>
        <translation>保存 PID(&amp;I)</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="70"/>
        <source>Store pre&amp;set</source>
        <translation>保存預設速度(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="73"/>
        <source>Writes %1 = 1: %2</source>
        <translation>寫入 %1 = 1：%2</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="78"/>
        <source>Writes store.config = 0: the controller reloads the stored configuration; unstored configuration changes are discarded</source>
        <translation>寫入 store.config = 0：控制器重新載入已保存的組態；未保存的組態變更將被捨棄</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="85"/>
        <source>Speed mode and motor currents</source>
        <translation>速度模式與馬達電流</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="86"/>
        <source>Speed &amp;mode:</source>
        <translation>速度模式(&amp;M)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="87"/>
        <source>Rated current:</source>
        <translation>額定電流：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="88"/>
        <source>Maximum start/load current:</source>
        <translation>最大啟動/負載電流：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="89"/>
        <source>Brake current:</source>
        <translation>煞車電流：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="91"/>
        <source>Limit switches</source>
        <translation>極限開關</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="92"/>
        <source>Limits:</source>
        <translation>極限開關：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="93"/>
        <source>SQ1 active level (forward):</source>
        <translation>SQ1 有效準位 (正轉)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="94"/>
        <source>SQ2 active level (reverse):</source>
        <translation>SQ2 有效準位 (反轉)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="96"/>
        <source>Protective stops (0 = off)</source>
        <translation>保護停止 (0 = 關閉)</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="97"/>
        <source>S&amp;tall stop time:</source>
        <translation>堵轉停止時間(&amp;T)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="98"/>
        <source>Communication loss stop time:</source>
        <translation>通訊中斷停止時間：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="106"/>
        <source>Serial port (used from the next power-up)</source>
        <translation>序列埠 (自下次上電起生效)</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="111"/>
        <source>Baud rate and parity are written as one 15-register block from 0x0080 that also stores the configuration; the controller uses them from the next power-up on: switch it off and on, then reconnect with them. The lock is lost at power-off until stored (Store configuration).</source>
        <translation>鮑率與同位元會以自 0x0080 起的一個 15 暫存器區塊寫入，此寫入同時會保存組態；控制器自下次上電起使用新設定：請將其斷電再上電，然後以新設定重新連線。序列組態鎖定在保存 (保存組態) 前斷電即遺失。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="133"/>
        <source>Takes effect now and is kept over power-off: each change is written as one 5-register block from 0x0050 that also stores the port states.</source>
        <translation>立即生效，斷電後仍保留：每次變更都會以自 0x0050 起的一個 5 暫存器區塊寫入，此寫入同時會保存各埠狀態。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="175"/>
        <source>The communication loss stop time is 0 s (%1): the manual does not say what 0 does, and OpenTOP assumes the stop is then off: if the connection is lost while the motor runs, the controller keeps it running at the last speed command. Set a time so that it brakes when the bus goes quiet.</source>
        <translation>通訊中斷停止時間為 0 s (%1)：手冊並未說明 0 的作用，OpenTOP 假設此時停止功能為關閉：若馬達運轉中連線中斷，控制器會依最後的速度指令持續運轉。請設定時間，使匯流排無通訊時能煞車停止。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="107"/>
        <source>Baud rate:</source>
        <translation>鮑率：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="108"/>
        <source>Parity and stop bits:</source>
        <translation>同位元與停止位元：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="109"/>
        <source>Configuration over serial:</source>
        <translation>序列埠組態設定：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="115"/>
        <source>Speed loop PID</source>
        <translation>速度迴路 PID</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="116"/>
        <source>&amp;P coefficient:</source>
        <translation>P 係數(&amp;P)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="117"/>
        <source>I coefficient:</source>
        <translation>I 係數：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="118"/>
        <source>&amp;D coefficient:</source>
        <translation>D 係數(&amp;D)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="119"/>
        <source>D period:</source>
        <translation>D 週期：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="121"/>
        <source>Preset speed (potentiometer/analog control)</source>
        <translation>預設速度 (可變電阻/類比控制)</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="122"/>
        <source>Preset speed mo&amp;de:</source>
        <translation>預設速度模式(&amp;D)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="123"/>
        <source>Trigger:</source>
        <translation>觸發：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="124"/>
        <source>&amp;Forward speed:</source>
        <translation>正轉速度(&amp;F)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="125"/>
        <source>Reverse speed:</source>
        <translation>反轉速度：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="127"/>
        <source>AI1/AI2 as digital ports</source>
        <translation>AI1/AI2 作為數位埠</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="128"/>
        <source>AI1 direction:</source>
        <translation>AI1 方向：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="129"/>
        <source>AI2 direction:</source>
        <translation>AI2 方向：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="130"/>
        <source>AI1 level:</source>
        <translation>AI1 準位：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="131"/>
        <source>AI2 level:</source>
        <translation>AI2 準位：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="191"/>
        <source>Takes effect now, lost at power-off until stored (%1).</source>
        <translation>立即生效，保存 (%1) 前斷電即遺失。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="252"/>
        <source>Set it anyway?</source>
        <translation>仍要設定嗎？</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="268"/>
        <source>Forward and reverse speed in this mode (%1): %2</source>
        <translation>此模式 (%1) 下的正轉與反轉速度：%2</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="270"/>
        <source>The unit and range of the speeds follow the preset speed mode (not read yet).</source>
        <translation>速度的單位與範圍取決於預設速度模式 (尚未讀取)。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="294"/>
        <source>&lt;b&gt;Written but not stored:&lt;/b&gt; %1. These values act now and are lost when the controller is switched off.</source>
        <translation>&lt;b&gt;已寫入但未保存：&lt;/b&gt;%1。這些值目前有效，控制器關閉電源後即遺失。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="316"/>
        <source>%1: the controller writes the values now in effect to its memory and uses them from the next power-up on.

Stored: %2.</source>
        <translation>%1：控制器會將目前生效的值寫入記憶體，並自下次上電起使用。

保存項目：%2。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="327"/>
        <source>Not written yet, so not stored: %1.</source>
        <translation>尚未寫入，因此不會保存：%1。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="330"/>
        <source>%1: done, kept over power-off.</source>
        <translation>%1：完成，斷電後仍保留。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="338"/>
        <source>The controller replaces its configuration (%1) with the one stored in its memory.

Configuration changes written but not stored are discarded.</source>
        <translation>控制器會以記憶體中已保存的組態取代目前的組態 (%1)。

已寫入但未保存的組態變更將被捨棄。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="344"/>
        <source>Stored configuration reloaded.</source>
        <translation>已重新載入保存的組態。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="352"/>
        <source>Writing %1 = %2…</source>
        <translation>正在寫入 %1 = %2…</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="362"/>
        <source>%1 = %2 failed: %3</source>
        <translation>%1 = %2 失敗：%3</translation>
    </message>
</context>
<context>
    <name>opentop::DcMotor</name>
    <message>
        <location filename="../sim/DcMotor.cpp" line="64"/>
        <source>unknown motor setting &apos;%1&apos;; settings: %2</source>
        <translation>未知的馬達設定 &apos;%1&apos;；可用設定：%2</translation>
    </message>
    <message>
        <location filename="../sim/DcMotor.cpp" line="71"/>
        <source>motor setting %1 must be a number %2..%3, got &apos;%4&apos;</source>
        <translation>馬達設定 %1 必須是 %2..%3 的數字，收到 &apos;%4&apos;</translation>
    </message>
</context>
<context>
    <name>opentop::DcPidSimDevice</name>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="366"/>
        <source>%1 %2%3, output %4 %, command %5, line %6 %7</source>
        <translation>%1 %2%3，輸出 %4 %，指令 %5，線路 %6 %7</translation>
    </message>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="368"/>
        <source> (stall stop)</source>
        <translation> (堵轉停止)</translation>
    </message>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="384"/>
        <source>usage: %1 ID VALUE with VALUE %2..%3 %4</source>
        <translation>用法：%1 ID VALUE，VALUE 為 %2..%3 %4</translation>
    </message>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="388"/>
        <source>(bit0 SQ1, bit1 SQ2, bit2 DE)</source>
        <translation>(bit0 SQ1, bit1 SQ2, bit2 DE)</translation>
    </message>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="388"/>
        <source>(% current)</source>
        <translation>(電流 %)</translation>
    </message>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="390"/>
        <source>%1 = %2</source>
        <translation>%1 = %2</translation>
    </message>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="407"/>
        <source>motor %1, speed %2 1/s, current %3 A</source>
        <translation>馬達 %1，速度 %2 1/s，電流 %3 A</translation>
    </message>
</context>
<context>
    <name>opentop::DcRunCommands</name>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="26"/>
        <source>Set s&amp;peed</source>
        <translation>設定速度(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="31"/>
        <source>set point, e.g. 50 or -20</source>
        <translation>設定值，例如 50 或 -20</translation>
    </message>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="39"/>
        <source>Speed command:</source>
        <translation>速度指令：</translation>
    </message>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="54"/>
        <source>&amp;Brake (speed 0)</source>
        <translation>煞車 (速度 0)(&amp;B)</translation>
    </message>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="56"/>
        <source>&amp;Natural stop</source>
        <translation>自然停止(&amp;N)</translation>
    </message>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="90"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="91"/>
        <source>(reading %1…)</source>
        <translation>(正在讀取 %1…)</translation>
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
        <translation>%1 = %2 會使 %3 失去有效值，因為它們的允許值取決於此參數。請為它們選擇新值，並與此參數一起寫入。</translation>
    </message>
    <message>
        <location filename="../model/session/DependentValues.cpp" line="57"/>
        <source>%1 cannot be checked: the values of %2 depend on it and could not be read</source>
        <translation>無法檢查 %1：%2 的值取決於此參數，但無法讀取</translation>
    </message>
</context>
<context>
    <name>opentop::DeviceIdentifier</name>
    <message>
        <location filename="../model/session/DeviceIdentifier.cpp" line="31"/>
        <source>answers, but none of the device profiles matches</source>
        <translation>有回應，但沒有符合的定義檔</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceIdentifier.cpp" line="96"/>
        <source>device name &quot;%1&quot; is not a %2</source>
        <translation>裝置名稱 &quot;%1&quot; 不是 %2</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceIdentifier.cpp" line="116"/>
        <source>the variant cannot be read from the device; choose it</source>
        <translation>無法從裝置讀取機型；請自行選擇</translation>
    </message>
</context>
<context>
    <name>opentop::DeviceInfo</name>
    <message>
        <location filename="../model/session/DeviceInfo.cpp" line="59"/>
        <source>not checked</source>
        <translation>未檢查</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceInfo.cpp" line="61"/>
        <source>online</source>
        <translation>連線中</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceInfo.cpp" line="63"/>
        <source>no answer</source>
        <translation>無回應</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceInfo.cpp" line="65"/>
        <source>garbled replies (duplicate machine number?)</source>
        <translation>回應錯亂 (機號重複？)</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceInfo.cpp" line="68"/>
        <source>unknown device</source>
        <translation>未知裝置</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceInfo.cpp" line="70"/>
        <source>answered, identification failed</source>
        <translation>有回應，識別失敗</translation>
    </message>
</context>
<context>
    <name>opentop::DeviceMonitor</name>
    <message>
        <location filename="../model/monitor/DeviceMonitor.cpp" line="66"/>
        <source>Stopped</source>
        <translation>已停止</translation>
    </message>
    <message>
        <location filename="../model/monitor/DeviceMonitor.cpp" line="68"/>
        <source>Running</source>
        <translation>運轉中</translation>
    </message>
    <message>
        <location filename="../model/monitor/DeviceMonitor.cpp" line="69"/>
        <source>Running CCW</source>
        <translation>CCW 運轉中</translation>
    </message>
    <message>
        <location filename="../model/monitor/DeviceMonitor.cpp" line="69"/>
        <source>Running CW</source>
        <translation>CW 運轉中</translation>
    </message>
    <message>
        <location filename="../model/monitor/DeviceMonitor.cpp" line="212"/>
        <source>machine number %1: %2</source>
        <translation>機號 %1：%2</translation>
    </message>
</context>
<context>
    <name>opentop::DeviceParameters</name>
    <message>
        <location filename="../model/session/DeviceParameters.cpp" line="92"/>
        <source>%1 has no parameter &quot;%2&quot;</source>
        <translation>%1 沒有參數 &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceParameters.cpp" line="94"/>
        <source>%1 is read-only</source>
        <translation>%1 為唯讀</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceParameters.cpp" line="96"/>
        <source>%1 is a command, not a setting; commands are sent one by one on request</source>
        <translation>%1 是指令而非設定；指令只會依要求逐一送出</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceParameters.cpp" line="252"/>
        <location filename="../model/session/DeviceParameters.cpp" line="263"/>
        <location filename="../model/session/DeviceParameters.cpp" line="275"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/session/DeviceParameters.cpp" line="286"/>
        <source>%n write(s) failed: %1</source>
        <translation>
            <numerusform>%n 筆寫入失敗：%1</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/session/DeviceParameters.cpp" line="289"/>
        <source>Written, but not verified on every drive it reached: %1</source>
        <translation>已寫入，但未能在所有收到的驅動器上確認：%1</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/session/DeviceParameters.cpp" line="292"/>
        <source>%n value(s) written and verified</source>
        <translation>
            <numerusform>已寫入並驗證 %n 個值</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::DeviceSession</name>
    <message>
        <location filename="../model/session/DeviceSession.cpp" line="83"/>
        <source>%1 has no parameter &quot;%2&quot;</source>
        <translation>%1 沒有參數 &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/session/BlockReader.cpp" line="50"/>
        <location filename="../model/session/DeviceSession.cpp" line="92"/>
        <source>%1 cannot be read (it is a write-only command)</source>
        <translation>%1 無法讀取 (為僅可寫入的指令)</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceSession.cpp" line="137"/>
        <source>%1 is read-only</source>
        <translation>%1 為唯讀</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceSession.cpp" line="143"/>
        <source>%1 is a %2 command; it is only sent when explicitly requested</source>
        <translation>%1 是 %2 指令；僅在明確要求時才會送出</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceSession.cpp" line="173"/>
        <source>%1 cannot be checked: %2</source>
        <translation>無法檢查 %1：%2</translation>
    </message>
    <message>
        <location filename="../model/session/BlockWriter.cpp" line="28"/>
        <source>not written: %1 is written together with 0x%2–0x%3, and reading those first failed: %4</source>
        <translation>未寫入：%1 需與 0x%2–0x%3 一起寫入，而事先讀取這些暫存器失敗：%4</translation>
    </message>
    <message>
        <location filename="../model/session/BlockWriter.cpp" line="33"/>
        <source>short reply</source>
        <translation>回應過短</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceSession.cpp" line="254"/>
        <source>written, but reading it back failed: %1</source>
        <translation>已寫入，但回讀失敗：%1</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceSession.cpp" line="263"/>
        <source>verification failed: wrote %1, the device holds %2</source>
        <translation>驗證失敗：寫入 %1，裝置中為 %2</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceRefusal.cpp" line="67"/>
        <source>error code %1</source>
        <translation>錯誤碼 %1</translation>
    </message>
</context>
<context>
    <name>opentop::DriveBatchReader</name>
    <message>
        <location filename="../model/files/DriveBatchReader.cpp" line="13"/>
        <source>machine number %1: not read</source>
        <translation>機號 %1：未讀取</translation>
    </message>
    <message>
        <location filename="../model/files/DriveBatchReader.cpp" line="22"/>
        <source>%1: cannot read %2</source>
        <translation>%1：無法讀取 %2</translation>
    </message>
    <message>
        <location filename="../model/files/DriveBatchReader.cpp" line="24"/>
        <source>%1 holds a value its profile does not allow, so the backup could not be restored: %2</source>
        <translation>%1 含有定義檔不允許的值，此備份將無法還原：%2</translation>
    </message>
    <message>
        <location filename="../model/files/DriveBatchReader.cpp" line="89"/>
        <source>machine number %1 is not a drive on the bus</source>
        <translation>機號 %1 不是匯流排上的驅動器</translation>
    </message>
</context>
<context>
    <name>opentop::DriveFormatsField</name>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="28"/>
        <source>none: every drive at the port&apos;s format</source>
        <translation>無：所有驅動器都用連接埠的格式</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="30"/>
        <source>Drives set to another line format than the port&apos;s, e.g. 7=9600:8E1 or 7=8N2 (the baud rate may be left out): requests to them switch the line to their format and back between transactions. A DBU works only at 8N1; a DC controller at 8E1, 8O1 or 8N2. The bus list&apos;s context menu sets them too.</source>
        <translation>設為與連接埠不同通訊格式的驅動器，例如 7=9600:8E1 或 7=8N2（鮑率可省略）：送往它們的要求會在交易之間把線路切換到它們的格式再切換回來。DBU 只能用 8N1；DC 控制器用 8E1、8O1 或 8N2。匯流排清單的右鍵選單也可設定。</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="36"/>
        <source>&amp;Mixed bus…</source>
        <translation>混合匯流排(&amp;M)…</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="37"/>
        <source>How a drive of another format joins this bus</source>
        <translation>不同格式的驅動器如何加入此匯流排</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="39"/>
        <source>Drives of different line formats</source>
        <translation>不同通訊格式的驅動器</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="47"/>
        <source>Drive f&amp;ormats:</source>
        <translation>驅動器格式(&amp;O)：</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="68"/>
        <source>Drive formats: %1</source>
        <translation>驅動器格式：%1</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="74"/>
        <source>Every drive hears only frames sent in its own line format: a DBU works only at 8N1 (19200 bit/s from the factory), a DC controller at 8E1 (9600 bit/s from the factory), 8O1 or 8N2. OpenTOP can talk to drives of different formats on one port: give each drive that is not at the port&apos;s format its own (Drive formats here, or Line format… in the bus list&apos;s context menu); the port is switched between transactions. To put all drives at one format for good, change the drives:</source>
        <translation>每台驅動器只聽得到以它自己的通訊格式送出的訊框：DBU 只能用 8N1（出廠 19200 bit/s），DC 控制器用 8E1（出廠 9600 bit/s）、8O1 或 8N2。OpenTOP 可在同一個連接埠上與不同格式的驅動器通訊：為每台不是連接埠格式的驅動器設定它自己的格式（在這裡的「驅動器格式」，或匯流排清單右鍵選單的「通訊格式…」）；連接埠會在交易之間切換。若要讓所有驅動器永久使用同一種格式，請變更驅動器的設定：</translation>
    </message>
</context>
<context>
    <name>opentop::DriveLineDialog</name>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="29"/>
        <source>Line format of machine number %1</source>
        <translation>機號 %1 的通訊格式</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="29"/>
        <source>Add drive</source>
        <translation>新增驅動器</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="37"/>
        <source>&amp;Machine number:</source>
        <translation>機號(&amp;M)：</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="51"/>
        <source>The port&apos;s (%1)</source>
        <translation>連接埠的格式 (%1)</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="63"/>
        <source>The baud rate and format the drive is set to: requests to it switch the port to it and back between transactions. Type another as 38400 8E1.</source>
        <translation>驅動器設定的鮑率與格式：送往它的要求會在交易之間把連接埠切換過去再切換回來。其他格式可輸入，例如 38400 8E1。</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="66"/>
        <source>&amp;Line format:</source>
        <translation>通訊格式(&amp;L)：</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="74"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="147"/>
        <source>Line &amp;format…</source>
        <translation>通訊格式(&amp;F)…</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="152"/>
        <source>Machine number %1 talks %2, not the port&apos;s %3</source>
        <translation>機號 %1 使用 %2，而非連接埠的 %3</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="155"/>
        <source>Machine number %1 talks the port&apos;s %2</source>
        <translation>機號 %1 使用連接埠的 %2</translation>
    </message>
</context>
<context>
    <name>opentop::DriveName</name>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="19"/>
        <source>A machine&apos;s name has at most %1 characters; &quot;%2&quot; has %3.</source>
        <translation>機器名稱最多 %1 個字元；「%2」有 %3 個。</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="30"/>
        <source>A machine&apos;s name may not hold control characters or line breaks (U+%1).</source>
        <translation>機器名稱不可包含控制字元或換行 (U+%1)。</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="38"/>
        <source>A machine&apos;s name may not hold %1 (a percent sign directly before a digit).</source>
        <translation>機器名稱不可包含 %1（百分比符號後面緊接數字）。</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="47"/>
        <source>machine number %1</source>
        <translation>機號 %1</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="48"/>
        <source>machine number %1 (%2)</source>
        <translation>機號 %1 (%2)</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="53"/>
        <source>Machine number %1</source>
        <translation>機號 %1</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="54"/>
        <source>Machine number %1 (%2)</source>
        <translation>機號 %1 (%2)</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="72"/>
        <source>drive %1 (%2)</source>
        <translation>驅動器 %1 (%2)</translation>
    </message>
</context>
<context>
    <name>opentop::DrivePages</name>
    <message>
        <location filename="../ui/main/DrivePages.cpp" line="102"/>
        <source>Monitor</source>
        <translation>監視</translation>
    </message>
    <message>
        <location filename="../ui/main/DrivePages.cpp" line="115"/>
        <source>Test run</source>
        <translation>試運轉</translation>
    </message>
    <message>
        <location filename="../ui/main/DrivePages.cpp" line="139"/>
        <source>%1 — %2, firmware V%3, switches %4</source>
        <translation>%1 — %2，韌體 V%3，開關 %4</translation>
    </message>
    <message>
        <location filename="../ui/main/DrivePages.cpp" line="123"/>
        <source>Speed loop tuning</source>
        <translation>速度迴路調諧</translation>
    </message>
    <message>
        <location filename="../ui/main/DrivePages.cpp" line="129"/>
        <source>Alarms</source>
        <translation>警報</translation>
    </message>
</context>
<context>
    <name>opentop::DriveStatus</name>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="8"/>
        <source>not polled yet</source>
        <translation>尚未輪詢</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="10"/>
        <source>online</source>
        <translation>連線中</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/bus/DriveStatus.cpp" line="12"/>
        <source>no answer (%n poll(s) in a row)</source>
        <translation>
            <numerusform>無回應 (連續 %n 次輪詢)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../model/bus/DriveStatus.cpp" line="13"/>
        <source>communication error (%n in a row)</source>
        <translation>
            <numerusform>通訊錯誤 (連續 %n 次)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="19"/>
        <location filename="../model/bus/DriveStatus.cpp" line="31"/>
        <source>Status not known yet</source>
        <translation>狀態尚未得知</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="21"/>
        <source>No answer: %1</source>
        <translation>無回應：%1</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="24"/>
        <source>Communication error: %1</source>
        <translation>通訊錯誤：%1</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="34"/>
        <source>Alarm %1 %2</source>
        <translation>警報 %1 %2</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="36"/>
        <source>Alarm %1h (not in the alarm table)</source>
        <translation>警報 %1h (不在警報表中)</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="38"/>
        <source>Alarm active</source>
        <translation>警報發生中</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="42"/>
        <source>Running</source>
        <translation>運轉中</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="43"/>
        <source>Running CCW</source>
        <translation>CCW 運轉中</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="43"/>
        <source>Running CW</source>
        <translation>CW 運轉中</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="45"/>
        <source>Stopped, no alarm</source>
        <translation>已停止，無警報</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="52"/>
        <source>grey</source>
        <translation>灰色</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="54"/>
        <source>green</source>
        <translation>綠色</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="56"/>
        <source>orange</source>
        <translation>橘色</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="58"/>
        <source>sky blue</source>
        <translation>天藍色</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="60"/>
        <source>red</source>
        <translation>紅色</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="62"/>
        <source>purple</source>
        <translation>紫色</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="64"/>
        <source>blue</source>
        <translation>藍色</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="101"/>
        <source>%1; %2</source>
        <translation>%1；%2</translation>
    </message>
</context>
<context>
    <name>opentop::DriveWorkspace</name>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="35"/>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="169"/>
        <source>Write &amp;all pending</source>
        <translation>寫入所有待寫入項目(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="36"/>
        <source>Revert all</source>
        <translation>全部復原</translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="37"/>
        <source>Re-read all</source>
        <translation>全部重新讀取</translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="55"/>
        <source>Write every pending edit of this drive, on all pages, and verify</source>
        <translation>寫入此驅動器所有頁面上的待寫入變更並驗證</translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="88"/>
        <source>Select a drive in the bus list to set it up.</source>
        <translation>請在匯流排清單中選擇要設定的驅動器。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="152"/>
        <source>Every edit is accepted now. Nothing has been written yet: Write all pending sends %n value(s).</source>
        <translation>
            <numerusform>所有編輯值現已接受。尚未寫入任何值：「寫入所有待寫入值」將送出 %n 個值。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="168"/>
        <source>Write &amp;all pending (%1)</source>
        <translation>寫入所有待寫入項目 (%1)(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="190"/>
        <source>Reading the drive…</source>
        <translation>正在讀取驅動器…</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="192"/>
        <source>%n value(s) could not be read</source>
        <translation>
            <numerusform>%n 個值無法讀取</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="147"/>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="210"/>
        <source>Nothing was written: %1</source>
        <translation>未寫入任何資料：%1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="144"/>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="224"/>
        <source>%1: %2 Nothing was written.</source>
        <translation>%1：%2 未寫入任何資料。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="233"/>
        <source>Write %n pending value(s) to machine number %1</source>
        <translation>
            <numerusform>將 %n 個待寫入的值寫入機號 %1</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="205"/>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="235"/>
        <source>Nothing was written.</source>
        <translation>未寫入任何資料。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="238"/>
        <source>Writing %n value(s)…</source>
        <translation>
            <numerusform>正在寫入 %n 個值…</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::EolAuditCommand</name>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="34"/>
        <source>Show the audit trail: who logged in, approved, used or was refused a privilege</source>
        <translation>顯示稽核紀錄：誰登入、核准、使用或被拒絕某項權限</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="40"/>
        <source>Results database: an SQLite file or postgresql://user@host/db.</source>
        <translation>結果資料庫：SQLite 檔案或 postgresql://user@host/db。</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="41"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="42"/>
        <source>audit: at or after T (2026-11-24, 8h, 2d, today).</source>
        <translation>audit：T 當時或之後（2026-11-24、8h、2d、today）。</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="42"/>
        <source>T</source>
        <translation>T</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="43"/>
        <source>audit: only this user.</source>
        <translation>audit：僅此使用者。</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="43"/>
        <location filename="../cli/EolAuditCommand.cpp" line="44"/>
        <source>NAME</source>
        <translation>名稱</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="44"/>
        <source>audit: only this station.</source>
        <translation>audit：僅此工站。</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="53"/>
        <source>usage: opentop-cli eol %1</source>
        <translation>用法：opentop-cli eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="62"/>
        <source>error: --since: %1</source>
        <translation>錯誤：--since：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="74"/>
        <source>error: %1</source>
        <translation>錯誤：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="89"/>
        <source>no audit entry matches</source>
        <translation>沒有符合的稽核紀錄</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="92"/>
        <source>time</source>
        <translation>時間</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="92"/>
        <source>station</source>
        <translation>工站</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="92"/>
        <source>user</source>
        <translation>使用者</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="92"/>
        <source>action</source>
        <translation>動作</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="92"/>
        <source>detail</source>
        <translation>內容</translation>
    </message>
</context>
<context>
    <name>opentop::EolCertificateCommand</name>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="31"/>
        <source>A unit&apos;s certificate: its newest record as a PDF, or as JSON with --json</source>
        <translation>產品的測試證書：以 PDF 輸出其最新記錄，或以 --json 輸出 JSON</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="37"/>
        <source>The results database (see results).</source>
        <translation>結果資料庫 (參閱 results)。</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="37"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="38"/>
        <source>certificate: the record with this id instead of the newest.</source>
        <translation>certificate：使用此 id 的記錄，而非最新記錄。</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="39"/>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="59"/>
        <source>error: name one serial number, or a record with --id ID; usage: eol %1</source>
        <translation>錯誤：請指定一個序號，或以 --id ID 指定記錄；用法：eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="67"/>
        <source>error: the serial number is empty</source>
        <translation>錯誤：序號為空</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="73"/>
        <location filename="../cli/EolCertificateCommand.cpp" line="138"/>
        <location filename="../cli/EolCertificateCommand.cpp" line="154"/>
        <source>error: %1</source>
        <translation>錯誤：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="80"/>
        <source>error: this program cannot draw a PDF (no Qt GUI application); use --json</source>
        <translation>錯誤：此程式無法產生 PDF (沒有 Qt GUI 應用程式)；請使用 --json</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="96"/>
        <source>error: no record %1 in %2 (%3)</source>
        <translation>錯誤：%2 中沒有記錄 %1 (%3)</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="104"/>
        <source>error: record %1 is of serial number %2, not %3</source>
        <translation>錯誤：記錄 %1 屬於序號 %2，而非 %3</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="114"/>
        <location filename="../cli/EolCertificateCommand.cpp" line="147"/>
        <source>error: %1: %2</source>
        <translation>錯誤：%1：%2</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="121"/>
        <source>error: no record of serial number %1 in %2</source>
        <translation>錯誤：%2 中沒有序號 %1 的記錄</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="141"/>
        <source>wrote %1</source>
        <translation>已寫入 %1</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="157"/>
        <source>wrote %1: serial number %2, %3, recorded %4</source>
        <translation>已寫入 %1：序號 %2，%3，記錄於 %4</translation>
    </message>
</context>
<context>
    <name>opentop::EolCommand</name>
    <message>
        <location filename="../cli/EolCommand.cpp" line="36"/>
        <source>End-of-line station: recipes, the results database, unit certificates</source>
        <translation>終檢工站：配方、結果資料庫、產品測試證書</translation>
    </message>
    <message>
        <location filename="../cli/EolCommand.cpp" line="41"/>
        <source>Subcommands:
</source>
        <translation>子指令：
</translation>
    </message>
    <message>
        <location filename="../cli/EolCommand.cpp" line="44"/>
        <source>Results database: --db URL, else OPENTOP_EOL_DB, else the SQLite file
$XDG_DATA_HOME/opentop/results.db (~/.local/share/opentop/results.db).
&quot;opentop-cli help eol&quot; lists every option; each subcommand takes only its own.</source>
        <translation>結果資料庫：--db URL，否則為 OPENTOP_EOL_DB，再否則為 SQLite 檔
$XDG_DATA_HOME/opentop/results.db (~/.local/share/opentop/results.db)。
&quot;opentop-cli help eol&quot; 會列出所有選項；每個子指令只接受自己的選項。</translation>
    </message>
    <message>
        <location filename="../cli/EolCommand.cpp" line="92"/>
        <source>error: name a subcommand: eol %1</source>
        <translation>錯誤：請指定子指令：eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolCommand.cpp" line="94"/>
        <source>error: unknown subcommand &quot;eol %1&quot;; subcommands: %2</source>
        <translation>錯誤：未知子指令 &quot;eol %1&quot;；子指令：%2</translation>
    </message>
    <message>
        <location filename="../cli/EolCommand.cpp" line="98"/>
        <source>See &quot;opentop-cli help eol&quot;.</source>
        <translation>請參閱 &quot;opentop-cli help eol&quot;。</translation>
    </message>
    <message>
        <location filename="../cli/EolCommand.cpp" line="114"/>
        <source>error: eol %1: --%2 is not an option of this subcommand; usage: eol %3</source>
        <translation>錯誤：eol %1：--%2 不是此子指令的選項；用法：eol %3</translation>
    </message>
</context>
<context>
    <name>opentop::EolDriveRun</name>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="56"/>
        <source>identifying</source>
        <translation>識別中</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="84"/>
        <source>no drive answers at machine number %1</source>
        <translation>機號 %1 沒有驅動器回應</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="85"/>
        <source>the drive at machine number %1 is not identified: %2</source>
        <translation>無法識別機號 %1 的驅動器：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="99"/>
        <source>a %1 drive, the recipe needs a %2 drive</source>
        <translation>為 %1 驅動器，配方需要 %2 驅動器</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="103"/>
        <source>firmware %1, the recipe allows %2</source>
        <translation>韌體為 %1，配方允許 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="104"/>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="110"/>
        <source>no profile for the family %1</source>
        <translation>沒有 %1 系列的定義檔</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="193"/>
        <source>cannot read whether the motor runs or an alarm is active: %1</source>
        <translation>無法讀取馬達是否運轉中或是否有警報發生：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="194"/>
        <source>no answer</source>
        <translation>無回應</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="201"/>
        <source>its motor was running before the test</source>
        <translation>測試前馬達已在運轉</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="202"/>
        <source>the motor is already running before the test (left by an interrupted run?); nothing was written: stop it first (STOP ALL, or at the drive)</source>
        <translation>測試前馬達已在運轉 (先前中斷的測試所遺留？)；未寫入任何資料：請先停止馬達 (全部停止，或在驅動器上操作)</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="209"/>
        <source>an alarm is active before the test (left by the last unit?); nothing was written: reset the alarm and test again</source>
        <translation>測試前已有警報發生 (上一台產品遺留？)；未寫入任何資料：請重置警報後重新測試</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="219"/>
        <source>writing the settings</source>
        <translation>正在寫入設定</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="224"/>
        <source>writing the settings: %1</source>
        <translation>寫入設定：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="233"/>
        <source>reading every setting back</source>
        <translation>正在回讀所有設定</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="238"/>
        <source>verifying the settings: %1</source>
        <translation>驗證設定：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="252"/>
        <source>arming the communication-loss stop</source>
        <translation>啟用通訊中斷停止</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="266"/>
        <source>testing</source>
        <translation>測試中</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="270"/>
        <source>step %1 of %2: %3</source>
        <translation>步驟 %1/%2：%3</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="335"/>
        <source>passed</source>
        <translation>合格</translation>
    </message>
</context>
<context>
    <name>opentop::EolMenu</name>
    <message>
        <location filename="../ui/eol/EolMenu.cpp" line="38"/>
        <source>&amp;Recipe editor…</source>
        <translation>配方編輯器(&amp;R)…</translation>
    </message>
    <message>
        <location filename="../ui/eol/EolMenu.cpp" line="51"/>
        <source>the recipe editor</source>
        <translation>配方編輯器</translation>
    </message>
    <message>
        <location filename="../ui/eol/EolMenu.cpp" line="57"/>
        <source>Re&amp;sults…</source>
        <translation>結果(&amp;S)…</translation>
    </message>
</context>
<context>
    <name>opentop::EolRecipeApproveCommand</name>
    <message>
        <location filename="../cli/EolRecipeApproveCommand.cpp" line="35"/>
        <source>Approve a signed recipe for the line (an engineer): stations then run it</source>
        <translation>核准已簽署的配方供產線使用（工程師）：之後工站即可執行</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeApproveCommand.cpp" line="41"/>
        <source>Results database: an SQLite file or postgresql://user@host/db.</source>
        <translation>結果資料庫：SQLite 檔案或 postgresql://user@host/db。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeApproveCommand.cpp" line="41"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeApproveCommand.cpp" line="49"/>
        <source>usage: opentop-cli eol %1</source>
        <translation>用法：opentop-cli eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeApproveCommand.cpp" line="61"/>
        <source>%1: the recipe is not valid, so it cannot be approved:</source>
        <translation>%1：配方無效，因此無法核准：</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeApproveCommand.cpp" line="80"/>
        <source>error: %1; the recipe was not approved</source>
        <translation>錯誤：%1；配方未核准</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeApproveCommand.cpp" line="98"/>
        <source>%1 rev. %2 approved by %3 (approval %4, checksum %5)</source>
        <translation>%1 版次 %2 已由 %3 核准（核准 %4，校驗碼 %5）</translation>
    </message>
</context>
<context>
    <name>opentop::EolRecipeCheckCommand</name>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="27"/>
        <source>Check a recipe against the drive profiles (and per-unit values of a CSV file)</source>
        <translation>依驅動器定義檔檢查配方 (以及 CSV 檔中的單台數值)</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="33"/>
        <source>recipe check: also check every unit&apos;s per-unit values in this CSV file.</source>
        <translation>recipe check：同時檢查此 CSV 檔中每台產品的單台數值。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="34"/>
        <source>CSV</source>
        <translation>CSV</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="55"/>
        <source>error: %1 refused: %2</source>
        <translation>錯誤：%1 被拒絕：%2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="65"/>
        <source>%1, serial %2</source>
        <translation>%1，序號 %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="91"/>
        <source>error: %1</source>
        <translation>錯誤：%1</translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="93"/>
        <source>%1 is not valid: %n problem(s); nothing may be run with it</source>
        <translation>
            <numerusform>%1 無效：%n 個問題；不可使用此配方執行</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="102"/>
        <source>valid: %1 revision %2: %3</source>
        <translation>有效：%1 版次 %2：%3</translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="107"/>
        <source>; %n unit(s) of %1 checked</source>
        <translation>
            <numerusform>；已檢查 %1 的 %n 台產品</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::EolRecipeCreateCommand</name>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="39"/>
        <source>Make a recipe from a golden unit: a backup file or drives on the bus</source>
        <translation>由標準樣品建立配方：來源為備份檔或匯流排上的驅動器</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="45"/>
        <source>recipe create: the golden unit&apos;s backup file.</source>
        <translation>recipe create：標準樣品的備份檔。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="46"/>
        <source>FILE</source>
        <translation>FILE</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="48"/>
        <source>recipe create: the golden unit&apos;s drives on the bus, e.g. 1,2 (with the connection options).</source>
        <translation>recipe create：標準樣品在匯流排上的驅動器，例如 1,2 (搭配連線選項)。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="50"/>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="51"/>
        <source>recipe create: the product&apos;s name.</source>
        <translation>recipe create：產品名稱。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="51"/>
        <source>NAME</source>
        <translation>NAME</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="52"/>
        <source>recipe create: the recipe&apos;s revision.</source>
        <translation>recipe create：配方版次。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="52"/>
        <source>REV</source>
        <translation>REV</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="54"/>
        <source>recipe create: replace an existing recipe file.</source>
        <translation>recipe create：取代既有的配方檔。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="56"/>
        <source>recipe create --drives: run the golden unit through the recipe&apos;s steps once (its motors turn) and take the hold limits from what it measured.</source>
        <translation>recipe create --drives：讓標準樣品依配方步驟運轉一次 (馬達會轉動)，並以量測值訂定保持步驟的限值。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="59"/>
        <source>recipe create --measure: the margin around a measured value, in % of it (default 25; at least 5 % of the parameter&apos;s full scale).</source>
        <translation>recipe create --measure：量測值兩側的裕度，以量測值的 % 表示 (預設 25；至少為該參數滿刻度的 5 %)。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="61"/>
        <source>PERCENT</source>
        <translation>百分比</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="62"/>
        <source>recipe create --measure: run the motors.</source>
        <translation>recipe create --measure：確認讓馬達運轉。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="76"/>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="177"/>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="282"/>
        <source>error: %1; nothing written</source>
        <translation>錯誤：%1；未寫入任何資料</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="118"/>
        <source>nothing written</source>
        <translation>未寫入任何資料</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="91"/>
        <source>%1: %2 settings read</source>
        <translation>%1：已讀取 %2 項設定</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="106"/>
        <source>interrupted while reading the golden unit: nothing written</source>
        <translation>讀取標準樣品時中斷：未寫入任何檔案</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="112"/>
        <source>note: %1</source>
        <translation>注意：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="117"/>
        <source>give its variant with --variant %1=VARIANT</source>
        <translation>請以 --variant %1=機型 指定其機型</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="133"/>
        <source>Would run the golden unit through the recipe&apos;s steps:</source>
        <translation>將讓標準樣品依配方步驟運轉：</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="136"/>
        <source>This turns motors: add --yes to run them. Nothing was run; nothing written.</source>
        <translation>這會使馬達轉動：加上 --yes 才會運轉。未運轉任何馬達，也未寫入任何檔案。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="141"/>
        <source>measuring the golden unit (Ctrl-C stops every motor):</source>
        <translation>正在量測標準樣品 (按 Ctrl-C 停止所有馬達)：</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="150"/>
        <source>drive %1: %2</source>
        <translation>驅動器 %1：%2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="162"/>
        <source>interrupted</source>
        <translation>已中斷</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="175"/>
        <source>WARNING: %1 is not confirmed stopped</source>
        <translation>警告：%1 未確認停止</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="185"/>
        <source>limits from the golden unit:</source>
        <translation>由標準樣品訂定的限值：</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="189"/>
        <source>  drive %1, step %2: %3</source>
        <translation>  驅動器 %1，步驟 %2：%3</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="213"/>
        <source>error: %1; usage: eol %2</source>
        <translation>錯誤：%1；用法：eol %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="218"/>
        <source>unexpected argument &quot;%1&quot;</source>
        <translation>非預期的引數 &quot;%1&quot;</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="222"/>
        <source>give either --from-backup FILE or --drives LIST</source>
        <translation>請指定 --from-backup FILE 或 --drives LIST 其中之一</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="225"/>
        <source>--measure needs the golden unit on the bus: give --drives LIST</source>
        <translation>--measure 需要匯流排上的標準樣品：請指定 --drives 清單</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="231"/>
        <source>--margin is for --measure</source>
        <translation>--margin 僅用於 --measure</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="233"/>
        <source>--margin %1: give a percentage from 1 to 100</source>
        <translation>--margin %1：請輸入 1 到 100 的百分比</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="239"/>
        <source>give the product&apos;s name with --product NAME</source>
        <translation>請以 --product NAME 指定產品名稱</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="241"/>
        <source>give the recipe&apos;s revision with --revision REV</source>
        <translation>請以 --revision REV 指定配方版次</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="244"/>
        <source>give the recipe file to write with -o RECIPE</source>
        <translation>請以 -o RECIPE 指定要寫入的配方檔</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="248"/>
        <source>error: %1 exists; give --force to replace it</source>
        <translation>錯誤：%1 已存在；請加上 --force 以取代</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="253"/>
        <source>error: %1; nothing read</source>
        <translation>錯誤：%1；未讀取任何資料</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="272"/>
        <source>--drives %1: %2</source>
        <translation>--drives %1：%2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="115"/>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="290"/>
        <source>error: %1</source>
        <translation>錯誤：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="308"/>
        <source>wrote %1: %2 revision %3, %4</source>
        <translation>已寫入 %1：%2 版次 %3，%4</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="316"/>
        <source>error: the recipe does not pass &quot;eol recipe check&quot;: fix it, then sign it with &quot;opentop-cli eol recipe sign %1&quot;</source>
        <translation>錯誤：配方未通過 &quot;eol recipe check&quot;：請修正後以 &quot;opentop-cli eol recipe sign %1&quot; 簽署</translation>
    </message>
</context>
<context>
    <name>opentop::EolRecipeShowCommand</name>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="61"/>
        <source>Show a recipe: positions, settings by label with units, steps and limits</source>
        <translation>顯示配方：位置、依標籤列出的設定 (含單位)、步驟與限值</translation>
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
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="88"/>
        <source>  no settings</source>
        <translation>  無設定</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="90"/>
        <source>  setting</source>
        <translation>  設定</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="90"/>
        <source>value</source>
        <translation>值</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="90"/>
        <source>unit</source>
        <translation>單位</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="100"/>
        <source>  per-unit value</source>
        <translation>  單台數值</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="100"/>
        <source>range</source>
        <translation>範圍</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="100"/>
        <source>from</source>
        <translation>來源</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="103"/>
        <source>%1 … %2</source>
        <translation>%1 … %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="106"/>
        <source>CSV file by serial</source>
        <translation>依序號取自 CSV 檔</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="107"/>
        <source>typed by the operator</source>
        <translation>由作業員輸入</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="112"/>
        <source>  no test steps</source>
        <translation>  無測試步驟</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="115"/>
        <source>  steps:</source>
        <translation>  步驟：</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="174"/>
        <source>%1, revision %2</source>
        <translation>%1，版次 %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="180"/>
        <source>serial numbers: %1</source>
        <translation>序號：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="181"/>
        <source>checksum %1</source>
        <translation>檢查碼 %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="182"/>
        <source>position</source>
        <translation>位置</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="182"/>
        <source>machine number</source>
        <translation>機號</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="182"/>
        <source>name</source>
        <translation>名稱</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="182"/>
        <source>family</source>
        <translation>系列</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="183"/>
        <source>variants</source>
        <translation>機型</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="183"/>
        <source>firmware</source>
        <translation>韌體</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="194"/>
        <source>any</source>
        <translation>不限</translation>
    </message>
</context>
<context>
    <name>opentop::EolRecipeSignCommand</name>
    <message>
        <location filename="../cli/EolRecipeSignCommand.cpp" line="27"/>
        <source>Accept a recipe edited by hand: a new checksum, only when it passes check</source>
        <translation>接受手動編輯的配方：僅在通過檢查時產生新的檢查碼</translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolRecipeSignCommand.cpp" line="49"/>
        <source>error: %1 does not pass check (%n problem(s)); not signed</source>
        <translation>
            <numerusform>錯誤：%1 未通過檢查 (%n 個問題)；未簽署</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeSignCommand.cpp" line="57"/>
        <source>error: %1; not signed</source>
        <translation>錯誤：%1；未簽署</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeSignCommand.cpp" line="70"/>
        <source>%1 is signed already (%2); nothing changed</source>
        <translation>%1 已簽署 (%2)；未做任何變更</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeSignCommand.cpp" line="74"/>
        <source>signed %1: %2 revision %3, %4</source>
        <translation>已簽署 %1：%2 版次 %3，%4</translation>
    </message>
</context>
<context>
    <name>opentop::EolResultsCommand</name>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="74"/>
        <source>List units of the results database, their first-pass yield, or export them as CSV</source>
        <translation>列出結果資料庫中的產品、其一次良率，或匯出為 CSV</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="81"/>
        <source>The results database: a SQLite file, sqlite:PATH or postgresql://user@host/db (default: OPENTOP_EOL_DB, else ~/.local/share/opentop/results.db).</source>
        <translation>結果資料庫：SQLite 檔、sqlite:PATH 或 postgresql://user@host/db (預設：OPENTOP_EOL_DB，否則為 ~/.local/share/opentop/results.db)。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="83"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="85"/>
        <source>results: only this serial number; with * or ? a pattern that ignores case (&quot;SN-10*&quot;).</source>
        <translation>results：只列出此序號；含 * 或 ? 時為不分大小寫的樣式（&quot;SN-10*&quot;）。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="87"/>
        <source>S</source>
        <translation>S</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="89"/>
        <source>results: started at or after T (2026-11-24, 2026-11-24T06:00, 8h, 2d, today).</source>
        <translation>results：於 T 或之後開始 (2026-11-24、2026-11-24T06:00、8h、2d、today)。</translation>
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
        <translation>results：於 T 之前開始。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="92"/>
        <source>results: only this recipe (product name).</source>
        <translation>results：僅此配方 (產品名稱)。</translation>
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
        <translation>results：僅此工站。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="101"/>
        <source>results: only the newest N units.</source>
        <translation>results：僅最新的 N 台產品。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="101"/>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="103"/>
        <source>results: CSV (RFC 4180) on standard output or to -o FILE.</source>
        <translation>results：以 CSV (RFC 4180) 輸出至標準輸出或 -o FILE。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="108"/>
        <source>results --yield: the shifts&apos; start times in local time (default 06:00,14:00,22:00).</source>
        <translation>results --yield：各班別的開始時間，以本地時間表示 (預設 06:00,14:00,22:00)。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="109"/>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="141"/>
        <source>&quot;%1&quot; is not a time; give 2026-11-24, 2026-11-24T06:00 (local, or with Z or +01:00), 8h, 2d, today or yesterday</source>
        <translation>&quot;%1&quot; 不是時間；請使用 2026-11-24、2026-11-24T06:00 (本地時間，或加上 Z 或 +01:00)、8h、2d、today 或 yesterday</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="151"/>
        <location filename="../cli/EolResultsCommand.cpp" line="297"/>
        <source>error: %1</source>
        <translation>錯誤：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="167"/>
        <source>--%1: %2</source>
        <translation>--%1：%2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="172"/>
        <source>--since %1 is not before --until %2</source>
        <translation>--since %1 未早於 --until %2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="94"/>
        <source>results: only this version of a recipe (its checksum, as eol recipe check prints it).</source>
        <translation>results：僅此版本的配方 (以檢查碼指定，即 eol recipe check 顯示的值)。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="96"/>
        <source>SUM</source>
        <translation>SUM</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="98"/>
        <source>results: pass, fail, error (station error), interrupted, aborted or running.</source>
        <translation>results：pass、fail、error (工站錯誤)、interrupted、aborted 或 running。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="105"/>
        <source>results: first-, second- and last-pass yield and failure reasons per recipe version and per shift; station errors and aborts are kept out of yield.</source>
        <translation>results：依配方版本及班別列出一次、二次及最終良率與不合格原因；工站錯誤與中止不計入良率。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="178"/>
        <source>--verdict &quot;%1&quot;: give pass, fail, error, interrupted, aborted or running</source>
        <translation>--verdict &quot;%1&quot;：請指定 pass、fail、error、interrupted、aborted 或 running</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="186"/>
        <source>--limit &quot;%1&quot;: give a number of units from 1</source>
        <translation>--limit &quot;%1&quot;：請指定 1 以上的產品台數</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="196"/>
        <location filename="../cli/EolResultsCommand.cpp" line="226"/>
        <source>no unit matches</source>
        <translation>沒有符合的產品</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="199"/>
        <source>started</source>
        <translation>開始時間</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="199"/>
        <source>serial</source>
        <translation>序號</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="199"/>
        <location filename="../cli/EolResultsCommand.cpp" line="230"/>
        <source>recipe</source>
        <translation>配方</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="199"/>
        <source>station</source>
        <translation>工站</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="199"/>
        <source>approved by</source>
        <translation>核准人</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="200"/>
        <source>operator</source>
        <translation>作業員</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="200"/>
        <source>verdict</source>
        <translation>判定</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="200"/>
        <source>time</source>
        <translation>時間</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="200"/>
        <source>reason</source>
        <translation>原因</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="200"/>
        <source>drives</source>
        <translation>驅動器</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="209"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="211"/>
        <source>%1 rev. %2</source>
        <translation>%1 版次 %2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="232"/>
        <source>shift</source>
        <translation>班別</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="233"/>
        <source>serials</source>
        <translation>序號數</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="233"/>
        <source>first pass</source>
        <translation>一次合格</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="233"/>
        <source>second pass</source>
        <translation>二次合格</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="233"/>
        <source>last pass</source>
        <translation>最終合格</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="234"/>
        <source>passed</source>
        <translation>合格</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="234"/>
        <source>failed</source>
        <translation>不合格</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="234"/>
        <source>station errors</source>
        <translation>工站錯誤</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="254"/>
        <source>Yield per recipe version (station errors and aborts are not counted)</source>
        <translation>各配方版本的良率 (不計入工站錯誤與中止)</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="263"/>
        <source>%1: checksum %2</source>
        <translation>%1：檢查碼 %2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="234"/>
        <source>not finished</source>
        <translation>未完成</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="266"/>
        <source>Per shift</source>
        <translation>各班別</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="282"/>
        <source>Failure reasons</source>
        <translation>不合格原因</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="283"/>
        <source>Station errors (not counted in yield)</source>
        <translation>工站錯誤 (不計入良率)</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="300"/>
        <source>wrote %1</source>
        <translation>已寫入 %1</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="308"/>
        <source>error: unexpected argument &quot;%1&quot;; usage: eol %2</source>
        <translation>錯誤：非預期的引數 &quot;%1&quot;；用法：eol %2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="315"/>
        <source>error: give --csv or --json, not both</source>
        <translation>錯誤：--csv 與 --json 只能擇一</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="319"/>
        <source>error: -o names the CSV file: give --csv too</source>
        <translation>錯誤：-o 指定的是 CSV 檔：請同時加上 --csv</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="324"/>
        <source>error: --shifts is for --yield</source>
        <translation>錯誤：--shifts 僅用於 --yield</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="333"/>
        <source>error: --shifts %1: %2</source>
        <translation>錯誤：--shifts %1：%2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="352"/>
        <location filename="../cli/EolResultsCommand.cpp" line="382"/>
        <location filename="../cli/EolResultsCommand.cpp" line="393"/>
        <source>error: %1: %2</source>
        <translation>錯誤：%1：%2</translation>
    </message>
</context>
<context>
    <name>opentop::EolRun</name>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="59"/>
        <source>recording the unit before anything is sent</source>
        <translation>傳送任何內容前正在記錄產品</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="65"/>
        <source>the results database cannot record the unit: %1</source>
        <translation>結果資料庫無法記錄此產品：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="98"/>
        <source>the recipe has no drives</source>
        <translation>配方中沒有驅動器</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="111"/>
        <source>the recipe is not valid: %1</source>
        <translation>配方無效：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="116"/>
        <source>%1: no value for %2 for this unit</source>
        <translation>%1：此產品沒有 %2 的值</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="134"/>
        <source>cancelled by the operator</source>
        <translation>已由作業員取消</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="145"/>
        <source>the connection was lost: %1</source>
        <translation>連線中斷：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="153"/>
        <location filename="../model/eol/EolRun.cpp" line="161"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="158"/>
        <source>%1 failed</source>
        <translation>%1 失敗</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="198"/>
        <source>NOT CONFIRMED STOPPED: %1</source>
        <translation>未確認停止：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="207"/>
        <source>recording the result</source>
        <translation>正在記錄結果</translation>
    </message>
</context>
<context>
    <name>opentop::EolRunCommand</name>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="59"/>
        <source>Set up and test one unit at the end of the line; record the result</source>
        <translation>於終檢工站設定並測試一台產品，並記錄結果</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="65"/>
        <source>The unit&apos;s serial number (as its barcode reads).</source>
        <translation>產品序號 (依條碼讀取值)。</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="65"/>
        <source>S</source>
        <translation>S</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="66"/>
        <source>Who tests it, on a station without users (default: the login name).</source>
        <translation>無使用者的工站上的測試者（預設：登入名稱）。</translation>
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
        <translation>此工站名稱 (預設：主機名稱)。</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="70"/>
        <source>Results database: an SQLite file or postgresql://user@host/db.</source>
        <translation>結果資料庫：SQLite 檔或 postgresql://user@host/db。</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="70"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="71"/>
        <source>CSV file with the per-unit values, by serial number.</source>
        <translation>含單台數值的 CSV 檔，依序號對應。</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="71"/>
        <source>CSV</source>
        <translation>CSV</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="72"/>
        <source>A per-unit value typed by the operator, e.g. 1:spno3.speed=1500.</source>
        <translation>由作業員輸入的單台數值，例如 1:spno3.speed=1500。</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="73"/>
        <source>ID:NAME=VALUE</source>
        <translation>ID:NAME=VALUE</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="75"/>
        <source>A technician allows a retest the recipe&apos;s rules hold back (a serial that passed already, or its attempts used up).</source>
        <translation>由技術員許可配方規則不允許的重新測試 (已合格的序號，或測試次數已用完)。</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="109"/>
        <source>--value %1: write it as MACHINE:NAME=VALUE, e.g. 1:spno3.speed=1500</source>
        <translation>--value %1：請寫成 MACHINE:NAME=VALUE，例如 1:spno3.speed=1500</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="114"/>
        <source>--value %1: %2</source>
        <translation>--value %1：%2</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="137"/>
        <source>--variant %1: %2 allows %3; nothing was sent</source>
        <translation>--variant %1：%2 允許 %3；未送出任何內容</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="139"/>
        <source>any %1 variant</source>
        <translation>任何 %1 機型</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="148"/>
        <source>--variant %1: the recipe has no position at machine number %2; nothing was sent</source>
        <translation>--variant %1：配方在機號 %2 沒有位置；未送出任何內容</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="162"/>
        <source>usage: opentop-cli eol %1</source>
        <translation>用法：opentop-cli eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="178"/>
        <source>%1: the recipe is not valid; nothing was sent:</source>
        <translation>%1：配方無效；未送出任何資料：</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="188"/>
        <source>--serial: %1; nothing was sent</source>
        <translation>--serial：%1；未送出任何內容</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="217"/>
        <source>results database: %1; nothing was sent</source>
        <translation>結果資料庫：%1；未送出任何資料</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="223"/>
        <source>note: unit %1 (begun %2) was left unfinished by a station process that is gone; it is now recorded as interrupted. Check that its motor is stopped.</source>
        <translation>注意：單元 %1（開始於 %2）因工作站程序已結束而未完成，現已記錄為「中斷」。請確認其馬達已停止。</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="228"/>
        <source>note: %1 result(s) kept on this station could not be sent to the results database yet</source>
        <translation>注意：本工作站保存的 %1 筆結果尚未能送到結果資料庫</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="317"/>
        <source>error: %1; nothing was sent</source>
        <translation>錯誤：%1；未送出任何資料</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="320"/>
        <source>a technician allows it with --retest</source>
        <translation>技術員可使用 --retest 許可重新測試</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="269"/>
        <source>note: %1; tested again as --retest allows</source>
        <translation>注意：%1；依 --retest 的許可重新測試</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="273"/>
        <source>note: %1</source>
        <translation>注意：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="280"/>
        <source>station: %1</source>
        <translation>工作站：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="326"/>
        <source>a drive of the station is not confirmed stopped; nothing was tested</source>
        <translation>工作站有驅動器未確認停止；未進行任何檢測</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="298"/>
        <source>interrupted at the station</source>
        <translation>在工站上中斷</translation>
    </message>
</context>
<context>
    <name>opentop::EolRunIdentity</name>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="50"/>
        <location filename="../cli/EolRunIdentity.cpp" line="88"/>
        <source>the results database is not open</source>
        <translation>結果資料庫未開啟</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="53"/>
        <location filename="../cli/EolRunIdentity.cpp" line="101"/>
        <source>results database: %1; nothing was sent</source>
        <translation>結果資料庫：%1；未送出任何資料</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="65"/>
        <location filename="../cli/EolRunIdentity.cpp" line="107"/>
        <source>refused: %1; nothing was sent</source>
        <translation>拒絕：%1；未傳送任何內容</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="66"/>
        <source>this station has users: name who tests with --user NAME (the password from OPENTOP_PASSWORD or the terminal)</source>
        <translation>此工站有使用者：請以 --user NAME 指定測試者（密碼取自 OPENTOP_PASSWORD 或終端機）</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="73"/>
        <source>error: on a station with users the operator is the user who logs in (--user); --operator is not taken</source>
        <translation>錯誤：有使用者的工站上，作業員即登入的使用者（--user）；不接受 --operator</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="98"/>
        <source>run-units: recipe checksum %1 is not approved</source>
        <translation>run-units：配方校驗碼 %1 未核准</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="113"/>
        <source>refused: %1 Nothing was sent.</source>
        <translation>拒絕：%1 未傳送任何內容。</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="123"/>
        <source>%1 logged in; recipe approved by %2 (approval %3)</source>
        <translation>%1 已登入；配方由 %2 核准（核准 %3）</translation>
    </message>
</context>
<context>
    <name>opentop::EolRunOutput</name>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="98"/>
        <location filename="../cli/EolRunOutput.cpp" line="121"/>
        <source>drive %1</source>
        <translation>驅動器 %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="129"/>
        <source>ok</source>
        <translation>OK</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="129"/>
        <source>FAIL</source>
        <translation>不合格</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="165"/>
        <source>rev. %1</source>
        <translation>版次 %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="167"/>
        <source>attempt %1</source>
        <translation>第 %1 次測試</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="174"/>
        <source>the result was NOT recorded: %1</source>
        <translation>結果「未」記錄：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="178"/>
        <source>the results database did not answer: the result is kept on this station (%1) and sent when a station program next reaches the database</source>
        <translation>結果資料庫沒有回應：結果已保存在本工作站（%1），下次工作站程式連上資料庫時會送出</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="183"/>
        <source>WARNING: motor not confirmed stopped: %1</source>
        <translation>警告：未確認馬達已停止：%1</translation>
    </message>
</context>
<context>
    <name>opentop::EolSettingsWriter</name>
    <message>
        <location filename="../model/eol/EolSettingsWriter.cpp" line="69"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/EolSettingsWriter.cpp" line="95"/>
        <source>%1 cannot be read back: %2</source>
        <translation>%1 無法回讀：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/EolSettingsWriter.cpp" line="101"/>
        <source>%1 does not keep its value: set to %2, reads %3</source>
        <translation>%1 未保持其值：設定為 %2，讀取為 %3</translation>
    </message>
</context>
<context>
    <name>opentop::EolSpeedChart</name>
    <message>
        <location filename="../ui/eol/EolSpeedChart.cpp" line="20"/>
        <source>time (s)</source>
        <translation>時間 (s)</translation>
    </message>
    <message>
        <location filename="../ui/eol/EolSpeedChart.cpp" line="44"/>
        <source>speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <location filename="../ui/eol/EolSpeedChart.cpp" line="44"/>
        <location filename="../ui/eol/EolSpeedChart.cpp" line="57"/>
        <source>speed (%1)</source>
        <translation>速度 (%1)</translation>
    </message>
    <message>
        <location filename="../ui/eol/EolSpeedChart.cpp" line="52"/>
        <source>drive %1</source>
        <translation>驅動器 %1</translation>
    </message>
</context>
<context>
    <name>opentop::EolStation</name>
    <message>
        <location filename="../model/station/EolStation.cpp" line="121"/>
        <source>a unit is being tested</source>
        <translation>有產品正在測試中</translation>
    </message>
    <message>
        <location filename="../model/station/EolStation.cpp" line="125"/>
        <source>open a recipe first</source>
        <translation>請先開啟配方</translation>
    </message>
    <message>
        <location filename="../model/station/EolStation.cpp" line="145"/>
        <source>run-units: serial %1: %2</source>
        <translation>run-units：序號 %1：%2</translation>
    </message>
    <message>
        <location filename="../model/station/EolStation.cpp" line="149"/>
        <source>not connected to a bus</source>
        <translation>未連線至匯流排</translation>
    </message>
    <message>
        <location filename="../model/station/EolStation.cpp" line="153"/>
        <source>unit %1 starts as soon as the station&apos;s drives are safe</source>
        <translation>工作站的驅動器確認安全後，單元 %1 會立即開始</translation>
    </message>
    <message>
        <location filename="../model/station/EolStation.cpp" line="185"/>
        <source>serial %1 tested again, allowed by %2: %3</source>
        <translation>序號 %1 重新測試,由 %2 核准:%3</translation>
    </message>
    <message>
        <location filename="../model/station/EolStation.cpp" line="227"/>
        <source>no unit was started yet</source>
        <translation>尚未開始任何產品的測試</translation>
    </message>
</context>
<context>
    <name>opentop::EolStepRunner</name>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="118"/>
        <source>step %1 (%2)</source>
        <translation>步驟 %1 (%2)</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="124"/>
        <location filename="../model/eol/EolStepRunner.cpp" line="148"/>
        <source>the drive&apos;s session ended</source>
        <translation>驅動器的連線階段已結束</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="197"/>
        <location filename="../model/eol/EolStepRunner.cpp" line="215"/>
        <location filename="../model/eol/EolStepRunner.cpp" line="225"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="209"/>
        <source>%1: the drive has no communication priority</source>
        <translation>%1：驅動器未設為通訊優先</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="256"/>
        <source>the stop command failed: %1</source>
        <translation>停止指令失敗：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="269"/>
        <source>stopped after %1 s</source>
        <translation>%1 s 後停止</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="270"/>
        <source>not confirmed stopped: %1</source>
        <translation>未確認停止：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="326"/>
        <source>communication priority could not be given back: %1</source>
        <translation>無法恢復原本的控制優先權：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="157"/>
        <source>the steps ended with the motor running</source>
        <translation>步驟結束時馬達仍在運轉</translation>
    </message>
</context>
<context>
    <name>opentop::EolSupport</name>
    <message>
        <location filename="../cli/EolSupport.cpp" line="26"/>
        <source>error: name one recipe file; usage: eol %1</source>
        <translation>錯誤：請指定一個配方檔；用法：eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="39"/>
        <source>no such file</source>
        <translation>檔案不存在</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="41"/>
        <source>is a directory; name a recipe file</source>
        <translation>是資料夾；請指定配方檔</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="43"/>
        <source>is not a regular file (a device, FIFO or socket); name a recipe file</source>
        <translation>不是一般檔案 (裝置、FIFO 或 socket)；請指定配方檔</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="45"/>
        <source>is larger than %1 MB, the most a recipe file may hold</source>
        <translation>大於配方檔上限 %1 MB</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="49"/>
        <source>cannot be read: %1</source>
        <translation>無法讀取：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="51"/>
        <location filename="../cli/EolSupport.cpp" line="177"/>
        <source>error: %1: %2</source>
        <translation>錯誤：%1：%2</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="78"/>
        <location filename="../cli/EolSupport.cpp" line="199"/>
        <source>error: %1</source>
        <translation>錯誤：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="86"/>
        <source>error: %1 refused: %2</source>
        <translation>錯誤：%1 被拒絕：%2</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="95"/>
        <source>%1 was changed after OpenTOP wrote it (its checksum does not match), so no station runs it. Check it with &quot;opentop-cli eol recipe check %1&quot; and, when it is right, sign it with &quot;opentop-cli eol recipe sign %1&quot;</source>
        <translation>%1 在 OpenTOP 寫入後曾被修改 (檢查碼不符)，因此任何工站都不會執行。請以 &quot;opentop-cli eol recipe check %1&quot; 檢查，確認無誤後以 &quot;opentop-cli eol recipe sign %1&quot; 簽署</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="113"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolSupport.cpp" line="140"/>
        <source>%n position(s)</source>
        <translation>
            <numerusform>%n 個位置</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolSupport.cpp" line="141"/>
        <source>%n setting(s)</source>
        <translation>
            <numerusform>%n 項設定</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolSupport.cpp" line="143"/>
        <source>%n per-unit value(s)</source>
        <translation>
            <numerusform>%n 個單台數值</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolSupport.cpp" line="144"/>
        <source>%n step(s)</source>
        <translation>
            <numerusform>%n 個步驟</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="151"/>
        <source>The file to write (recipe create; results --csv; certificate).</source>
        <translation>要寫入的檔案 (recipe create；results --csv；certificate)。</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="152"/>
        <source>FILE</source>
        <translation>FILE</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="188"/>
        <source>error: no results database at %1 (nothing recorded there yet); name one with --db URL</source>
        <translation>錯誤：%1 沒有結果資料庫 (尚未記錄任何資料)；請以 --db URL 指定</translation>
    </message>
</context>
<context>
    <name>opentop::EolTarget</name>
    <message>
        <location filename="../model/eol/EolTarget.cpp" line="26"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/EolTarget.cpp" line="38"/>
        <location filename="../model/eol/EolTarget.cpp" line="49"/>
        <source>not a parameter of %1</source>
        <translation>不是 %1 的參數</translation>
    </message>
    <message>
        <location filename="../model/eol/EolTarget.cpp" line="51"/>
        <source>this unit&apos;s value is missing</source>
        <translation>缺少此產品的值</translation>
    </message>
    <message>
        <location filename="../model/eol/EolTarget.cpp" line="54"/>
        <source>%1 is outside this product&apos;s range %2–%3 %4</source>
        <translation>%1 超出此產品的範圍 %2–%3 %4</translation>
    </message>
</context>
<context>
    <name>opentop::EolUserCommand</name>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="72"/>
        <source>Add a user (operator, technician, engineer or administrator); the first user is an administrator and needs no --user</source>
        <translation>新增使用者（作業員、技術員、工程師或管理員）；第一位使用者是管理員，不需要 --user</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="75"/>
        <source>List the users of the results database</source>
        <translation>列出結果資料庫的使用者</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="77"/>
        <source>Disable a user: they can no longer log in; their records stay</source>
        <translation>停用使用者：無法再登入；其紀錄保留</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="81"/>
        <source>Set a user&apos;s password (your own with your old one, anyone&apos;s as administrator)</source>
        <translation>設定使用者密碼（自己的需輸入舊密碼，管理員可設定任何人的）</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="87"/>
        <source>Results database: an SQLite file or postgresql://user@host/db.</source>
        <translation>結果資料庫：SQLite 檔案或 postgresql://user@host/db。</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="87"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="90"/>
        <source>user add: operator, technician, engineer or administrator.</source>
        <translation>user add：operator、technician、engineer 或 administrator。</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="92"/>
        <source>ROLE</source>
        <translation>角色</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="93"/>
        <source>user add: the name shown on the screen.</source>
        <translation>user add：畫面上顯示的名稱。</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="94"/>
        <source>TEXT</source>
        <translation>文字</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="109"/>
        <location filename="../cli/EolUserCommand.cpp" line="168"/>
        <source>error: %1</source>
        <translation>錯誤：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="124"/>
        <source>no users: this station is unmanaged (anyone can run, edit and leave); add the first administrator with: opentop-cli eol user add NAME --role administrator</source>
        <translation>沒有使用者：此工站未受管理（任何人都可執行、編輯和離開）；新增第一位管理員：opentop-cli eol user add NAME --role administrator</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="130"/>
        <source>user</source>
        <translation>使用者</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="130"/>
        <source>name</source>
        <translation>名稱</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="130"/>
        <source>role</source>
        <translation>角色</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="130"/>
        <source>active</source>
        <translation>啟用</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="130"/>
        <source>created</source>
        <translation>建立時間</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="133"/>
        <source>yes</source>
        <translation>是</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="133"/>
        <source>no (disabled)</source>
        <translation>否（已停用）</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="145"/>
        <source>usage: opentop-cli eol %1</source>
        <translation>用法：opentop-cli eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="153"/>
        <source>error: --role is one of: %1</source>
        <translation>錯誤：--role 須為下列之一：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="183"/>
        <source>Present password for %1: </source>
        <translation>%1 的目前密碼：</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="194"/>
        <location filename="../cli/EolUserCommand.cpp" line="216"/>
        <source>New password for %1: </source>
        <translation>%1 的新密碼：</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="203"/>
        <source>user %1 added as %2</source>
        <translation>已新增使用者 %1，角色 %2</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="211"/>
        <source>user %1 disabled</source>
        <translation>已停用使用者 %1</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="221"/>
        <source>password of %1 changed</source>
        <translation>已變更 %1 的密碼</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="230"/>
        <source>error: %1; nothing was changed</source>
        <translation>錯誤：%1；未做任何變更</translation>
    </message>
</context>
<context>
    <name>opentop::ExitActions</name>
    <message>
        <location filename="../model/run/ExitActions.cpp" line="50"/>
        <source>Machine number %1: left in communication priority, as it was not confirmed stopped</source>
        <translation>機號 %1：未確認已停止，因此仍維持通訊優先</translation>
    </message>
    <message>
        <location filename="../model/run/ExitActions.cpp" line="75"/>
        <source>The stop broadcast to the %1 drives failed: %2</source>
        <translation>對 %1 驅動器的停止廣播失敗：%2</translation>
    </message>
    <message>
        <location filename="../model/run/ExitActions.cpp" line="81"/>
        <source>Machine number %1: STILL RUNNING (%2) %3</source>
        <translation>機號 %1：仍在運轉 (%2) %3</translation>
    </message>
    <message>
        <location filename="../model/run/ExitActions.cpp" line="86"/>
        <source>Machine number %1: NO ANSWER, not confirmed stopped %2</source>
        <translation>機號 %1：無回應，未確認停止 %2</translation>
    </message>
    <message>
        <location filename="../model/run/ExitActions.cpp" line="111"/>
        <source>Machine number %1: no way to give control back to its inputs is known</source>
        <translation>機號 %1：不知道如何將控制權交還給其輸入端子</translation>
    </message>
    <message>
        <location filename="../model/run/ExitActions.cpp" line="123"/>
        <source>Machine number %1: %2</source>
        <translation>機號 %1：%2</translation>
    </message>
</context>
<context>
    <name>opentop::ExitCheck</name>
    <message>
        <location filename="../model/run/ExitCheck.cpp" line="20"/>
        <source>in communication priority (its own inputs cannot start or stop it)</source>
        <translation>處於通訊優先 (其本身的輸入端子無法啟動或停止它)</translation>
    </message>
    <message>
        <location filename="../model/run/ExitCheck.cpp" line="21"/>
        <source>Machine number %1 (%2): %3</source>
        <translation>機號 %1 (%2)：%3</translation>
    </message>
</context>
<context>
    <name>opentop::ExitGuard</name>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="99"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="134"/>
        <source>Stopping the drives, then giving control back to their inputs…</source>
        <translation>正在停止驅動器，接著將控制權交還給其輸入端子…</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="135"/>
        <source>Stopping the drives…</source>
        <translation>正在停止驅動器…</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="132"/>
        <source>Giving control back to the drives&apos; inputs…</source>
        <translation>正在將控制權交還給驅動器的輸入端子…</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="159"/>
        <source>Not every drive is safe</source>
        <translation>並非所有驅動器都已處於安全狀態</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="160"/>
        <source>Could not %1 every drive:</source>
        <translation>無法對所有驅動器執行「%1」：</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="162"/>
        <source>Stay connected</source>
        <translation>保持連線</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="163"/>
        <source>Go on anyway</source>
        <translation>仍要繼續</translation>
    </message>
</context>
<context>
    <name>opentop::ExitPlan</name>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="55"/>
        <source>Stop and give control back</source>
        <translation>停止並交還控制權</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="56"/>
        <source>Stop the drives</source>
        <translation>停止驅動器</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="56"/>
        <source>Give control back (I/O priority)</source>
        <translation>交還控制權 (I/O 優先)</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="58"/>
        <source>Give control back only</source>
        <translation>僅交還控制權</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="60"/>
        <source>Leave them running</source>
        <translation>讓其繼續運轉</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="60"/>
        <source>Leave them so</source>
        <translation>維持現狀</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="70"/>
        <location filename="../model/run/ExitPlan.cpp" line="73"/>
        <source>give control back to</source>
        <translation>交還控制權</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="71"/>
        <source>stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="71"/>
        <source>stop and give control back to</source>
        <translation>停止並交還控制權</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="82"/>
        <source>Drives are running</source>
        <translation>驅動器運轉中</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="82"/>
        <source>Drives left in communication priority</source>
        <translation>仍處於通訊優先的驅動器</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="88"/>
        <source>Before you %1: these drives are left in communication priority.</source>
        <translation>在%1之前：以下驅動器仍處於通訊優先。</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="89"/>
        <source>Before you %1: these drives are running or left in communication priority.</source>
        <translation>在%1之前：以下驅動器正在運轉或仍處於通訊優先。</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="101"/>
        <source>left as it is: it runs from its own inputs (I/O priority), which a stop over the bus does not override</source>
        <translation>維持現狀：它依其本身的輸入端子運轉 (I/O 優先)，透過匯流排的停止指令無法改變</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="104"/>
        <source>stopped (confirmed by reading it), then given back to its own inputs (I/O priority, read back)</source>
        <translation>停止 (以讀取確認)，接著交還給其本身的輸入端子 (I/O 優先，回讀確認)</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="107"/>
        <source>stopped (confirmed by reading it); its family has no I/O priority setting, so it stays under the bus&apos;s control</source>
        <translation>停止 (以讀取確認)；此系列沒有 I/O 優先設定，因此仍由匯流排控制</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="110"/>
        <source>stopped (confirmed by reading it)</source>
        <translation>停止 (以讀取確認)</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="112"/>
        <source>given back to its own inputs (I/O priority, read back)</source>
        <translation>交還給其本身的輸入端子 (I/O 優先，回讀確認)</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="114"/>
        <source>left as it is: no way to give control back to its inputs is known</source>
        <translation>維持現狀：不知道如何將控制權交還給其輸入端子</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="115"/>
        <source>   → %1</source>
        <translation>   → %1</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="122"/>
        <source>In communication priority a drive takes run and stop only from the bus: once OpenTOP lets go, only another bus master or switching its power off stops it.</source>
        <translation>在通訊優先下，驅動器只接受來自匯流排的運轉與停止指令：OpenTOP 一旦放手，只有其他匯流排主站或切斷電源才能使其停止。</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="126"/>
        <source>Stopping broadcasts every family&apos;s stop command to the whole bus and checks that each drive above has stopped; a drive that has not stopped is not given back to its inputs.</source>
        <translation>停止時會向整個匯流排廣播各系列的停止指令，並確認上列每台驅動器均已停止；未停止的驅動器不會交還給其輸入端子。</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="131"/>
        <source>&quot;Give control back only&quot; sets I/O priority without a stop: the machine&apos;s own inputs decide at once whether the drives run.</source>
        <translation>「僅交還控制權」會直接設為 I/O 優先而不先停止：由機台本身的輸入端子立即決定驅動器是否運轉。</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="135"/>
        <source>&quot;Give control back&quot; sets I/O priority, so the machine&apos;s own inputs run the drives again.</source>
        <translation>「交還控制權」會設為 I/O 優先，讓機台本身的輸入端子再次控制驅動器。</translation>
    </message>
</context>
<context>
    <name>opentop::FaultInjector</name>
    <message>
        <location filename="../sim/FaultInjector.cpp" line="30"/>
        <source>fault &apos;%1&apos; must be NAME=VALUE; names: %2</source>
        <translation>故障 &apos;%1&apos; 必須寫成 NAME=VALUE；名稱：%2</translation>
    </message>
    <message>
        <location filename="../sim/FaultInjector.cpp" line="38"/>
        <source>late_ms must be a whole number of milliseconds 1..60000, got &apos;%1&apos;</source>
        <translation>late_ms 必須是 1..60000 的整數毫秒，收到 &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../sim/FaultInjector.cpp" line="52"/>
        <source>unknown fault &apos;%1&apos;; allowed: %2</source>
        <translation>未知故障 &apos;%1&apos;；允許：%2</translation>
    </message>
    <message>
        <location filename="../sim/FaultInjector.cpp" line="57"/>
        <source>fault rate %1 must be a number 0..1, got &apos;%2&apos;</source>
        <translation>故障率 %1 必須是 0..1 的數字，收到 &apos;%2&apos;</translation>
    </message>
    <message>
        <location filename="../sim/FaultInjector.cpp" line="64"/>
        <source>the fault rates add up to more than 1</source>
        <translation>故障率總和大於 1</translation>
    </message>
</context>
<context>
    <name>opentop::FileActions</name>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="22"/>
        <source>OpenTOP backups (*.json);;All files (*)</source>
        <translation>OpenTOP 備份檔 (*.json);;所有檔案 (*)</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="38"/>
        <location filename="../ui/files/FileActions.cpp" line="94"/>
        <source>&amp;Back up selected drive…</source>
        <translation>備份所選驅動器(&amp;B)…</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="44"/>
        <source>Back up &amp;whole bus…</source>
        <translation>備份整個匯流排(&amp;W)…</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="50"/>
        <source>Save the settings of every identified drive to one file</source>
        <translation>將所有已識別驅動器的設定儲存至一個檔案</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="52"/>
        <source>&amp;Open backup file…</source>
        <translation>開啟備份檔(&amp;O)…</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="54"/>
        <source>Show the drives and settings a backup file holds</source>
        <translation>顯示備份檔中的驅動器與設定</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="55"/>
        <source>Co&amp;mpare…</source>
        <translation>比較(&amp;M)…</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="58"/>
        <source>Compare drives and backup files side by side, or against factory defaults</source>
        <translation>並排比較驅動器與備份檔，或與出廠預設值比較</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="59"/>
        <source>&amp;Restore from file…</source>
        <translation>從檔案還原(&amp;R)…</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="60"/>
        <source>Preview, then write a backup&apos;s settings back to drives</source>
        <translation>預覽後將備份的設定寫回驅動器</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="93"/>
        <source>&amp;Back up selected drives…</source>
        <translation>備份所選驅動器(&amp;B)…</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="96"/>
        <source>Select an identified drive in the bus list first</source>
        <translation>請先在匯流排清單中選擇已識別的驅動器</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="97"/>
        <source>Save the settings of the selected drive(s) to a file</source>
        <translation>將所選驅動器的設定儲存至檔案</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="108"/>
        <source>Back up to file</source>
        <translation>備份至檔案</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="120"/>
        <source>Open backup file</source>
        <translation>開啟備份檔</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="141"/>
        <source>Restore from backup file</source>
        <translation>從備份檔還原</translation>
    </message>
</context>
<context>
    <name>opentop::FileCommandSupport</name>
    <message>
        <location filename="../cli/FileCommandSupport.cpp" line="29"/>
        <source>no such file</source>
        <translation>檔案不存在</translation>
    </message>
    <message>
        <location filename="../cli/FileCommandSupport.cpp" line="31"/>
        <source>is a directory; name a backup file</source>
        <translation>是資料夾；請指定備份檔</translation>
    </message>
    <message>
        <location filename="../cli/FileCommandSupport.cpp" line="33"/>
        <source>is not a regular file (a device, FIFO or socket); name a backup file</source>
        <translation>不是一般檔案 (裝置、FIFO 或 socket)；請指定備份檔</translation>
    </message>
    <message>
        <location filename="../cli/FileCommandSupport.cpp" line="35"/>
        <source>error: %1: %2</source>
        <translation>錯誤：%1：%2</translation>
    </message>
    <message>
        <location filename="../cli/FileCommandSupport.cpp" line="43"/>
        <source>error: %1 refused: %2</source>
        <translation>錯誤：%1 被拒絕：%2</translation>
    </message>
</context>
<context>
    <name>opentop::FixedLineHint</name>
    <message>
        <location filename="../model/bus/FixedLineHint.cpp" line="41"/>
        <source>A DC controller in potentiometer/analog control mode talks only at %1 bit/s, 8%2%3, address %4.</source>
        <translation>處於可變電阻/類比控制模式的 DC 控制器只以 %1 bit/s、8%2%3、位址 %4 通訊。</translation>
    </message>
    <message>
        <location filename="../model/bus/FixedLineHint.cpp" line="60"/>
        <source>%1 8%2%3, address %4</source>
        <translation>%1 8%2%3，位址 %4</translation>
    </message>
</context>
<context>
    <name>opentop::GainDesign</name>
    <message>
        <location filename="../model/tuning/GainDesign.cpp" line="21"/>
        <source>the model has no ultimate point</source>
        <translation>模型沒有臨界點</translation>
    </message>
    <message>
        <location filename="../model/tuning/GainDesign.cpp" line="55"/>
        <source>no gains from the %1 rule settle within %2 ms with at most %3 % overshoot on the motor&apos;s model, even with P at a tenth of the rule&apos;s</source>
        <translation>即使將 P 降到規則值的十分之一，%1 規則的增益在馬達模型上也無法於 %2 ms 內以不超過 %3 % 的超調安定</translation>
    </message>
    <message>
        <location filename="../model/tuning/GainDesign.cpp" line="60"/>
        <source>Try a rule that allows more overshoot or a smaller step (a lower operating speed), or raise the drive&apos;s current limit if the motor allows it.</source>
        <translation>請改用允許較大超調的規則或較小的步階 (較低的運轉速度)；若馬達允許，也可提高驅動器的電流限值。</translation>
    </message>
</context>
<context>
    <name>opentop::GetCommand</name>
    <message>
        <location filename="../cli/GetCommand.cpp" line="44"/>
        <source>Read parameters by name in engineering units (or registers with --raw)</source>
        <translation>依名稱以工程單位讀取參數 (或以 --raw 讀取暫存器)</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="50"/>
        <source>Read every parameter of a group (see params).</source>
        <translation>讀取某一參數群組的所有參數 (參閱 params)。</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="50"/>
        <source>GROUP</source>
        <translation>GROUP</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="51"/>
        <source>Read every readable parameter.</source>
        <translation>讀取所有可讀取的參數。</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="53"/>
        <source>Read registers by address: ADDR or ADDR:COUNT (0x.. or decimal).</source>
        <translation>依位址讀取暫存器：ADDR 或 ADDR:COUNT (0x.. 或十進位)。</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="53"/>
        <source>ADDR</source>
        <translation>ADDR</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="55"/>
        <source>Function code for --raw: 3 (holding) or 4 (input) to read, 6 or 16 to write.</source>
        <translation>--raw 使用的功能碼：讀取用 3 (holding) 或 4 (input)，寫入用 6 或 16。</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="56"/>
        <source>FC</source>
        <translation>FC</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="64"/>
        <source>error: give one machine number first: get ID NAME...</source>
        <translation>錯誤：請先指定一個機號：get ID NAME...</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="72"/>
        <source>error: name parameters, or give exactly one of --group, --all, --raw</source>
        <translation>錯誤：請指定參數，或在 --group、--all、--raw 中擇一</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="80"/>
        <location filename="../cli/GetCommand.cpp" line="210"/>
        <source>error: %1</source>
        <translation>錯誤：%1</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="91"/>
        <source>error: %1 has no group &quot;%2&quot;; groups: %3</source>
        <translation>錯誤：%1 沒有參數群組 &quot;%2&quot;；群組：%3</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="109"/>
        <source>error: %1 is a write-only command and cannot be read</source>
        <translation>錯誤：%1 是僅可寫入的指令，無法讀取</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="110"/>
        <source>error: %1 has no parameter &quot;%2&quot;; see &quot;opentop-cli params --family %1&quot;</source>
        <translation>錯誤：%1 沒有參數 &quot;%2&quot;；請參閱 &quot;opentop-cli params --family %1&quot;</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="124"/>
        <source>interrupted</source>
        <translation>已中斷</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="154"/>
        <source>Parameter</source>
        <translation>參數</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="154"/>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="154"/>
        <source>Raw</source>
        <translation>原始值</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="154"/>
        <source>Label</source>
        <translation>標籤</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="159"/>
        <source>(failed: %1)</source>
        <translation>(失敗：%1)</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="161"/>
        <source>  ! outside the profile&apos;s allowed values</source>
        <translation>  ! 超出定義檔的允許值</translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/GetCommand.cpp" line="168"/>
        <source>error: %n parameter(s) could not be read</source>
        <translation>
            <numerusform>錯誤：%n 個參數無法讀取</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="191"/>
        <source>error: --raw needs ADDR or ADDR:COUNT (address 0x0000–0xFFFF, count 1–125) and --fc 3 or 4</source>
        <translation>錯誤：--raw 需要 ADDR 或 ADDR:COUNT (位址 0x0000–0xFFFF，數量 1–125) 以及 --fc 3 或 4</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="223"/>
        <source>Address</source>
        <translation>位址</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="223"/>
        <source>Hex</source>
        <translation>十六進位</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="223"/>
        <source>Decimal</source>
        <translation>十進位</translation>
    </message>
</context>
<context>
    <name>opentop::GoldenLimits</name>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="67"/>
        <source>the golden unit did not pass its own test (%1): no limits can come from it</source>
        <translation>標準樣品未通過自身的檢測 (%1)：無法由它訂定限值</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="75"/>
        <source>machine number %1: unknown family &quot;%2&quot;</source>
        <translation>機號 %1：未知的機種系列「%2」</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="94"/>
        <source>machine number %1: unknown parameter &quot;%2&quot;</source>
        <translation>機號 %1：未知的參數「%2」</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="104"/>
        <source>machine number %1: the golden unit&apos;s %2 was not measured</source>
        <translation>機號 %1：未量測到標準樣品的 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="129"/>
        <source>Hold limits measured on the golden unit on %1: the measured value ± %2 % (at least %3 % of full scale), never wider than the default limits.</source>
        <translation>保持步驟的限值於 %1 在標準樣品上量測：量測值 ± %2 % (至少為滿刻度的 %3 %)，不會比預設限值寬。</translation>
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
        <translation>無限值</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="153"/>
        <source>%1 %2 (kept: measured %3)</source>
        <translation>%1 %2 (維持原值：量測值 %3)</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="155"/>
        <source>%1 %2 (default %3, measured %4)</source>
        <translation>%1 %2 (預設 %3，量測值 %4)</translation>
    </message>
</context>
<context>
    <name>opentop::GoldenMeasure</name>
    <message>
        <location filename="../model/eol/GoldenMeasure.cpp" line="31"/>
        <source>machine number %1 (%2): runs its motor for about %3 s: %4</source>
        <translation>機號 %1 (%2)：馬達運轉約 %3 s：%4</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenMeasure.cpp" line="43"/>
        <source>golden unit</source>
        <translation>標準樣品</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenMeasure.cpp" line="44"/>
        <source>recipe from a golden unit</source>
        <translation>由標準樣品建立配方</translation>
    </message>
</context>
<context>
    <name>opentop::GoldenMeasureButton</name>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="36"/>
        <source>Measure limits…</source>
        <translation>量測限值…</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="42"/>
        <source>Run the golden unit on the bus through the recipe&apos;s steps once and take the hold limits from what it measures: the measured value ± 25 % (at least 5 % of full scale), never wider than the limits before</source>
        <translation>讓匯流排上的標準樣品依配方步驟運轉一次，以量測值訂定保持步驟的限值：量測值 ± 25 % (至少為滿刻度的 5 %)，不會比原限值寬</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="52"/>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="87"/>
        <source>Measure limits on the golden unit</source>
        <translation>在標準樣品上量測限值</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="60"/>
        <source>The recipe has no positions.</source>
        <translation>配方沒有任何工位。</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="61"/>
        <source>The recipe cannot be read: %1</source>
        <translation>無法讀取配方：%1</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="65"/>
        <source>Machine number %1 is not a drive on the bus: connect to the golden unit and scan first.</source>
        <translation>機號 %1 不是匯流排上的驅動器：請先連線到標準樣品並掃描。</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="70"/>
        <source>Run the golden unit through the recipe&apos;s steps? These motors turn:</source>
        <translation>要讓標準樣品依配方步驟運轉嗎？以下馬達會轉動：</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="76"/>
        <source>Run the motors</source>
        <translation>運轉馬達</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="90"/>
        <source>The bus is not connected.</source>
        <translation>匯流排未連線。</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="95"/>
        <source>Measuring the golden unit…</source>
        <translation>正在量測標準樣品…</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="95"/>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="102"/>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="104"/>
        <source>stopped by the user</source>
        <translation>由使用者停止</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="108"/>
        <source>Machine number %1: %2</source>
        <translation>機號 %1：%2</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="120"/>
        <source>%1 is not confirmed stopped.</source>
        <translation>%1 未確認停止。</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="122"/>
        <source>No limits were taken: %1</source>
        <translation>未訂定任何限值：%1</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="129"/>
        <source>Machine number %1, step %2: %3</source>
        <translation>機號 %1，步驟 %2：%3</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="135"/>
        <source>The hold limits now follow the golden unit. Check them, then save the recipe.</source>
        <translation>保持步驟的限值已依標準樣品訂定。請確認後儲存配方。</translation>
    </message>
</context>
<context>
    <name>opentop::GoldenRecipeSource</name>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="39"/>
        <source>New recipe from %1: check the settings and the test steps&apos; limits, then save it.</source>
        <translation>由 %1 建立的新配方：請檢查設定與測試步驟的限值後儲存。</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="55"/>
        <source>machine number %1 is not a known drive on the bus; scan the bus first</source>
        <translation>機號 %1 不是匯流排上已知的驅動器；請先掃描匯流排</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="64"/>
        <source>Reading the golden unit&apos;s settings…</source>
        <translation>正在讀取標準樣品的設定…</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="64"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="73"/>
        <source>machine number %1 is not on the bus</source>
        <translation>機號 %1 不在匯流排上</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="86"/>
        <source>cancelled: no recipe was made</source>
        <translation>已取消：未建立配方</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="98"/>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="103"/>
        <source>New recipe</source>
        <translation>新配方</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="98"/>
        <source>Product name:</source>
        <translation>產品名稱：</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="103"/>
        <source>Revision:</source>
        <translation>版次：</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="111"/>
        <source>Golden unit&apos;s backup file</source>
        <translation>標準樣品的備份檔</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="112"/>
        <source>Backups (*.json)</source>
        <translation>備份檔 (*.json)</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="124"/>
        <source>No drives on the bus: connect and scan first.</source>
        <translation>匯流排上沒有驅動器：請先連線並掃描。</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="132"/>
        <source>New recipe from drives</source>
        <translation>從驅動器新建配方</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="133"/>
        <source>Machine numbers of the golden unit&apos;s drives (found: %1):</source>
        <translation>標準樣品驅動器的機號 (已找到：%1)：</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="143"/>
        <source>&quot;%1&quot; is not a machine number (1–247)</source>
        <translation>&quot;%1&quot; 不是機號 (1–247)</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="152"/>
        <source>New recipe from the drives on the bus: check the settings and the test steps&apos; limits, then save it.</source>
        <translation>由匯流排上的驅動器建立的新配方：請檢查設定與測試步驟的限值後儲存。</translation>
    </message>
</context>
<context>
    <name>opentop::GroupCheck</name>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="65"/>
        <location filename="../cli/GroupCheck.cpp" line="131"/>
        <source>error: %1</source>
        <translation>錯誤：%1</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="73"/>
        <source>note: --no-group-check: drives in communication group %1 (which also execute what is sent to %1) were not looked for</source>
        <translation>注意：--no-group-check：未尋找通訊群組 %1 內的驅動器 (它們也會執行送往 %1 的內容)</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="79"/>
        <source>error: the drives on this bus are not known, so drives in communication group %1 (which also execute what is sent to %1, without replying) cannot be named; nothing was sent</source>
        <translation>錯誤：不知道此匯流排上有哪些驅動器，因此無法列出通訊群組 %1 內的驅動器 (它們也會執行送往 %1 的內容，且不回應)；未送出任何內容</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="84"/>
        <source>scan the bus first (opentop-cli scan), name its drives with --bus-drives LIST, or add --no-group-check to send it without looking</source>
        <translation>請先掃描匯流排 (opentop-cli scan)、以 --bus-drives LIST 指定其驅動器，或加上 --no-group-check 不檢查直接送出</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="109"/>
        <source>warning: the communication group of %1 could not be read</source>
        <translation>警告：無法讀取 %1 的通訊群組</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="119"/>
        <source>note: the drives on the bus are %1, from %2; drives added since are not known until the next scan</source>
        <translation>注意：匯流排上的驅動器為 %1，取自%2；之後加入的驅動器要到下次掃描才會知道</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="131"/>
        <source>note: %1</source>
        <translation>注意：%1</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="134"/>
        <source>add --yes to send it to all of %1 and %2; nothing was sent</source>
        <translation>加上 --yes 才會送往 %1 及 %2 全部；未送出任何資料</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="169"/>
        <source>not readable</source>
        <translation>無法讀取</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="193"/>
        <source>Read back from the drives of the group:</source>
        <translation>從群組中的驅動器回讀：</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="194"/>
        <source>Drive</source>
        <translation>驅動器</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="194"/>
        <source>Parameter</source>
        <translation>參數</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="194"/>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="194"/>
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="197"/>
        <source>(not read: %1)</source>
        <translation>(未讀取：%1)</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="198"/>
        <source>verified</source>
        <translation>已確認</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="199"/>
        <source>DIFFERS from what was written</source>
        <translation>與寫入值不同</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="200"/>
        <source>not verified</source>
        <translation>未確認</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="248"/>
        <source>off</source>
        <translation>停用</translation>
    </message>
</context>
<context>
    <name>opentop::GroupFollowers</name>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="78"/>
        <source>could not be read</source>
        <translation>無法讀取</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="109"/>
        <source>its control priority could not be read</source>
        <translation>無法讀取其控制優先權</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="111"/>
        <source>it is in %1: it takes run commands only from its input terminals and ignores them over the bus</source>
        <translation>它處於 %1：只接受輸入端子的運轉指令，會忽略經由通訊送來的運轉指令</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="115"/>
        <source>an alarm is active: it runs only once the alarm is cleared</source>
        <translation>有警報發生：警報解除後才會運轉</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="129"/>
        <source>error code %1h</source>
        <translation>錯誤代碼 %1h</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="154"/>
        <source>Machine number %1 follows it.</source>
        <translation>機號 %1 會跟隨。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="155"/>
        <source>Machine number %1 follows it (%2).</source>
        <translation>機號 %1 會跟隨 (%2)。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="158"/>
        <source>Machine number %1: not known whether it follows: %2.</source>
        <translation>機號 %1：不確定是否會跟隨：%2。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="160"/>
        <source>Machine number %1 does NOT follow it: %2. To run it with this drive, set its control priority to communication priority; otherwise it shows E2h &quot;Cannot execute command&quot;.</source>
        <translation>機號 %1 不會跟隨：%2。若要與此驅動器一起運轉，請將其控制優先權設為通訊優先；否則它會顯示 E2h「無法執行指令」。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="174"/>
        <source>Machine number %1: its run state could not be read.</source>
        <translation>機號 %1：無法讀取其運轉狀態。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="176"/>
        <source>Machine number %1 runs.</source>
        <translation>機號 %1 運轉中。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="177"/>
        <source>Machine number %1 runs (%2).</source>
        <translation>機號 %1 運轉中 (%2)。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="179"/>
        <source>Machine number %1 does not run: %2.</source>
        <translation>機號 %1 沒有運轉：%2。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="181"/>
        <source>Machine number %1 does not run.</source>
        <translation>機號 %1 沒有運轉。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="183"/>
        <source>It shows %1</source>
        <translation>它顯示 %1</translation>
    </message>
</context>
<context>
    <name>opentop::GroupWriteCheck</name>
    <message>
        <location filename="../ui/groups/GroupWriteCheck.cpp" line="50"/>
        <source>Machine number %1: %2</source>
        <translation>機號 %1：%2</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupWriteCheck.cpp" line="59"/>
        <source>Communication group</source>
        <translation>通訊群組</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupWriteCheck.cpp" line="64"/>
        <source>Their values are read back afterwards.</source>
        <translation>之後會回讀它們的值。</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupWriteCheck.cpp" line="65"/>
        <source>Send, also to %1</source>
        <translation>送出 (也會送往 %1)</translation>
    </message>
</context>
<context>
    <name>opentop::GroupsView</name>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="34"/>
        <source>Read &amp;groups again</source>
        <translation>重新讀取群組(&amp;G)</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="35"/>
        <source>&amp;Write plan…</source>
        <translation>寫入規劃(&amp;W)…</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="38"/>
        <source>A drive whose communication group is another drive&apos;s machine number is that drive&apos;s child: it executes every write and command sent to its parent, without replying. Plan the groups in the last column and write them; every drive&apos;s group is then read back.</source>
        <translation>若驅動器的通訊群組設為另一台驅動器的機號，即成為該驅動器的群組子站：它會執行送往群組母站的每個寫入與指令，但不回應。請在最後一欄規劃群組並寫入；之後會回讀每台驅動器的群組。</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="49"/>
        <source>Machine number</source>
        <translation>機號</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="49"/>
        <source>Model</source>
        <translation>型號</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="49"/>
        <source>Group</source>
        <translation>群組</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="50"/>
        <source>Follows / followed by</source>
        <translation>跟隨 / 被跟隨</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="50"/>
        <source>Problem</source>
        <translation>問題</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="50"/>
        <source>Plan</source>
        <translation>規劃</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="51"/>
        <source>Read back</source>
        <translation>回讀值</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="57"/>
        <source>Read every drive&apos;s communication group from the drive</source>
        <translation>從每台驅動器讀取其通訊群組</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="58"/>
        <source>Write the planned groups (asks first), then read every drive&apos;s group back</source>
        <translation>寫入規劃的群組 (會先詢問)，然後回讀每台驅動器的群組</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="79"/>
        <location filename="../ui/groups/GroupsView.cpp" line="145"/>
        <source>Disabled</source>
        <translation>停用</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="146"/>
        <source>Planned group of machine number %1</source>
        <translation>機號 %1 的規劃群組</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="147"/>
        <source>The group machine number %1 should have: its own number makes it a parent, another drive&apos;s number its child; Disabled: no group</source>
        <translation>機號 %1 應設定的群組：設為自己的機號即成為群組母站，設為其他驅動器的機號即成為其群組子站；停用：不屬於任何群組</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="166"/>
        <source>child and parent</source>
        <translation>既是子站又是母站</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="167"/>
        <source>no drive %1</source>
        <translation>沒有驅動器 %1</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="176"/>
        <source>not read</source>
        <translation>未讀取</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="198"/>
        <source>No problem found in the groups as read from the drives.</source>
        <translation>從驅動器讀取的群組設定中未發現問題。</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="199"/>
        <source>Problems:</source>
        <translation>問題：</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="206"/>
        <source>%1: %2 → %3</source>
        <translation>%1：%2 → %3</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="213"/>
        <source>The plan is what the drives hold.</source>
        <translation>規劃與驅動器中的設定相同。</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="214"/>
        <source>Plan changes: %1.</source>
        <translation>規劃變更：%1。</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="216"/>
        <source>After it: %1</source>
        <translation>變更後：%1</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="242"/>
        <source>Reading every drive&apos;s group…</source>
        <translation>正在讀取每台驅動器的群組…</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/groups/GroupsView.cpp" line="248"/>
        <source>%n drive(s) did not answer</source>
        <translation>
            <numerusform>%n 台驅動器未回應</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="263"/>
        <source>Machine number %1: group %2 → %3.</source>
        <translation>機號 %1：群組 %2 → %3。</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="268"/>
        <source>This also reaches %1 (its children), which are written again after it.</source>
        <translation>此操作也會送達 %1 (其群組子站)，之後會再重新寫入它們。</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="277"/>
        <source>Warning: %1</source>
        <translation>警告：%1</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="279"/>
        <source>Write communication groups</source>
        <translation>寫入通訊群組</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/groups/GroupsView.cpp" line="280"/>
        <source>Write the planned communication group to %n drive(s)?</source>
        <translation>
            <numerusform>要將規劃的通訊群組寫入 %n 台驅動器嗎？</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="284"/>
        <source>Drives with children are written last; every drive&apos;s group is read back afterwards.</source>
        <translation>有群組子站的驅動器最後寫入；之後會回讀每台驅動器的群組。</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="286"/>
        <source>&amp;Write groups</source>
        <translation>寫入群組(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="317"/>
        <source>Writing group %1 to machine number %2…</source>
        <translation>正在將群組 %1 寫入機號 %2…</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="326"/>
        <source>write failed: %1</source>
        <translation>寫入失敗：%1</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="340"/>
        <source>Reading every drive&apos;s group back…</source>
        <translation>正在回讀每台驅動器的群組…</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="353"/>
        <source>write failed</source>
        <translation>寫入失敗</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="354"/>
        <source>✓ %1</source>
        <translation>✓ %1</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="355"/>
        <source>✗ %1, planned %2</source>
        <translation>✗ %1，規劃為 %2</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="365"/>
        <source>Proved: every drive read back holds its planned group.</source>
        <translation>已確認：每台回讀的驅動器都保有其規劃的群組。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/groups/GroupsView.cpp" line="366"/>
        <source>Not as planned: %1 (read back; %n drive(s) did not answer).</source>
        <translation>
            <numerusform>與規劃不符：%1 (已回讀；%n 台驅動器未回應)。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::HelpActions</name>
    <message>
        <location filename="../ui/help/HelpActions.cpp" line="18"/>
        <source>&amp;User guide</source>
        <translation>使用手冊(&amp;U)</translation>
    </message>
    <message>
        <location filename="../ui/help/HelpActions.cpp" line="21"/>
        <source>&amp;Keyboard shortcuts</source>
        <translation>鍵盤快速鍵(&amp;K)</translation>
    </message>
    <message>
        <location filename="../ui/help/HelpActions.cpp" line="25"/>
        <source>&amp;About OpenTOP</source>
        <translation>關於 OpenTOP(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/help/HelpActions.cpp" line="28"/>
        <source>About &amp;Qt</source>
        <translation>關於 Qt(&amp;Q)</translation>
    </message>
</context>
<context>
    <name>opentop::IdentityDialog</name>
    <message>
        <location filename="../ui/eol/IdentityDialog.cpp" line="23"/>
        <source>Who is it?</source>
        <translation>請確認身分</translation>
    </message>
    <message>
        <location filename="../ui/eol/IdentityDialog.cpp" line="25"/>
        <source>To %1 this station needs the %2 role or higher. Log in with your user name and password.</source>
        <translation>要%1，此工站需要%2或更高角色。請以使用者名稱和密碼登入。</translation>
    </message>
    <message>
        <location filename="../ui/eol/IdentityDialog.cpp" line="42"/>
        <source>User name:</source>
        <translation>使用者名稱:</translation>
    </message>
    <message>
        <location filename="../ui/eol/IdentityDialog.cpp" line="43"/>
        <source>Password:</source>
        <translation>密碼:</translation>
    </message>
    <message>
        <location filename="../ui/eol/IdentityDialog.cpp" line="62"/>
        <source>Refused: %1</source>
        <translation>已拒絕：%1</translation>
    </message>
</context>
<context>
    <name>opentop::InputFile</name>
    <message>
        <location filename="../model/io/InputFile.cpp" line="13"/>
        <source>cannot read %1: %2</source>
        <translation>無法讀取 %1：%2</translation>
    </message>
</context>
<context>
    <name>opentop::IoTerminalsPage</name>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="31"/>
        <source>Not functioning: the drive ignores this input.</source>
        <translation>無功能：驅動器忽略此輸入。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="33"/>
        <source>RUN/STOP: ON runs the motor, OFF stops it.</source>
        <translation>RUN/STOP：ON 時馬達運轉，OFF 時停止。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="35"/>
        <source>CW/CCW: the running direction, OFF clockwise, ON counter-clockwise.</source>
        <translation>CW/CCW：運轉方向，OFF 為順時針，ON 為逆時針。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="38"/>
        <source>CW/STOP: ON runs the motor clockwise, OFF stops it.</source>
        <translation>CW/STOP：ON 時馬達順時針運轉，OFF 時停止。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="40"/>
        <source>CCW/STOP: ON runs the motor counter-clockwise, OFF stops it.</source>
        <translation>CCW/STOP：ON 時馬達逆時針運轉，OFF 時停止。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="43"/>
        <source>Alarm-Reset: clears an alarm (alarm erase method Alarm-Reset).</source>
        <translation>Alarm-Reset：解除警報 (警報解除方式為 Alarm-Reset 時)。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="51"/>
        <source>M%1: bit %1 of the running data selection (M2 M1 M0 = 000–111 select SPno1–SPno8).</source>
        <translation>M%1：運轉資料選擇的第 %1 位元 (M2 M1 M0 = 000–111 選擇 SPno1–SPno8)。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="56"/>
        <source>Ext-Error (EX-Er): an external interrupt that stops the motor; the only input still active in communication priority.</source>
        <translation>Ext-Error (EX-Er)：使馬達停止的外部中斷；通訊優先下唯一仍有效的輸入。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="61"/>
        <source>H-Free: releases the motor&apos;s holding force while stopped.</source>
        <translation>H-Free：停止時解除馬達的保持力。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="63"/>
        <source>Code %1 is not a known input function.</source>
        <translation>代碼 %1 不是已知的輸入功能。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="71"/>
        <source>Not functioning: the output stays off.</source>
        <translation>無功能：輸出保持 OFF。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="73"/>
        <source>Alarm-Out: switches when an alarm stops the motor.</source>
        <translation>Alarm-Out：警報使馬達停止時動作。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="75"/>
        <source>Reach Speed-Out: switches when the motor reaches the target speed.</source>
        <translation>Reach Speed-Out：馬達到達目標速度時動作。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="78"/>
        <source>VA-Out: switches before the target speed, at the target speed minus the VA speed.</source>
        <translation>VA-Out：在到達目標速度之前，於目標速度減去 VA 速度時動作。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="81"/>
        <source>Speed-Out: speed pulses, 24 per motor revolution.</source>
        <translation>Speed-Out：速度脈波，馬達每轉 24 個脈波。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="83"/>
        <source>Warning-Out: switches on a warning; the motor keeps running.</source>
        <translation>Warning-Out：發生警告時動作；馬達繼續運轉。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="86"/>
        <source>Move-Out: switches while the motor is turning.</source>
        <translation>Move-Out：馬達轉動中時動作。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="88"/>
        <source>Code %1 is not a known output function.</source>
        <translation>代碼 %1 不是已知的輸出功能。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="102"/>
        <source>I/O terminals</source>
        <translation>I/O 端子</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="118"/>
        <source>Control</source>
        <translation>控制</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="123"/>
        <source>Control &amp;mode:</source>
        <translation>控制模式(&amp;M)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="124"/>
        <source>Mode1 uses RUN/STOP and CW/CCW inputs (like UBD, SBD, DBD); Mode2 uses CW/STOP and CCW/STOP inputs (like DB, BMD). The input function codes differ: switching the mode disables the other mode&apos;s input functions, so every input X0–X3 needs a function of the new mode.</source>
        <translation>Mode1 使用 RUN/STOP 與 CW/CCW 輸入 (同 UBD、SBD、DBD)；Mode2 使用 CW/STOP 與 CCW/STOP 輸入 (同 DB、BMD)。兩者的輸入功能代碼不同：切換模式會停用另一模式的輸入功能，因此每個輸入 X0–X3 都需要指定新模式的功能。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="136"/>
        <source>Control &amp;priority:</source>
        <translation>控制優先權(&amp;P)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="137"/>
        <source>In I/O priority the input terminals run the motor. In communication priority the drive runs from bus commands and of the inputs only EX-Er (external error) acts.</source>
        <translation>I/O 優先時由輸入端子控制馬達運轉。通訊優先時驅動器依匯流排指令運轉，輸入端子中只有 EX-Er (外部異常) 有作用。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="146"/>
        <source>Inputs — CN5</source>
        <translation>輸入 — CN5</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="148"/>
        <source>COM0: input common (external supply)</source>
        <translation>COM0：輸入共用端 (外部電源)</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="151"/>
        <source>COM1: input common (internal supply)</source>
        <translation>COM1：輸入共用端 (內部電源)</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="156"/>
        <source>Outputs — CN6</source>
        <translation>輸出 — CN6</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="174"/>
        <source>Give each flagged input the default function of the new mode (pending, not written)</source>
        <translation>將每個標示的輸入設為新模式的預設功能 (待寫入，尚未寫入)</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="203"/>
        <source>Connector pin %1</source>
        <translation>接頭針腳 %1</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="208"/>
        <source>Terminal %1 function</source>
        <translation>端子 %1 功能</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="235"/>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="261"/>
        <source>Not read yet.</source>
        <translation>尚未讀取。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="268"/>
        <source>Not valid in %1: choose again</source>
        <translation>在 %1 中無效：請重新選擇</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="296"/>
        <source>The mode changes from %1 to %2 when written; Write page writes the mode first, then the terminals.</source>
        <translation>寫入後模式將由 %1 變為 %2；「寫入本頁」會先寫入模式，再寫入端子。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="306"/>
        <source>Not valid in %1: %2. Choose their functions again before writing.</source>
        <translation>在 %1 中無效：%2。寫入前請重新選擇其功能。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="309"/>
        <source>Use %1 defaults</source>
        <translation>使用 %1 預設值</translation>
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
        <translation>缺少 &quot;%1&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="33"/>
        <source>&quot;%1&quot; must be a string</source>
        <translation>&quot;%1&quot; 必須是字串</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="48"/>
        <source>&quot;%1&quot; must be a number</source>
        <translation>&quot;%1&quot; 必須是數字</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="59"/>
        <source>%1 must be a whole number</source>
        <translation>%1 必須是整數</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="64"/>
        <source>%1 is out of range</source>
        <translation>%1 超出範圍</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="80"/>
        <source>%1 must be an integer or a &quot;0x...&quot; string</source>
        <translation>%1 必須是整數或 &quot;0x...&quot; 字串</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="104"/>
        <source>&quot;%1&quot; must be an array</source>
        <translation>&quot;%1&quot; 必須是陣列</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="120"/>
        <source>&quot;%1&quot; must be an object</source>
        <translation>&quot;%1&quot; 必須是物件</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="130"/>
        <source>%1: unknown key &quot;%2&quot;</source>
        <translation>%1：未知的鍵 &quot;%2&quot;</translation>
    </message>
</context>
<context>
    <name>opentop::Language</name>
    <message>
        <location filename="../model/i18n/Language.cpp" line="140"/>
        <source>unknown language &apos;%1&apos;; available: %2</source>
        <translation>未知的語言「%1」；可用：%2</translation>
    </message>
    <message>
        <location filename="../model/i18n/Language.cpp" line="167"/>
        <source>the %1 translation is missing from this build</source>
        <translation>此版本缺少 %1 翻譯</translation>
    </message>
</context>
<context>
    <name>opentop::LanguageMenu</name>
    <message>
        <location filename="../ui/i18n/LanguageMenu.cpp" line="10"/>
        <source>&amp;Language</source>
        <translation>語言(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/i18n/LanguageMenu.cpp" line="16"/>
        <source>System language (%1)</source>
        <translation>系統語言（%1）</translation>
    </message>
</context>
<context>
    <name>opentop::LimitCheck</name>
    <message>
        <location filename="../model/eol/LimitCheck.cpp" line="35"/>
        <source>%1 could not be read</source>
        <translation>無法讀取 %1</translation>
    </message>
    <message>
        <location filename="../model/eol/LimitCheck.cpp" line="50"/>
        <source>%1 %2 %3, %4</source>
        <translation>%1 %2 %3，%4</translation>
    </message>
    <message>
        <location filename="../model/eol/LimitCheck.cpp" line="73"/>
        <source>allowed %1–%2 %3</source>
        <translation>允許 %1–%2 %3</translation>
    </message>
    <message>
        <location filename="../model/eol/LimitCheck.cpp" line="75"/>
        <source>allowed at most %1 %2</source>
        <translation>最多允許 %1 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/LimitCheck.cpp" line="77"/>
        <source>allowed at least %1 %2</source>
        <translation>至少需 %1 %2</translation>
    </message>
</context>
<context>
    <name>opentop::LineFormat</name>
    <message>
        <location filename="../transport/LineFormat.cpp" line="37"/>
        <source>Baud rate %1 is not supported: use 1200–115200.</source>
        <translation>不支援鮑率 %1：請使用 1200–115200。</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="39"/>
        <source>Parity &apos;%1&apos; is not supported: use N (none), E (even) or O (odd).</source>
        <translation>不支援同位元「%1」：請使用 N（無）、E（偶）或 O（奇）。</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="42"/>
        <source>%1 data bits are not supported: use 7 or 8.</source>
        <translation>不支援 %1 個資料位元：請使用 7 或 8。</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="44"/>
        <source>%1 stop bits are not supported: use 1 or 2.</source>
        <translation>不支援 %1 個停止位元：請使用 1 或 2。</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="66"/>
        <source>&quot;%1&quot; is not a line format: write DATA BITS, PARITY and STOP BITS as 8N1, 8E1, 8O1 or 8N2, with the baud rate before it if it differs from the port&apos;s (9600:8E1)</source>
        <translation>「%1」不是通訊格式：請依資料位元、同位元、停止位元寫成 8N1、8E1、8O1 或 8N2，若鮑率與連接埠不同則寫在前面（9600:8E1）</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="81"/>
        <source>&quot;%1&quot;: %2</source>
        <translation>「%1」：%2</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="98"/>
        <source>&quot;%1&quot;: write MACHINE NUMBER=FORMAT, e.g. 7=9600:8E1 or 7=8N2 (machine numbers 1–247)</source>
        <translation>「%1」：請寫成 機號=格式，例如 7=9600:8E1 或 7=8N2（機號 1–247）</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="107"/>
        <source>machine number %1: %2</source>
        <translation>機號 %1：%2</translation>
    </message>
</context>
<context>
    <name>opentop::LineFormatHint</name>
    <message>
        <location filename="../model/bus/LineFormatHint.cpp" line="72"/>
        <source>%1: %2 from the factory (it can be set to %3).</source>
        <translation>%1：出廠為 %2（可設為 %3）。</translation>
    </message>
    <message>
        <location filename="../model/bus/LineFormatHint.cpp" line="77"/>
        <source>Drives set to another line format than %1 do not answer it. %2</source>
        <translation>設為 %1 以外通訊格式的驅動器不會回應它。%2</translation>
    </message>
</context>
<context>
    <name>opentop::LinkLoss</name>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="31"/>
        <source>Machine number %1 (%2): state never read</source>
        <translation>機號 %1 (%2)：狀態從未讀取</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="46"/>
        <source>The connection to %1 was lost at %2.</source>
        <translation>與 %1 的連線於 %2 中斷。</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="54"/>
        <source>• %1 — last answer %2 (%3 when the link dropped)</source>
        <translation>• %1 — 最後回應 %2 (連線中斷時為 %3)</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="61"/>
        <source>By the last values read, no drive was running or in communication priority.</source>
        <translation>依最後讀取的數值，沒有驅動器正在運轉或處於通訊優先。</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="62"/>
        <source>When the link dropped, by the last values read:</source>
        <translation>連線中斷時，依最後讀取的數值：</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="70"/>
        <source>OpenTOP cannot stop these drives or give control back to their inputs until the link is back: nothing is sent over a lost link. A drive in communication priority keeps its last command. Check on the machine: each drive&apos;s own STOP input, the emergency stop, and the drives&apos; power.</source>
        <translation>在連線恢復之前，OpenTOP 無法停止這些驅動器，也無法將控制權交還給其輸入端子：中斷的連線上不會送出任何資料。處於通訊優先的驅動器會維持最後的指令。請在機台上確認：每台驅動器本身的停止輸入端子、緊急停止，以及驅動器的電源。</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="78"/>
        <source>Before you %1: the connection to %2 was lost at %3, and OpenTOP cannot reach these drives.</source>
        <translation>在%1之前：與 %2 的連線已於 %3 中斷，OpenTOP 無法存取這些驅動器。</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="96"/>
        <source>Running when it dropped, by the last values read: machine number %1.</source>
        <translation>中斷時依最後讀取的數值正在運轉：機號 %1。</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="99"/>
        <source>In communication priority: machine number %1.</source>
        <translation>處於通訊優先：機號 %1。</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/run/LinkLoss.cpp" line="102"/>
        <source>%n drive(s) never read.</source>
        <translation>
            <numerusform>%n 台驅動器從未讀取。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="104"/>
        <source>OpenTOP cannot stop them until the link is back: check each drive&apos;s STOP input, the emergency stop and the power on the machine.</source>
        <translation>在連線恢復之前，OpenTOP 無法停止它們：請在機台上確認每台驅動器的停止輸入端子、緊急停止與電源。</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="118"/>
        <source>Machine number %1 (%2): no answer, its state is not known</source>
        <translation>機號 %1 (%2)：無回應，狀態不明</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="126"/>
        <source>Every drive read again: none is running or in communication priority.</source>
        <translation>已重新讀取所有驅動器：沒有驅動器正在運轉或處於通訊優先。</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="127"/>
        <source>Read again just now:</source>
        <translation>剛剛重新讀取：</translation>
    </message>
</context>
<context>
    <name>opentop::MainMenus</name>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="35"/>
        <source>&amp;Bus</source>
        <translation>匯流排(&amp;B)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="36"/>
        <source>Main</source>
        <translation>主要</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="39"/>
        <source>&amp;Connect…</source>
        <translation>連線(&amp;C)…</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="41"/>
        <source>Choose the serial port, gateway or simulated bus (Ctrl+K)</source>
        <translation>選擇序列埠、閘道器或模擬匯流排 (Ctrl+K)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="45"/>
        <source>&amp;Scan bus</source>
        <translation>掃描匯流排(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="51"/>
        <source>&amp;Disconnect</source>
        <translation>中斷連線(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="57"/>
        <source>Communication &amp;groups…</source>
        <translation>通訊群組(&amp;G)…</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="62"/>
        <source>&amp;Export alarm histories…</source>
        <translation>匯出警報記錄(&amp;E)…</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="64"/>
        <source>&amp;Quit</source>
        <translation>結束(&amp;Q)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="67"/>
        <source>&amp;Files</source>
        <translation>檔案(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="72"/>
        <source>&amp;Drive</source>
        <translation>驅動器(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="75"/>
        <source>&amp;Write all pending</source>
        <translation>寫入所有待寫入項目(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="77"/>
        <source>&amp;Re-read all</source>
        <translation>全部重新讀取(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="79"/>
        <source>Write a setting to the selected drives…</source>
        <translation>將設定寫入所選驅動器…</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="85"/>
        <source>&amp;Next page</source>
        <translation>下一頁(&amp;N)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="91"/>
        <source>&amp;Previous page</source>
        <translation>上一頁(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="107"/>
        <source>&amp;View</source>
        <translation>檢視(&amp;V)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="113"/>
        <source>&amp;Traffic log</source>
        <translation>通訊記錄(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="114"/>
        <source>Bus &amp;overview</source>
        <translation>匯流排總覽(&amp;O)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="116"/>
        <source>T&amp;rends</source>
        <translation>趨勢圖(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="117"/>
        <source>Communication &amp;groups</source>
        <translation>通訊群組(&amp;G)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="130"/>
        <source>Language</source>
        <translation>語言</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="131"/>
        <source>OpenTOP will be in %1 the next time it starts.</source>
        <translation>OpenTOP 下次啟動時將以 %1 顯示。</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="137"/>
        <source>&amp;End of line</source>
        <translation>終檢(&amp;E)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="139"/>
        <source>&amp;Help</source>
        <translation>說明(&amp;H)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="155"/>
        <source>connect elsewhere</source>
        <translation>連線至其他匯流排</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="165"/>
        <source>Export alarm histories</source>
        <translation>匯出警報記錄</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="166"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV 檔 (*.csv)</translation>
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
        <translation>連線至其他匯流排</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="141"/>
        <source>Connecting to %1… (still connected to %2)</source>
        <translation>正在連線至 %1… (仍連線於 %2)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="158"/>
        <source>Connected: %1 (the new connection failed: %2)</source>
        <translation>已連線：%1 (新連線失敗：%2)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="161"/>
        <location filename="../ui/main/MainWindow.cpp" line="175"/>
        <source>Cannot connect</source>
        <translation>無法連線</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="162"/>
        <source>%1

Still connected to %2; nothing was changed.</source>
        <translation>%1

仍連線於 %2；未做任何變更。</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="165"/>
        <location filename="../ui/main/MainWindow.cpp" line="242"/>
        <source>Not connected: %1</source>
        <translation>未連線：%1</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="217"/>
        <location filename="../ui/main/MainWindow.cpp" line="219"/>
        <source>Connection lost: %1</source>
        <translation>連線中斷：%1</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="224"/>
        <source>OpenTOP — SIMULATED BUS (no hardware) — %1</source>
        <translation>OpenTOP — 模擬匯流排 (無實體硬體) — %1</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="225"/>
        <source>OpenTOP — %1</source>
        <translation>OpenTOP — %1</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="226"/>
        <source>Connecting to %1…</source>
        <translation>正在連線至 %1…</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="241"/>
        <source>Connected: %1</source>
        <translation>已連線：%1</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="248"/>
        <source>Connected: %1 (simulated, no hardware)</source>
        <translation>已連線：%1 (模擬，無實體硬體)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="276"/>
        <source>The drive does not report its variant; %1 is the configured one.</source>
        <translation>此驅動器不回報機型；%1 為設定的機型。</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="293"/>
        <location filename="../ui/main/MainWindow.cpp" line="303"/>
        <source>disconnect</source>
        <translation>中斷連線</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="300"/>
        <source>Not connected (disconnected)</source>
        <translation>未連線 (已中斷連線)</translation>
    </message>
</context>
<context>
    <name>opentop::MissingValues</name>
    <message>
        <location filename="../model/session/MissingValues.cpp" line="18"/>
        <source>cannot check the value: reading %1 failed: %2</source>
        <translation>無法檢查此值：讀取 %1 失敗：%2</translation>
    </message>
    <message>
        <location filename="../model/session/MissingValues.cpp" line="41"/>
        <source>reading %1 failed: %2</source>
        <translation>讀取 %1 失敗：%2</translation>
    </message>
</context>
<context>
    <name>opentop::MonitorCommand</name>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="47"/>
        <source>Watch speed, load, state, inputs and alarms live (Ctrl-C ends)</source>
        <translation>即時監視速度、負載、狀態、輸入與警報 (按 Ctrl-C 結束)</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="54"/>
        <source>Time between samples of a drive in ms, %1–%2 (default 500).</source>
        <translation>每台驅動器的取樣間隔，單位 ms，%1–%2 (預設 500)。</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="57"/>
        <source>MS</source>
        <translation>MS</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="58"/>
        <source>Stop after N samples per drive (default: until Ctrl-C).</source>
        <translation>每台驅動器取樣 N 次後停止 (預設：直到按下 Ctrl-C)。</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="59"/>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="61"/>
        <source>Also write every sample to FILE (CSV with a header; a row with a note where the link was lost and where it came back).</source>
        <translation>同時將每筆取樣寫入 FILE (含標題列的 CSV；連線中斷處與恢復處各有一列附註)。</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="63"/>
        <source>FILE</source>
        <translation>FILE</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="65"/>
        <source>When the link to the bus is lost, exit 1 if it is not back within SECONDS (default: reconnect by itself, 0.5 s to 5 s apart, until Ctrl-C).</source>
        <translation>與匯流排的連線中斷時，若 SECONDS 秒內未恢復則以 1 結束 (預設：自動重新連線，間隔 0.5 秒至 5 秒，直到按下 Ctrl-C)。</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="67"/>
        <source>SECONDS</source>
        <translation>SECONDS</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="79"/>
        <source>error: usage: %1</source>
        <translation>錯誤：用法：%1</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="89"/>
        <source>error: --interval must be %1–%2 ms, got &quot;%3&quot;</source>
        <translation>錯誤：--interval 必須為 %1–%2 ms，收到 &quot;%3&quot;</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="102"/>
        <source>error: --count must be a whole number of samples, 1 or more, got &quot;%1&quot;</source>
        <translation>錯誤：--count 必須是 1 以上的整數取樣次數，收到 &quot;%1&quot;</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="113"/>
        <source>error: --give-up must be a number of seconds, more than 0 and at most %1, got &quot;%2&quot;</source>
        <translation>錯誤：--give-up 必須是大於 0 且不超過 %1 的秒數，收到「%2」</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="125"/>
        <source>error: cannot write %1: %2</source>
        <translation>錯誤：無法寫入 %1：%2</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="134"/>
        <source>error: %1</source>
        <translation>錯誤：%1</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="154"/>
        <source>warning: machine number %1: %2; speeds are shown in r/min only</source>
        <translation>警告：機號 %1：%2；速度僅以 r/min 顯示</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="194"/>
        <source>error: cannot write %1: %2; monitoring stopped</source>
        <translation>錯誤：無法寫入 %1：%2；監視已停止</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="233"/>
        <source>%1 link lost: %2 (%3); reconnecting for up to %4 s (Ctrl-C ends)</source>
        <translation>%1 連線中斷：%2 (%3)；最多 %4 秒內持續重新連線 (Ctrl-C 結束)</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="237"/>
        <source>%1 link lost: %2 (%3); reconnecting until it is back (Ctrl-C ends)</source>
        <translation>%1 連線中斷：%2 (%3)；持續重新連線直到恢復 (Ctrl-C 結束)</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="246"/>
        <source>%1 link back after %2 s: %3; monitoring goes on</source>
        <translation>%1 連線已於 %2 秒後恢復：%3；繼續監視</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="261"/>
        <source>error: the link to %1 was lost at %2 and is not back after %3 s (--give-up %4): %5; monitoring stopped</source>
        <translation>錯誤：與 %1 的連線於 %2 中斷，%3 秒後仍未恢復 (--give-up %4)：%5；監視已停止</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="303"/>
        <source>%1 error: %2</source>
        <translation>%1 錯誤：%2</translation>
    </message>
</context>
<context>
    <name>opentop::MonitorCsv</name>
    <message>
        <location filename="../cli/MonitorCsv.cpp" line="33"/>
        <source>link lost</source>
        <translation>連線中斷</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCsv.cpp" line="38"/>
        <source>link back</source>
        <translation>連線恢復</translation>
    </message>
</context>
<context>
    <name>opentop::MonitorDetails</name>
    <message>
        <location filename="../ui/monitor/MonitorDetails.cpp" line="81"/>
        <location filename="../ui/monitor/MonitorDetails.cpp" line="88"/>
        <source>not read</source>
        <translation>未讀取</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorDetails.cpp" line="110"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
</context>
<context>
    <name>opentop::MonitorOutput</name>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="118"/>
        <source>Target shown</source>
        <translation>目標顯示值</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="118"/>
        <source>Speed shown</source>
        <translation>速度顯示值</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="128"/>
        <source>Active alarm</source>
        <translation>發生中的警報</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="170"/>
        <source>none</source>
        <translation>無</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="173"/>
        <source>code %1</source>
        <translation>代碼 %1</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="173"/>
        <source>active</source>
        <translation>發生中</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="180"/>
        <source>Time</source>
        <translation>時間</translation>
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
        <translation>即時值</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="199"/>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="215"/>
        <source>State</source>
        <translation>狀態</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="280"/>
        <source>%1 %2 on the drive&apos;s display</source>
        <translation>驅動器顯示器上為 %1 %2</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="289"/>
        <source>Alarm %1 %2 — %3</source>
        <translation>警報 %1 %2 — %3</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="292"/>
        <source>Alarm active (reading which one…)</source>
        <translation>警報發生中 (正在讀取警報代碼…)</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="347"/>
        <source>No live state: %1</source>
        <translation>無即時狀態：%1</translation>
    </message>
</context>
<context>
    <name>opentop::MonitorPollBar</name>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="30"/>
        <source>Poll every</source>
        <translation>輪詢間隔</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="32"/>
        <source>%1 ms (%2 Hz)</source>
        <translation>%1 ms (%2 Hz)</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="33"/>
        <source>How often every monitored drive is read. Commands you give always go first; the drives share what is left of the bus in turn.</source>
        <translation>每台受監視驅動器的讀取頻率。您下達的指令一律優先；其餘的匯流排時間由各驅動器輪流使用。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="45"/>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="53"/>
        <source>Resume polling</source>
        <translation>恢復輪詢</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="53"/>
        <source>Pause polling</source>
        <translation>暫停輪詢</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="67"/>
        <source>Polling paused: the values shown are the last ones read (%1).</source>
        <translation>輪詢已暫停：顯示的是最後讀取的值 (%1)。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="69"/>
        <source>Polling waits for the bus scan: %1.</source>
        <translation>輪詢正在等候匯流排掃描：%1。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="71"/>
        <source>Connection lost — not live: %1.</source>
        <translation>連線中斷 — 非即時：%1。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="73"/>
        <source>Not live: %1.</source>
        <translation>非即時：%1。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="74"/>
        <source>The drive does not answer (%1) — not live: %2.</source>
        <translation>驅動器無回應 (%1) — 非即時：%2。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="77"/>
        <source>Values %1 · %2 samples/s</source>
        <translation>數值 %1 · %2 次取樣/s</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="81"/>
        <source>Not read yet.</source>
        <translation>尚未讀取。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="82"/>
        <source>Cannot read the drive: %1</source>
        <translation>無法讀取驅動器：%1</translation>
    </message>
</context>
<context>
    <name>opentop::MotionPriorityBox</name>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="34"/>
        <source>Switch to communication priority…</source>
        <translation>切換為通訊優先…</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="59"/>
        <source>Machine number %1 is in &quot;%2&quot; (%3): it takes run, stop, direction and speed selection from its input terminals and refuses motion commands over the bus, so the test run is disabled.

Switching to &quot;%4&quot; hands these commands to the bus: the input terminals no longer start or stop the motor, and the machine&apos;s own controls stay without effect until you switch back to &quot;%2&quot;.</source>
        <translation>機號 %1 處於「%2」(%3)：運轉、停止、方向與速度選擇均來自其輸入端子，並拒絕來自匯流排的運轉指令，因此試運轉已停用。

切換為「%4」會將這些指令交給匯流排：輸入端子將不再能啟動或停止馬達，在您切換回「%2」之前，機台本身的控制均無作用。</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="85"/>
        <source>Switch to communication priority</source>
        <translation>切換為通訊優先</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="86"/>
        <source>Machine number %1 will take run, stop, direction and speed selection from the bus (%2 = &quot;%3&quot;). Its input terminals then no longer start or stop the motor.</source>
        <translation>機號 %1 的運轉、停止、方向與速度選擇將改由匯流排控制 (%2 = &quot;%3&quot;)。之後其輸入端子將不再能啟動或停止馬達。</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="92"/>
        <source>Switch</source>
        <translation>切換</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="101"/>
        <source>Switching to communication priority…</source>
        <translation>正在切換為通訊優先…</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="109"/>
        <source>Machine number %1 takes motion commands over the bus now.</source>
        <translation>機號 %1 現在接受來自匯流排的運轉指令。</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="111"/>
        <source>Cannot switch the control priority: %1</source>
        <translation>無法切換控制優先權：%1</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="121"/>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="127"/>
        <source>Return to I/O priority</source>
        <translation>恢復為 I/O 優先</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="122"/>
        <source>Machine number %1 will take run, stop, direction and speed selection from its input terminals again, and refuse motion commands over the bus. If an input says run, the motor runs.</source>
        <translation>機號 %1 將再次由輸入端子控制運轉、停止、方向與速度選擇，並拒絕來自匯流排的運轉指令。若輸入為運轉狀態，馬達即會運轉。</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="130"/>
        <source>Returning to I/O priority…</source>
        <translation>正在恢復為 I/O 優先…</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="139"/>
        <source>Machine number %1 follows its input terminals again.</source>
        <translation>機號 %1 已恢復由輸入端子控制。</translation>
    </message>
</context>
<context>
    <name>opentop::MotorSpeedBox</name>
    <message>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="23"/>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="49"/>
        <source>Motor speed</source>
        <translation>馬達速度</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="33"/>
        <source>not set</source>
        <translation>未設定</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="34"/>
        <source>Commutations per motor revolution (a motor property, see its data sheet). r/min = %1 ÷ this × 60.</source>
        <translation>馬達每轉的換相次數 (馬達特性，請參閱其規格書)。r/min = %1 ÷ 此值 × 60。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="38"/>
        <source>Commutations per revolution</source>
        <translation>每轉換相次數</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="79"/>
        <source>set the commutations per revolution</source>
        <translation>請設定每轉換相次數</translation>
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
        <translation>全部寫入(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="41"/>
        <source>Write one setting to several drives</source>
        <translation>將一項設定寫入多台驅動器</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="58"/>
        <source>Machine number</source>
        <translation>機號</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="58"/>
        <source>Model</source>
        <translation>型號</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="58"/>
        <source>Current value</source>
        <translation>目前值</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="59"/>
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="77"/>
        <source>Not written: another family (%1)</source>
        <translation>未寫入：不同系列 (%1)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="78"/>
        <source>Not written: not identified (%1)</source>
        <translation>未寫入：無法識別 (%1)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="83"/>
        <source>&amp;Setting:</source>
        <translation>設定(&amp;S)：</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="89"/>
        <source>New &amp;value:</source>
        <translation>新值(&amp;V)：</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="162"/>
        <source>cannot be read</source>
        <translation>無法讀取</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="165"/>
        <source>reading…</source>
        <translation>讀取中…</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="193"/>
        <source>read failed: %1</source>
        <translation>讀取失敗：%1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="218"/>
        <source>Drive %1: %2 is not known yet, and the allowed values depend on it.</source>
        <translation>驅動器 %1：%2 尚未得知，而允許值取決於此項。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="222"/>
        <source>drive %1: %2</source>
        <translation>驅動器 %1：%2</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="228"/>
        <source>The unit differs between the drives (%1); write them one at a time.</source>
        <translation>各驅動器的單位不同 (%1)；請逐台寫入。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="237"/>
        <source>Not allowed on drive %1 (%2): %3</source>
        <translation>驅動器 %1 (%2) 不允許：%3</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="244"/>
        <source>Not allowed on the communication group of drive %1: %2</source>
        <translation>驅動器 %1 的通訊群組不允許：%2</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="249"/>
        <source>None of the selected drives is identified.</source>
        <translation>所選驅動器均未識別。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="263"/>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="315"/>
        <source>Drive %1: %2</source>
        <translation>驅動器 %1：%2</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="266"/>
        <source>Allowed on %1</source>
        <translation>%1 的允許值</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="274"/>
        <source>Warning: %1</source>
        <translation>警告：%1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="275"/>
        <source>Allowed on %1.</source>
        <translation>%1 的允許值。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="323"/>
        <source>Set it on %n drive(s) anyway?</source>
        <translation>
            <numerusform>仍要在 %n 台驅動器上設定嗎？</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="324"/>
        <source>&amp;Set it</source>
        <translation>設定(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="344"/>
        <source>Write %1 to machine number(s) %2</source>
        <translation>將 %1 寫入機號 %2</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="346"/>
        <source>Nothing was written.</source>
        <translation>未寫入任何資料。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="351"/>
        <source>waiting…</source>
        <translation>等待中…</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="353"/>
        <source>Writing %1 to %n drive(s)…</source>
        <translation>
            <numerusform>正在將 %1 寫入 %n 台驅動器…</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="365"/>
        <source>Written and verified on %1 of %n drive(s).</source>
        <translation>
            <numerusform>已於 %n 台驅動器中的 %1 台寫入並驗證。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="374"/>
        <source>writing…</source>
        <translation>寫入中…</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="391"/>
        <source>Written and verified</source>
        <translation>已寫入並驗證</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="393"/>
        <source>Written, not verified: %1</source>
        <translation>已寫入，未確認：%1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="394"/>
        <source>Written, not verified (cannot be read back)</source>
        <translation>已寫入，未驗證 (無法回讀)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="395"/>
        <source>Failed: %1</source>
        <translation>失敗：%1</translation>
    </message>
</context>
<context>
    <name>opentop::NameCommand</name>
    <message>
        <location filename="../cli/NameCommand.cpp" line="39"/>
        <source>Name a machine (&quot;Infeed conveyor 3&quot;) or show the names of the bus</source>
        <translation>為機器命名 (「Infeed conveyor 3」) 或顯示此匯流排的名稱</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="45"/>
        <source>error: name takes a machine number and one name; put a name with spaces in quotes: name 1 &quot;Infeed conveyor 3&quot;</source>
        <translation>錯誤：name 需要一個機號和一個名稱；含空格的名稱請加引號：name 1 &quot;Infeed conveyor 3&quot;</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="53"/>
        <source>error: %1</source>
        <translation>錯誤：%1</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="63"/>
        <source>No machine of this bus has a name yet; give one with: name ID &quot;TEXT&quot;</source>
        <translation>此匯流排的機器尚無名稱；請以下列方式命名：name ID &quot;TEXT&quot;</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="67"/>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="67"/>
        <source>name</source>
        <translation>名稱</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="78"/>
        <source>error: &quot;%1&quot; is not a machine number 1–247</source>
        <translation>錯誤：「%1」不是 1–247 的機號</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="88"/>
        <source>Machine number %1 has no name.</source>
        <translation>機號 %1 沒有名稱。</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="94"/>
        <source>error: %1 Nothing was changed.</source>
        <translation>錯誤：%1 未變更任何內容。</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="107"/>
        <source>Machine number %1 has no name now.</source>
        <translation>機號 %1 現在沒有名稱。</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="108"/>
        <source>%1 is named now; messages, files and scans show it.</source>
        <translation>%1 已命名；訊息、檔案與掃描都會顯示此名稱。</translation>
    </message>
</context>
<context>
    <name>opentop::OutputFile</name>
    <message>
        <location filename="../model/io/OutputFile.cpp" line="24"/>
        <source>cannot write %1: it is a directory; name a file</source>
        <translation>無法寫入 %1：這是資料夾；請指定檔案</translation>
    </message>
    <message>
        <location filename="../model/io/OutputFile.cpp" line="26"/>
        <source>cannot write %1: the folder %2 does not exist</source>
        <translation>無法寫入 %1：資料夾 %2 不存在</translation>
    </message>
    <message>
        <location filename="../model/io/OutputFile.cpp" line="35"/>
        <source>cannot write %1: %2</source>
        <translation>無法寫入 %1：%2</translation>
    </message>
    <message>
        <location filename="../model/io/OutputFile.cpp" line="40"/>
        <source>it is a directory; name a file</source>
        <translation>這是資料夾；請指定檔案</translation>
    </message>
</context>
<context>
    <name>opentop::PanelMirror</name>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="20"/>
        <source>speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="22"/>
        <source>machine number</source>
        <translation>機號</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="24"/>
        <source>running data No.</source>
        <translation>運轉資料編號</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="26"/>
        <source>countdown</source>
        <translation>倒數計時</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="28"/>
        <source>load rate</source>
        <translation>負載率</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="47"/>
        <source>Alarm %1 %2</source>
        <translation>警報 %1 %2</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="48"/>
        <source>Alarm (code not read yet)</source>
        <translation>警報 (尚未讀取代碼)</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="59"/>
        <source>Current speed %1 %2</source>
        <translation>目前速度 %1 %2</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="63"/>
        <source>Current speed: no finite value in %1</source>
        <translation>目前速度：以 %1 表示時無有限值</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="70"/>
        <source>Current speed %1 r/min</source>
        <translation>目前速度 %1 r/min</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="70"/>
        <source>Speed not read</source>
        <translation>尚未讀取速度</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="76"/>
        <source>Machine number %1</source>
        <translation>機號 %1</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="83"/>
        <source>Running data SPno%1</source>
        <translation>運轉資料 SPno%1</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="86"/>
        <source>Running data not read</source>
        <translation>尚未讀取運轉資料</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="96"/>
        <source>Countdown set to %1 d %2 h %3 min %4 s (the drive does not report the time left)</source>
        <translation>倒數計時設定為 %1 d %2 h %3 min %4 s (驅動器不回報剩餘時間)</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="110"/>
        <source>Load rate %1 %</source>
        <translation>負載率 %1 %</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="113"/>
        <source>Load rate not read</source>
        <translation>尚未讀取負載率</translation>
    </message>
</context>
<context>
    <name>opentop::PanelMirrorView</name>
    <message>
        <location filename="../ui/monitor/PanelMirrorView.cpp" line="21"/>
        <source>Drive panel</source>
        <translation>驅動器面板</translation>
    </message>
    <message>
        <location filename="../ui/monitor/PanelMirrorView.cpp" line="51"/>
        <source>Not read yet</source>
        <translation>尚未讀取</translation>
    </message>
    <message>
        <location filename="../ui/monitor/PanelMirrorView.cpp" line="64"/>
        <source>%1 (more digits than the panel has)</source>
        <translation>%1 (位數超過面板可顯示的位數)</translation>
    </message>
    <message>
        <location filename="../ui/monitor/PanelMirrorView.cpp" line="68"/>
        <source>Panel set to show the %1 while running.</source>
        <translation>面板設定為運轉中顯示 %1。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/PanelMirrorView.cpp" line="69"/>
        <source>Drive panel shows %1</source>
        <translation>驅動器面板顯示 %1</translation>
    </message>
    <message>
        <location filename="../ui/monitor/PanelMirrorView.cpp" line="80"/>
        <source>not live</source>
        <translation>非即時</translation>
    </message>
</context>
<context>
    <name>opentop::ParameterField</name>
    <message>
        <location filename="../ui/workspace/ParameterField.cpp" line="217"/>
        <source>%1 (not valid now)</source>
        <translation>%1 (目前無效)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterField.cpp" line="246"/>
        <source>not read</source>
        <translation>未讀取</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterField.cpp" line="255"/>
        <source>Allowed: %1</source>
        <translation>允許值：%1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterField.cpp" line="258"/>
        <source>On the drive: %1</source>
        <translation>驅動器中：%1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterField.cpp" line="289"/>
        <source>Not accepted: %1</source>
        <translation>不接受：%1</translation>
    </message>
</context>
<context>
    <name>opentop::ParameterInitBox</name>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="40"/>
        <source>Parameter initialisation</source>
        <translation>參數初始化</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="50"/>
        <source>Returns every setting of drive %1 to its factory default, including the communication settings: afterwards the drive may answer only at the default rate, and control priority goes back to its input terminals. The motor must be stopped. The consequences for this drive are listed before anything is sent.</source>
        <translation>將驅動器 %1 的所有設定恢復為出廠預設值，包括通訊設定：之後驅動器可能只以預設鮑率回應，且控制優先權會回到輸入端子。馬達必須停止。送出任何資料前，會先列出對此驅動器的影響。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="58"/>
        <source>&amp;Initialise all parameters of drive %1…</source>
        <translation>初始化驅動器 %1 的所有參數(&amp;I)…</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="60"/>
        <source>Asks first, naming the drive and what changes</source>
        <translation>會先詢問，並列出驅動器及變更內容</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="88"/>
        <source>Reading what the initialisation would change…</source>
        <translation>正在讀取初始化將變更的內容…</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="112"/>
        <source>Afterwards:</source>
        <translation>之後：</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="117"/>
        <source>Your %n unwritten edit(s) of this drive are discarded.</source>
        <translation>
            <numerusform>此驅動器 %n 項未寫入的變更將被捨棄。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="123"/>
        <source>Sent: %1 to machine %2 only.</source>
        <translation>已送出：%1，僅送往機號 %2。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="124"/>
        <source>Sent: %1 to machine %2.</source>
        <translation>已送出：%1 至機號 %2。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="128"/>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="133"/>
        <source>Initialise drive %1</source>
        <translation>初始化驅動器 %1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="129"/>
        <source>Reset every setting of %1 to its factory defaults?</source>
        <translation>要將 %1 的所有設定恢復為出廠預設值嗎？</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="143"/>
        <source>Cancelled; nothing was sent.</source>
        <translation>已取消；未送出任何資料。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="151"/>
        <source>Initialising drive %1…</source>
        <translation>正在初始化驅動器 %1…</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="160"/>
        <source>Drive %1 did not confirm the initialisation: %2</source>
        <translation>驅動器 %1 未確認初始化：%2</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="161"/>
        <source>Nothing was sent: %1</source>
        <translation>未送出任何資料：%1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="174"/>
        <source>&amp;Reconnect at %1 bit/s after the power-up</source>
        <translation>上電後以 %1 bit/s 重新連線(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="178"/>
        <source>Drive %1 initialised; reading its values again…</source>
        <translation>驅動器 %1 已初始化；正在重新讀取其值…</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="184"/>
        <source>Drive %1 initialised; %n value(s) could not be read back (it may answer only at the default communication settings now).</source>
        <translation>
            <numerusform>驅動器 %1 已初始化；%n 個值無法回讀 (驅動器現在可能只以預設通訊設定回應)。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="188"/>
        <source>Drive %1 initialised to its factory defaults; values read again.</source>
        <translation>驅動器 %1 已初始化為出廠預設值；已重新讀取數值。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="214"/>
        <source>Reconnecting at %1 bit/s in %2 s…</source>
        <translation>%2 s 後以 %1 bit/s 重新連線…</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="227"/>
        <source>Reconnect at %1 bit/s from the Bus menu.</source>
        <translation>請從「匯流排」選單以 %1 bit/s 重新連線。</translation>
    </message>
</context>
<context>
    <name>opentop::ParameterInitialiser</name>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="65"/>
        <source>%1 drives have no parameter initialisation.</source>
        <translation>%1 驅動器沒有參數初始化功能。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="68"/>
        <source>%1 = %2 (register %3)</source>
        <translation>%1 = %2 (暫存器 %3)</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="76"/>
        <source>Drive %1 is running. Stop the motor first: parameter initialisation is only sent to a drive at standstill.</source>
        <translation>驅動器 %1 正在運轉。請先停止馬達：參數初始化只會送往靜止中的驅動器。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="80"/>
        <source>Whether drive %1 is running could not be read (%2), so nothing was sent.</source>
        <translation>無法讀取驅動器 %1 是否運轉 (%2)，因此未送出任何資料。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="94"/>
        <source>Every setting of drive %1 returns to its factory default: %2. Values set for this machine are lost; save a backup first to keep them.</source>
        <translation>驅動器 %1 的所有設定將恢復為出廠預設值：%2。為此機台設定的值將遺失；若要保留，請先儲存備份。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="111"/>
        <source>%1 could not be read; it returns to %2. %3</source>
        <translation>無法讀取 %1；將恢復為 %2。%3</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="114"/>
        <source>%1 goes from %2 back to %3. %4</source>
        <translation>%1 由 %2 恢復為 %3。%4</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="119"/>
        <source>%1 stays %2 (already the default).</source>
        <translation>%1 維持 %2 (已是預設值)。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="123"/>
        <source>%1 bit/s, parity %2, %3 stop bit(s)</source>
        <translation>%1 bit/s，同位元 %2，%3 個停止位元</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="131"/>
        <source>The link to the drive is lost from its next power-up: it answers only at the factory line settings, %1.</source>
        <translation>自下次上電起將失去與驅動器的連線：驅動器只以出廠通訊設定 %1 回應。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="142"/>
        <source>To reach drive %1 again: switch it off and on, wait %2 s after power-on, then reconnect at %3.</source>
        <translation>若要再次連上驅動器 %1：請將其斷電再上電，上電後等待 %2 s，然後以 %3 重新連線。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="159"/>
        <source>Bus control is lost: the drive follows its input terminals again and refuses start, stop and speed commands over the bus; an input that is on may start the motor, with the factory input functions.</source>
        <translation>將失去匯流排控制：驅動器將再次由輸入端子控制，並拒絕經由匯流排的啟動、停止與速度指令；依出廠輸入功能，處於 ON 的輸入可能使馬達啟動。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="168"/>
        <source>To control the motor over the bus again, set %1 to %2.</source>
        <translation>若要再次透過匯流排控制馬達，請將 %1 設為 %2。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="150"/>
        <source>The drive no longer follows writes sent to its group&apos;s parent, and drives that followed it no longer do.</source>
        <translation>此驅動器將不再跟隨送往其群組母站的寫入，原本跟隨它的驅動器也不再跟隨。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="173"/>
        <source>The machine number %1 is not a setting and does not change.</source>
        <translation>機號 %1 不屬於設定，不會變更。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="175"/>
        <source>The motor must stand still: drive %1 reports it stopped now, and this is read again just before the command is sent.</source>
        <translation>馬達必須靜止：驅動器 %1 目前回報已停止，送出指令前會再讀取一次。</translation>
    </message>
</context>
<context>
    <name>opentop::ParameterPage</name>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="26"/>
        <location filename="../ui/workspace/ParameterPage.cpp" line="149"/>
        <source>&amp;Write page</source>
        <translation>寫入本頁(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="27"/>
        <source>Re&amp;vert</source>
        <translation>復原(&amp;V)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="28"/>
        <source>Re-&amp;read</source>
        <translation>重新讀取(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="48"/>
        <source>Write this page&apos;s pending edits to the drive and verify them by reading back</source>
        <translation>將本頁的待寫入變更寫入驅動器，並以回讀驗證</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="49"/>
        <source>Discard this page&apos;s pending edits</source>
        <translation>捨棄本頁的待寫入變更</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="50"/>
        <source>Read this page&apos;s values from the drive again (edits stay)</source>
        <translation>從驅動器重新讀取本頁的值 (變更會保留)</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterPage.cpp" line="137"/>
        <source>Every field is accepted now. Nothing has been written yet: Write page sends %n value(s).</source>
        <translation>
            <numerusform>所有欄位現已接受。尚未寫入任何值：「寫入此頁」將送出 %n 個值。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="150"/>
        <source>&amp;Write page (%1)</source>
        <translation>寫入本頁 (%1)(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="163"/>
        <source>Reading…</source>
        <translation>讀取中…</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterPage.cpp" line="167"/>
        <source>%n value(s) could not be read</source>
        <translation>
            <numerusform>%n 個值無法讀取</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterPage.cpp" line="116"/>
        <source>Nothing was written: %n field(s) not accepted. %1</source>
        <translation>
            <numerusform>未寫入任何資料：%n 個欄位不接受。%1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterPage.cpp" line="208"/>
        <source>Write %n value(s) of the page %1 to machine number %2</source>
        <translation>
            <numerusform>將頁面「%1」的 %n 個值寫入機號 %2</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="182"/>
        <location filename="../ui/workspace/ParameterPage.cpp" line="203"/>
        <location filename="../ui/workspace/ParameterPage.cpp" line="212"/>
        <source>Nothing was written.</source>
        <translation>未寫入任何資料。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterPage.cpp" line="217"/>
        <source>Writing %n value(s)…</source>
        <translation>
            <numerusform>正在寫入 %n 個值…</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::ParameterReader</name>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="55"/>
        <source>entry</source>
        <translation>項目</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="63"/>
        <source>name must be lower-case dotted words: [a-z0-9_] separated by dots</source>
        <translation>name 必須是以點分隔的小寫字詞：[a-z0-9_] 以點分隔</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="72"/>
        <source>&quot;label&quot; is empty</source>
        <translation>&quot;label&quot; 為空</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="74"/>
        <source>group &quot;%1&quot; is not declared in &quot;groups&quot;</source>
        <translation>group &quot;%1&quot; 未在 &quot;groups&quot; 中宣告</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="76"/>
        <source>kind must be one of %1</source>
        <translation>kind 必須是 %1 其中之一</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="82"/>
        <source>address must be 0x0000–0xFFFF</source>
        <translation>address 必須為 0x0000–0xFFFF</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="89"/>
        <source>read must be 3 (holding) or 4 (input)</source>
        <translation>read 必須為 3 (holding) 或 4 (input)</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="91"/>
        <source>write must be 6 or 16</source>
        <translation>write 必須為 6 或 16</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="95"/>
        <source>input registers (read 4) cannot be written</source>
        <translation>input 暫存器 (read 4) 無法寫入</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="97"/>
        <source>neither readable nor writable</source>
        <translation>既不可讀取也不可寫入</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="105"/>
        <source>type must be u16, s16, u32, s32, f32, string or bits</source>
        <translation>type 必須為 u16、s16、u32、s32、f32、string 或 bits</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="114"/>
        <source>string parameters need &quot;count&quot; 1–125 registers</source>
        <translation>string 參數需要 &quot;count&quot; 為 1–125 個暫存器</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="119"/>
        <source>bits parameters have &quot;count&quot; 1 or 2</source>
        <translation>bits 參數的 &quot;count&quot; 為 1 或 2</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="124"/>
        <source>%1 takes %2 register(s), not %3</source>
        <translation>%1 佔用 %2 個暫存器，而非 %3 個</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="129"/>
        <source>&quot;wordOrder&quot; is for 2-register numbers and bit fields only</source>
        <translation>&quot;wordOrder&quot; 僅適用於 2 暫存器數值與位元欄位</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="133"/>
        <source>&quot;wordOrder&quot; must be &quot;high-first&quot; or &quot;low-first&quot;</source>
        <translation>&quot;wordOrder&quot; 必須為 &quot;high-first&quot; 或 &quot;low-first&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="136"/>
        <source>a %1-register value cannot be written with function 06; use 16</source>
        <translation>%1 個暫存器的值無法以功能碼 06 寫入；請使用 16</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="141"/>
        <source>safety must be one of %1</source>
        <translation>safety 必須是 %1 其中之一</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="143"/>
        <source>commands need a &quot;safety&quot; class</source>
        <translation>指令需要 &quot;safety&quot; 類別</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="146"/>
        <source>code table &quot;%1&quot; is not declared</source>
        <translation>代碼表 &quot;%1&quot; 未宣告</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="157"/>
        <source>a setting needs &quot;allowed&quot; or &quot;enum&quot;</source>
        <translation>設定需要 &quot;allowed&quot; 或 &quot;enum&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="160"/>
        <source>a writable parameter needs &quot;allowed&quot; or &quot;enum&quot;</source>
        <translation>可寫入的參數需要 &quot;allowed&quot; 或 &quot;enum&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="165"/>
        <source>bits parameters need &quot;bits&quot;</source>
        <translation>bits 參數需要 &quot;bits&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="173"/>
        <source>&quot;backup&quot; must be true or false</source>
        <translation>&quot;backup&quot; 必須為 true 或 false</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="178"/>
        <source>only readable and writable parameters can be backed up</source>
        <translation>只有可讀寫的參數能夠備份</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="191"/>
        <source>%1 needs &quot;address&quot; and &quot;count&quot;</source>
        <translation>%1 需要 &quot;address&quot; 與 &quot;count&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="193"/>
        <source>%1: the parameter is not writable</source>
        <translation>%1：此參數不可寫入</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="196"/>
        <source>%1: address 0x0000–0xFFFF and count 1–%2 (limits.maxWriteRegisters)</source>
        <translation>%1：address 須為 0x0000–0xFFFF，count 須為 1–%2 (limits.maxWriteRegisters)</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="205"/>
        <source>%1: tail values are registers, 0–65535</source>
        <translation>%1：tail 的值為暫存器值，0–65535</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="213"/>
        <source>%1: the parameter&apos;s registers must lie in the block, before its tail</source>
        <translation>%1：參數的暫存器必須位於區塊內、tail 之前</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="221"/>
        <source>scale must be positive</source>
        <translation>scale 必須為正數</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="233"/>
        <source>decimals must be 0–9</source>
        <translation>decimals 必須為 0–9</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="257"/>
        <source>recommended[%1] is not inside one of the &quot;allowed&quot; intervals</source>
        <translation>recommended[%1] 不在任何 &quot;allowed&quot; 區間內</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="275"/>
        <source>default %1 is not a whole number of steps of %2</source>
        <translation>預設值 %1 不是 %2 的整數倍</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="284"/>
        <source>default must be a number (or &quot;0x...&quot; code)</source>
        <translation>預設值必須是數字 (或 &quot;0x...&quot; 代碼)</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="287"/>
        <source>default must be a number or a string</source>
        <translation>預設值必須是數字或字串</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="298"/>
        <source>%1 must be an object {&quot;min&quot;:…, &quot;max&quot;:…}</source>
        <translation>%1 必須是物件 {&quot;min&quot;:…, &quot;max&quot;:…}</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="305"/>
        <source>%1 needs numeric min and max</source>
        <translation>%1 需要數值型的 min 與 max</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="311"/>
        <source>%1: %2 is not a whole number of steps of %3</source>
        <translation>%1：%2 不是 %3 的整數倍</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="319"/>
        <source>%1: min is greater than max</source>
        <translation>%1：min 大於 max</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="333"/>
        <source>%1 must be an object {&quot;value&quot;:…, &quot;label&quot;:…}</source>
        <translation>%1 必須是物件 {&quot;value&quot;:…, &quot;label&quot;:…}</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="349"/>
        <source>%1 has no label</source>
        <translation>%1 沒有 label</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="351"/>
        <source>%1 repeats a code or label</source>
        <translation>%1 有重複的代碼或 label</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="362"/>
        <source>&quot;bits&quot; only belongs to type bits</source>
        <translation>&quot;bits&quot; 只適用於 type bits</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="386"/>
        <source>%1.appliesWhen needs &quot;param&quot; and &quot;equals&quot;</source>
        <translation>%1.appliesWhen 需要 &quot;param&quot; 與 &quot;equals&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="391"/>
        <source>%1 lies outside the %2-bit register</source>
        <translation>%1 超出 %2 位元暫存器的範圍</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="393"/>
        <source>%1 needs a unique name</source>
        <translation>%1 需要唯一的名稱</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="407"/>
        <source>%1 must be an object</source>
        <translation>%1 必須是物件</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="419"/>
        <source>%1 needs either &quot;variant&quot; or &quot;param&quot;</source>
        <translation>%1 需要 &quot;variant&quot; 或 &quot;param&quot; 其中之一</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="422"/>
        <source>%1: variant &quot;%2&quot; is not declared</source>
        <translation>%1：variant &quot;%2&quot; 未宣告</translation>
    </message>
</context>
<context>
    <name>opentop::ParamsCommand</name>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="82"/>
        <source>List every parameter of the device profiles</source>
        <translation>列出定義檔中的所有參數</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="162"/>
        <source>error: params takes no arguments; use --family F</source>
        <translation>錯誤：params 不接受引數；請使用 --family F</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="170"/>
        <source>error: unknown family &quot;%1&quot;; known: %2</source>
        <translation>錯誤：未知系列 &quot;%1&quot;；已知：%2</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="192"/>
        <source>Name</source>
        <translation>名稱</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="192"/>
        <source>Label</source>
        <translation>標籤</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="192"/>
        <source>Address</source>
        <translation>位址</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="192"/>
        <source>FC</source>
        <translation>FC</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="192"/>
        <source>Type</source>
        <translation>類型</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="192"/>
        <source>Unit</source>
        <translation>單位</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="193"/>
        <source>Allowed</source>
        <translation>允許值</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="193"/>
        <source>Default</source>
        <translation>預設值</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="193"/>
        <source>Access</source>
        <translation>存取</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="193"/>
        <source>Group</source>
        <translation>群組</translation>
    </message>
</context>
<context>
    <name>opentop::PasswordHash</name>
    <message>
        <location filename="../model/access/PasswordHash.cpp" line="52"/>
        <source>a password needs at least %1 characters</source>
        <translation>密碼至少需要 %1 個字元</translation>
    </message>
</context>
<context>
    <name>opentop::PidGains</name>
    <message>
        <location filename="../model/tuning/PidGains.cpp" line="9"/>
        <source>P %1, I %2, D %3, D period %4 ms</source>
        <translation>P %1，I %2，D %3，D 週期 %4 ms</translation>
    </message>
</context>
<context>
    <name>opentop::PlantModel</name>
    <message>
        <location filename="../model/tuning/PlantModel.cpp" line="18"/>
        <source>the relay test gives no usable model (K·Ku = %1, Tu = %2 ms)</source>
        <translation>繼電器測試無法得出可用的模型 (K·Ku = %1，Tu = %2 ms)</translation>
    </message>
</context>
<context>
    <name>opentop::PortsCommand</name>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="16"/>
        <source>List serial ports and USB adapters</source>
        <translation>列出序列埠與 USB 轉接器</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="23"/>
        <source>error: ports takes no arguments</source>
        <translation>錯誤：ports 不接受引數</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="43"/>
        <source>No serial ports found.</source>
        <translation>找不到序列埠。</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="47"/>
        <source>Port</source>
        <translation>連接埠</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="48"/>
        <source>Adapter</source>
        <translation>轉接器</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="49"/>
        <source>Manufacturer</source>
        <translation>製造商</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="50"/>
        <source>Serial no.</source>
        <translation>序號</translation>
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
        <translation>%1 不是探測記錄檔 (%2)：已忽略；先前中斷的探測可能在驅動器上留下了探測值</translation>
    </message>
    <message>
        <location filename="../model/session/ProbeJournal.cpp" line="42"/>
        <source>cannot create the folder of %1</source>
        <translation>無法建立 %1 的資料夾</translation>
    </message>
    <message>
        <location filename="../model/session/ProbeJournal.cpp" line="78"/>
        <location filename="../model/session/ProbeJournal.cpp" line="92"/>
        <source>%1 is locked by another program</source>
        <translation>%1 已被其他程式鎖定</translation>
    </message>
</context>
<context>
    <name>opentop::ProductionMode</name>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="39"/>
        <source>&amp;Production mode (end of line)</source>
        <translation>生產模式 (終檢)(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="42"/>
        <source>The operator screen of an end-of-line station; no parameter editing until you switch back (Ctrl+Shift+P)</source>
        <translation>終檢工站的作業員畫面；切換回來之前無法編輯參數 (Ctrl+Shift+P)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="45"/>
        <source>&amp;Full screen</source>
        <translation>全螢幕(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="54"/>
        <source>&amp;Station name…</source>
        <translation>工作站名稱(&amp;S)…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="55"/>
        <source>The name this end-of-line station records with every unit</source>
        <translation>本出廠檢測站記錄在每個單元上的名稱</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="64"/>
        <source>%1

No unit can be tested until results can be recorded. The station tries again by itself.</source>
        <translation>%1

可記錄結果之前，無法測試任何產品。工作站會自動重試。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="83"/>
        <location filename="../ui/eol/ProductionMode.cpp" line="91"/>
        <source>Station name</source>
        <translation>工作站名稱</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="84"/>
        <source>The name this station records with every unit (each station of a line needs its own):</source>
        <translation>本工作站記錄在每個單元上的名稱（同一產線的每個工作站需各有其名）：</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="92"/>
        <source>A station needs a name.</source>
        <translation>工作站需要名稱。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="93"/>
        <source>A unit is being tested: change the name once it is finished.</source>
        <translation>正在檢測單元：請在完成後再變更名稱。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="110"/>
        <source>Production mode</source>
        <translation>生產模式</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="111"/>
        <source>A unit is being tested. Cancel it (Esc) or let it finish before switching back to engineering mode.</source>
        <translation>有產品正在測試中。請先取消 (Esc) 或等待測試完成，再切換回工程模式。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="63"/>
        <source>Results database</source>
        <translation>結果資料庫</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="124"/>
        <source>leave production mode</source>
        <translation>離開生產模式</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="171"/>
        <source>A unit is being tested</source>
        <translation>有產品正在測試中</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="172"/>
        <source>Unit %1 is being tested. Cancel it and %2? Its motors are stopped first; the unit is recorded as aborted.</source>
        <translation>產品 %1 正在測試中。要取消測試並%2嗎？會先停止其馬達，並將此產品記錄為已中止。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="184"/>
        <source>cancelled to %1</source>
        <translation>因%1而取消</translation>
    </message>
</context>
<context>
    <name>opentop::ProductionOptions</name>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="32"/>
        <source>Start in production mode (end-of-line station) with this recipe.</source>
        <translation>以此配方啟動生產模式 (終檢工站)。</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="33"/>
        <source>RECIPE</source>
        <translation>RECIPE</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="34"/>
        <source>Per-unit values (CSV by serial number) for production mode.</source>
        <translation>生產模式使用的單台數值 (依序號的 CSV)。</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="34"/>
        <source>CSV</source>
        <translation>CSV</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="36"/>
        <source>Results database for production mode: an SQLite file or postgresql://user@host/db.</source>
        <translation>生產模式的結果資料庫：SQLite 檔或 postgresql://user@host/db。</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="37"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="39"/>
        <source>This station&apos;s name in the results (default: as set in the program, else the computer&apos;s name); not saved.</source>
        <translation>結果中本工作站的名稱（預設：程式中設定的名稱，否則為電腦名稱）；不會儲存。</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="41"/>
        <source>NAME</source>
        <translation>名稱</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="42"/>
        <source>Start full screen.</source>
        <translation>以全螢幕啟動。</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="50"/>
        <source>--units, --results-db and --station go with --production RECIPE</source>
        <translation>--units、--results-db 與 --station 須與 --production RECIPE 一起使用</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="59"/>
        <source>--station needs a name</source>
        <translation>--station 需要名稱</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="64"/>
        <source>%1 cannot be run:
  %2</source>
        <translation>%1 無法執行：
  %2</translation>
    </message>
</context>
<context>
    <name>opentop::ProductionView</name>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="56"/>
        <source>Open recipe…</source>
        <translation>開啟配方…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="57"/>
        <source>Per-unit values…</source>
        <translation>單台數值…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="63"/>
        <source>Recipe:</source>
        <translation>配方：</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="84"/>
        <source>Drive</source>
        <translation>驅動器</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="84"/>
        <source>Now</source>
        <translation>目前</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="161"/>
        <source>Unit %1: %2…</source>
        <translation>產品 %1：%2…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="195"/>
        <source>Recipe not usable</source>
        <translation>配方無法使用</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="196"/>
        <source>%1 cannot be run; nothing will be sent:

%2</source>
        <translation>%1 無法執行；不會送出任何資料：

%2</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="217"/>
        <source>open another recipe</source>
        <translation>開啟其他配方</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="220"/>
        <source>Open recipe</source>
        <translation>開啟配方</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="220"/>
        <source>Recipes (*.json)</source>
        <translation>配方 (*.json)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="228"/>
        <location filename="../ui/eol/ProductionView.cpp" line="234"/>
        <source>Per-unit values</source>
        <translation>單台數值</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="229"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV 檔 (*.csv)</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/eol/ProductionView.cpp" line="242"/>
        <source>&lt;b&gt;%1&lt;/b&gt; rev. %2 — %n drive(s)</source>
        <translation>
            <numerusform>&lt;b&gt;%1&lt;/b&gt; 版次 %2 — %n 台驅動器</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="246"/>
        <source>&lt;i&gt;none: open the product&apos;s recipe&lt;/i&gt;</source>
        <translation>&lt;i&gt;無：請開啟產品的配方&lt;/i&gt;</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="247"/>
        <source>Station %1 · results: %2 · per-unit values: %3</source>
        <translation>工站 %1 · 結果：%2 · 單台數值：%3</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="250"/>
        <source>loaded</source>
        <translation>已載入</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="250"/>
        <source>none</source>
        <translation>無</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="118"/>
        <source>Unit %1: making the station&apos;s drives safe first…</source>
        <translation>單元 %1：先使工作站的驅動器進入安全狀態…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="287"/>
        <source>drive %1</source>
        <translation>驅動器 %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="288"/>
        <source>drive %1 (%2)</source>
        <translation>驅動器 %1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="289"/>
        <source>waiting</source>
        <translation>等待中</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="294"/>
        <source>Unit %1 — attempt %2</source>
        <translation>產品 %1 — 第 %2 次</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="316"/>
        <source>Kept on this station: the results server did not answer. It is sent by itself when the server answers.</source>
        <translation>已保存在本工作站：結果伺服器沒有回應。伺服器回應後會自動送出。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="361"/>
        <source>%1
Recorded at %2, after the results database came back.</source>
        <translation>%1
結果資料庫恢復後，已於 %2 記錄。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="161"/>
        <location filename="../ui/eol/ProductionView.cpp" line="295"/>
        <location filename="../ui/eol/ProductionView.cpp" line="314"/>
        <location filename="../ui/eol/ProductionView.cpp" line="362"/>
        <source>Unit %1</source>
        <translation>產品 %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="341"/>
        <source>Unit %1 ended %2, but its result is not in the results database: %3
Nothing is tested until it is recorded. The station tries again by itself (next try at %4); keep the unit aside.</source>
        <translation>產品 %1 已結束（%2），但結果未寫入結果資料庫：%3
記錄完成前不會進行任何測試。工作站會自動重試（下次 %4）；請將此產品放在一旁。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="322"/>
        <source>Motor not confirmed stopped</source>
        <translation>未確認馬達已停止</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="323"/>
        <source>These motors may still be turning; stop them before touching the unit:

%1</source>
        <translation>以下馬達可能仍在轉動；碰觸產品前請先使其停止：

%1</translation>
    </message>
</context>
<context>
    <name>opentop::ProfileCrossCheck</name>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="49"/>
        <source>%1: storeWith &quot;%2&quot; is not a command parameter</source>
        <translation>%1：storeWith &quot;%2&quot; 不是指令參數</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="52"/>
        <source>%1: the default is not among its allowed values</source>
        <translation>%1：預設值不在允許值之內</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="56"/>
        <source>%1: bit field &quot;%2&quot;: function &quot;%3&quot; is not a readable parameter</source>
        <translation>%1：位元欄位 &quot;%2&quot;：function &quot;%3&quot; 不是可讀取的參數</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="63"/>
        <source>%1: condition on unknown parameter &quot;%2&quot;</source>
        <translation>%1：條件引用了未知參數 &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="65"/>
        <source>%1: the default is not allowed when %2</source>
        <translation>%1：當 %2 時不允許此預設值</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="75"/>
        <source>%1 runs past address 0xFFFF</source>
        <translation>%1 超出位址 0xFFFF</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="78"/>
        <source>%1 overlaps &quot;%2&quot; at 0x%3 (%4 registers)</source>
        <translation>%1 與 &quot;%2&quot; 在 0x%3 重疊 (%4 個暫存器)</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="107"/>
        <source>identify: &quot;%1&quot; must be a parameter inside the identify read</source>
        <translation>identify：&quot;%1&quot; 必須是 identify 讀取範圍內的參數</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="110"/>
        <source>identify.nameMatch is not a valid regular expression</source>
        <translation>identify.nameMatch 不是有效的正規表示式</translation>
    </message>
</context>
<context>
    <name>opentop::ProfileLoader</name>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="345"/>
        <source>not valid JSON at offset %1: %2</source>
        <translation>位移 %1 處不是有效的 JSON：%2</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="349"/>
        <source>the top level must be a JSON object</source>
        <translation>最上層必須是 JSON 物件</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="360"/>
        <source>&quot;parameters&quot; is empty</source>
        <translation>&quot;parameters&quot; 為空</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="371"/>
        <source>must be an object</source>
        <translation>必須是物件</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="373"/>
        <source>name repeated</source>
        <translation>名稱重複</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="384"/>
        <source>texts: {setting:…} names no parameter (%1)</source>
        <translation>texts：{setting:…} 所指的參數不存在 (%1)</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="393"/>
        <source>%1: cannot open: %2</source>
        <translation>%1：無法開啟：%2</translation>
    </message>
</context>
<context>
    <name>opentop::ProfileTranslation</name>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="79"/>
        <source>%1 is larger than %2 MB, the most a profile translation may hold</source>
        <translation>%1 大於 %2 MB，即定義檔翻譯的上限</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="97"/>
        <source>larger than %1 MB, the most a profile translation may hold</source>
        <translation>大於 %1 MB，即定義檔翻譯的上限</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="102"/>
        <source>not valid JSON at offset %1: %2</source>
        <translation>位移 %1 處不是有效的 JSON：%2</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="106"/>
        <source>the top level must be a JSON object</source>
        <translation>最上層必須是 JSON 物件</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="109"/>
        <source>&quot;format&quot; must be &quot;%1&quot;</source>
        <translation>&quot;format&quot; 必須是 &quot;%1&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="112"/>
        <source>&quot;formatVersion&quot; must be %1</source>
        <translation>&quot;formatVersion&quot; 必須是 %1</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="118"/>
        <source>&quot;family&quot; is &quot;%1&quot;, but the profile is &quot;%2&quot;</source>
        <translation>&quot;family&quot; 是 &quot;%1&quot;，但定義檔是 &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="120"/>
        <source>&quot;language&quot; is &quot;%1&quot;, expected &quot;%2&quot;</source>
        <translation>&quot;language&quot; 是 &quot;%1&quot;，應為 &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="123"/>
        <source>&quot;texts&quot; must be an object of key → text</source>
        <translation>&quot;texts&quot; 必須是 鍵 → 文字 的物件</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="127"/>
        <source>texts &quot;%1&quot; must be a non-empty string</source>
        <translation>texts &quot;%1&quot; 必須是非空字串</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="144"/>
        <source>%1 key(s) of the profile missing: %2</source>
        <translation>缺少定義檔的 %1 個鍵：%2</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="148"/>
        <source>%1 key(s) the profile does not have: %2</source>
        <translation>%1 個鍵不屬於此定義檔：%2</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="156"/>
        <source>texts &quot;%1&quot;: the panel codes must stay as in the English (%2), found (%3)</source>
        <translation>texts &quot;%1&quot;：面板代碼必須與英文相同（%2），實際為（%3）</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="161"/>
        <source>texts &quot;%1&quot;: the placeholders must stay as in the English (%2), found (%3)</source>
        <translation>texts &quot;%1&quot;：預留位置必須與英文相同（%2），實際為（%3）</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="168"/>
        <source>texts &quot;%1&quot;: the settings named ({setting:…}) must stay as in the English (%2), found (%3)</source>
        <translation>texts &quot;%1&quot;：所指的設定 ({setting:…}) 必須與英文相同 (%2)，實際為 (%3)</translation>
    </message>
</context>
<context>
    <name>opentop::ProposalFlow</name>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="57"/>
        <source>Proposal rejected; the drive&apos;s gains were not changed.</source>
        <translation>已拒絕建議值；驅動器的增益未變更。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="60"/>
        <source>Proposal rejected</source>
        <translation>已拒絕建議值</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="71"/>
        <source>The accepted gains failed the check: %1. Reject them, or store them only after looking at the step.</source>
        <translation>已接受的增益未通過檢查：%1。請拒絕，或先查看步階後再保存。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="85"/>
        <source>no step test ran after Accept</source>
        <translation>接受後未執行步階測試</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="87"/>
        <source>Store gains that failed the check?</source>
        <translation>要保存未通過檢查的增益嗎？</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="88"/>
        <source>The gains accepted on %1 did not pass the check after Accept.</source>
        <translation>在 %1 接受的增益未通過接受後的檢查。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="90"/>
        <source>Stored, they stay after a power cycle and the motor may oscillate or overshoot as measured. Reject writes back the gains the drive had.</source>
        <translation>保存後斷電重新上電仍會保留，馬達可能如實測般振盪或超調。按「拒絕」會寫回驅動器原本的增益。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="95"/>
        <source>Reject the gains</source>
        <translation>拒絕此增益</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="96"/>
        <source>Store anyway</source>
        <translation>仍要保存</translation>
    </message>
</context>
<context>
    <name>opentop::PtySimServer</name>
    <message>
        <location filename="../sim/PtySimServer.cpp" line="66"/>
        <source>cannot open a pseudo-terminal: %1</source>
        <translation>無法開啟虛擬終端機：%1</translation>
    </message>
    <message>
        <location filename="../sim/PtySimServer.cpp" line="112"/>
        <source>%1 is in use by another simulator (PID %2); stop it first, or choose another path for --pty</source>
        <translation>%1 正由另一個模擬器（PID %2）使用中；請先停止它，或為 --pty 選擇其他路徑</translation>
    </message>
    <message>
        <location filename="../sim/PtySimServer.cpp" line="121"/>
        <source>cannot create the lock file %1: %2</source>
        <translation>無法建立鎖定檔 %1：%2</translation>
    </message>
    <message>
        <location filename="../sim/PtySimServer.cpp" line="80"/>
        <source>%1 exists and is not a symlink; refusing to replace it</source>
        <translation>%1 已存在且不是符號連結；拒絕取代</translation>
    </message>
    <message>
        <location filename="../sim/PtySimServer.cpp" line="83"/>
        <source>cannot create the symlink %1 -&gt; %2</source>
        <translation>無法建立符號連結 %1 -&gt; %2</translation>
    </message>
    <message>
        <location filename="../sim/PtySimServer.cpp" line="162"/>
        <source>the port is plugged in: %1</source>
        <translation>連接埠已接上：%1</translation>
    </message>
    <message>
        <location filename="../sim/PtySimServer_win.cpp" line="29"/>
        <source>a simulated serial line needs a pseudo-terminal, which Windows does not have: serve Modbus TCP with --tcp PORT (e.g. --tcp 5020) and connect with --tcp 127.0.0.1:5020</source>
        <translation>模擬的串列線路需要虛擬終端機，而 Windows 沒有：請以 --tcp PORT（例如 --tcp 5020）提供 Modbus TCP，並以 --tcp 127.0.0.1:5020 連線</translation>
    </message>
</context>
<context>
    <name>opentop::ReachedDrives</name>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="47"/>
        <source>%1, variant not known</source>
        <translation>%1，機型不明</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="62"/>
        <source>machine number %1 (%2) executes this write too (communication group %3), but has no such setting at 0x%4</source>
        <translation>機號 %1 (%2) 也會執行此寫入 (通訊群組 %3)，但在 0x%4 沒有這個設定</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="86"/>
        <source>machine number %1 (%2) executes this write too (communication group %3) and does not allow it: %4</source>
        <translation>機號 %1 (%2) 也會執行此寫入 (通訊群組 %3)，但不允許此值：%4</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="95"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="110"/>
        <source>%1 cannot be checked: %2</source>
        <translation>無法檢查 %1：%2</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="150"/>
        <source>verification failed in communication group %1: %2</source>
        <translation>通訊群組 %1 的確認失敗：%2</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="209"/>
        <source>reading %1 of machine number %2, which executes this write too, failed: %3</source>
        <translation>讀取機號 %2 (也會執行此寫入) 的 %1 失敗：%3</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="245"/>
        <source>machine number %1: not verified (the setting cannot be read there)</source>
        <translation>機號 %1：未確認 (該設定無法在此驅動器上讀取)</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="258"/>
        <source>machine number %1: not verified, reading it back failed: %2</source>
        <translation>機號 %1：未確認，讀回失敗：%2</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="260"/>
        <source>the drive was removed</source>
        <translation>驅動器已移除</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="273"/>
        <source>machine number %1 holds %2</source>
        <translation>機號 %1 的值為 %2</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="274"/>
        <source>machine number %1 holds %2, not %3</source>
        <translation>機號 %1 的值為 %2，不是 %3</translation>
    </message>
</context>
<context>
    <name>opentop::Recipe</name>
    <message>
        <location filename="../model/eol/Recipe.cpp" line="64"/>
        <source>position %1 (machine number %2)</source>
        <translation>位置 %1 (機號 %2)</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeApprovals</name>
    <message>
        <location filename="../model/access/RecipeApprovals.cpp" line="19"/>
        <source>recipe &quot;%1&quot; rev. %2 is a draft: this version (its checksum) is not approved, so it does not run. An engineer approves it (Approve… in the recipe editor, or opentop-cli eol recipe approve FILE --user NAME).</source>
        <translation>配方「%1」版次 %2 是草稿：此版本（其校驗碼）未經核准，因此不會執行。請工程師核准（配方編輯器中的「核准…」，或 opentop-cli eol recipe approve FILE --user NAME）。</translation>
    </message>
    <message>
        <location filename="../model/access/RecipeApprovals.cpp" line="56"/>
        <source>a recipe without a checksum cannot be approved: sign it first</source>
        <translation>沒有校驗碼的配方無法核准：請先簽署</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeApproveButton</name>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="16"/>
        <source>Approve…</source>
        <translation>核准…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="21"/>
        <source>Approve the saved recipe for the line (an engineer): stations with users run only approved recipes</source>
        <translation>核准已儲存的配方供產線使用（工程師）：有使用者的工站只執行已核准的配方</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="35"/>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="43"/>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="65"/>
        <source>Approve recipe</source>
        <translation>核准配方</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="37"/>
        <source>Save the recipe first: what is approved is the saved file&apos;s checksum.</source>
        <translation>請先儲存配方：核准的是已儲存檔案的校驗碼。</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="39"/>
        <source>%1 cannot be approved: %2</source>
        <translation>%1 無法核准：%2</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="44"/>
        <source>This station has no users: an approval names its approver. Set up users with opentop-cli eol user add.</source>
        <translation>此工站沒有使用者：核准須記名核准人。請以 opentop-cli eol user add 設定使用者。</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="50"/>
        <source>approve %1 rev. %2</source>
        <translation>核准 %1 版次 %2</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="66"/>
        <source>%1 rev. %2 is approved by %3: stations run it.</source>
        <translation>%1 版次 %2 已由 %3 核准：工站可執行。</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeBuilder</name>
    <message>
        <location filename="../model/eol/RecipeBuilder.cpp" line="208"/>
        <source>%1: unknown family &quot;%2&quot;</source>
        <translation>%1：未知系列 &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeBuilder.cpp" line="228"/>
        <source>%1: %2 holds a value the profile does not allow: %3</source>
        <translation>%1：%2 含有定義檔不允許的值：%3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeBuilder.cpp" line="261"/>
        <source>no drive to make a recipe of</source>
        <translation>沒有可用來建立配方的驅動器</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeChecker</name>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="62"/>
        <source> (for %1)</source>
        <translation> (適用於 %1)</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="94"/>
        <source>the recipe names no product</source>
        <translation>配方未指定產品</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="96"/>
        <source>the recipe has no revision</source>
        <translation>配方沒有版次</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="98"/>
        <source>the recipe names no drive</source>
        <translation>配方未指定驅動器</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="111"/>
        <source>%1: machine number %2 is already position %3; every drive of a unit needs its own machine number</source>
        <translation>%1：機號 %2 已用於位置 %3；產品中的每台驅動器都需要各自的機號</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="133"/>
        <source>%1: unknown family &quot;%2&quot;; known: %3</source>
        <translation>%1：未知的系列 &quot;%2&quot;；已知：%3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="139"/>
        <source>%1: a %2 takes machine numbers %3–%4</source>
        <translation>%1：%2 的機號範圍為 %3–%4</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="152"/>
        <source>%1: the %2 has no variant &quot;%3&quot;; known: %4</source>
        <translation>%1：%2 沒有機型 &quot;%3&quot;；已知：%4</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="154"/>
        <source>none</source>
        <translation>無</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="156"/>
        <source>%1: variant &quot;%2&quot; is named twice</source>
        <translation>%1：機型 &quot;%2&quot; 重複指定</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="164"/>
        <source>%1: variantProof &quot;%2&quot; is not known; use &quot;required&quot; or &quot;operator&quot; (or leave it out)</source>
        <translation>%1：variantProof「%2」無法識別；請用 &quot;required&quot; 或 &quot;operator&quot;（或省略）</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="169"/>
        <source>%1: variantProof &quot;operator&quot; needs exactly one allowed variant for the operator to confirm</source>
        <translation>%1：variantProof &quot;operator&quot; 需要剛好一個允許的機型供作業員確認</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="181"/>
        <source>%1: firmware version &quot;%2&quot; is not a version as the drive reports it (major.minor, e.g. &quot;1.5&quot;)</source>
        <translation>%1：韌體版本 &quot;%2&quot; 不是驅動器回報的版本格式 (major.minor，例如 &quot;1.5&quot;)</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="194"/>
        <source>the %1 has no setting &quot;%2&quot;</source>
        <translation>%1 沒有設定 &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="196"/>
        <source>%1 is not a setting a recipe can write</source>
        <translation>%1 不是配方可寫入的設定</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="198"/>
        <source>%1 decides how the drive communicates; a recipe cannot change it, or the station would lose the drive in the middle of the run</source>
        <translation>%1 決定驅動器的通訊方式；配方不能變更此設定，否則工站會在測試途中失去與驅動器的連線</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="218"/>
        <source>%1: setting %2</source>
        <translation>%1：設定 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="223"/>
        <location filename="../model/eol/RecipeChecker.cpp" line="288"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="229"/>
        <source>%1 is given twice</source>
        <translation>%1 重複指定</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="237"/>
        <source>%1: what it allows depends on %2, which the recipe does not set; add %2 to the settings</source>
        <translation>%1：其允許值取決於配方未設定的 %2；請將 %2 加入設定</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="246"/>
        <source>%1 decides what %2 allows; set %2 in the recipe too, or the drive may be left with a value that is no longer valid</source>
        <translation>%1 決定 %2 的允許值；請同時在配方中設定 %2，否則驅動器可能留下已不再有效的值</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="262"/>
        <location filename="../model/eol/RecipeChecker.cpp" line="330"/>
        <source>%1: unit &quot;%2&quot;, but the drive&apos;s value is in &quot;%3&quot;</source>
        <translation>%1：單位為 &quot;%2&quot;，但驅動器的值以 &quot;%3&quot; 表示</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="283"/>
        <location filename="../model/eol/RecipeChecker.cpp" line="385"/>
        <source>%1: per-unit value %2</source>
        <translation>%1：單台數值 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="294"/>
        <source>%1 is given twice (as a setting or as a per-unit value)</source>
        <translation>%1 重複指定 (作為設定或單台數值)</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="300"/>
        <source>%1: the range&apos;s lowest value %2 is above its highest value %3</source>
        <translation>%1：範圍的最小值 %2 大於最大值 %3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="321"/>
        <source>%1: what it allows depends on %2, which the recipe does not set</source>
        <translation>%1：其允許值取決於配方未設定的 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="328"/>
        <source>%1 is not a number; a per-unit value needs a numeric setting</source>
        <translation>%1 不是數值；單台數值需要數值型設定</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="334"/>
        <source>%1: range %2–%3%4</source>
        <translation>%1：範圍 %2–%3%4</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="340"/>
        <source>%1 is outside what the drive allows: %2%3</source>
        <translation>%1 超出驅動器的允許範圍：%2%3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="352"/>
        <source>%1 includes values the drive does not allow; allowed: %2%3</source>
        <translation>%1 包含驅動器不允許的值；允許：%2%3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="378"/>
        <source>%1: per-unit value %2: %3%4 is outside the recipe&apos;s range %5–%6%4</source>
        <translation>%1：單台數值 %2：%3%4 超出配方範圍 %5–%6%4</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="389"/>
        <source>%1: the recipe has no per-unit value %2</source>
        <translation>%1：配方中沒有單台數值 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="392"/>
        <source>the recipe has no drive at machine number %1</source>
        <translation>配方中沒有機號 %1 的驅動器</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeEditor</name>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="40"/>
        <source>Recipe editor</source>
        <translation>配方編輯器</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="61"/>
        <source>Revision:</source>
        <translation>版次：</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="63"/>
        <source>Product:</source>
        <translation>產品：</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="64"/>
        <source>Description:</source>
        <translation>說明：</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="65"/>
        <source>Position:</source>
        <translation>位置：</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="108"/>
        <source>New from drives on the bus…</source>
        <translation>從匯流排上的驅動器新建…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="109"/>
        <source>New from backup file…</source>
        <translation>從備份檔新建…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="110"/>
        <source>Open…</source>
        <translation>開啟…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="111"/>
        <source>Save</source>
        <translation>儲存</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="112"/>
        <source>Save as…</source>
        <translation>另存新檔…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="160"/>
        <source>%1: %2%3</source>
        <translation>%1：%2%3</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="163"/>
        <source> — %1</source>
        <translation> — %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="234"/>
        <source>Make a recipe from a golden unit&apos;s drives on the bus or its backup file, or open one.</source>
        <translation>由標準樣品在匯流排上的驅動器或其備份檔建立配方，或開啟既有配方。</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="238"/>
        <source>the recipe is empty</source>
        <translation>配方為空</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="249"/>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="253"/>
        <source>The recipe passes check: it can be saved and run.</source>
        <translation>配方通過檢查：可儲存並執行。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/eol/RecipeEditor.cpp" line="256"/>
        <source>%n problem(s): the recipe cannot be saved until they are fixed.</source>
        <translation>
            <numerusform>%n 個問題：修正之前無法儲存配方。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/eol/RecipeEditor.cpp" line="268"/>
        <source>the recipe does not pass check (%n problem(s)); nothing was saved</source>
        <translation>
            <numerusform>配方未通過檢查 (%n 個問題)；未儲存任何資料</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="284"/>
        <source>cannot read %1: %2</source>
        <translation>無法讀取 %1：%2</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="296"/>
        <source>%1 is not an OpenTOP recipe file</source>
        <translation>%1 不是 OpenTOP 配方檔</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="303"/>
        <source>Opened %1</source>
        <translation>已開啟 %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="304"/>
        <source>Opened %1, which does not load as it is (%2). Saving checks it and signs it again.</source>
        <translation>已開啟 %1，但無法直接載入 (%2)。儲存時會檢查並重新簽署。</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="325"/>
        <source>Open recipe</source>
        <translation>開啟配方</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="326"/>
        <source>Recipes (*.json);;All files (*)</source>
        <translation>配方 (*.json);;所有檔案 (*)</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="336"/>
        <source>Save recipe</source>
        <translation>儲存配方</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="338"/>
        <source>Recipes (*.json)</source>
        <translation>配方 (*.json)</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="343"/>
        <source>Saved and signed: %1</source>
        <translation>已儲存並簽署：%1</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeFile</name>
    <message>
        <location filename="../model/eol/RecipeFile.cpp" line="268"/>
        <source>%1 is larger than %2 MB, the most a recipe file may hold; not a recipe file</source>
        <translation>%1 大於配方檔上限 %2 MB；不是配方檔</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeFile.cpp" line="276"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeFromDrives</name>
    <message>
        <location filename="../model/eol/RecipeFromDrives.cpp" line="66"/>
        <source>machine number %1: %2; give its variant if you know it</source>
        <translation>機號 %1：%2；若知道其機型請指定</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeFromDrives.cpp" line="74"/>
        <source>machine number %1: %2, %3 (%4)</source>
        <translation>機號 %1：%2，%3（%4）</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeFromDrives.cpp" line="113"/>
        <source>Made from a golden unit; variants: %1.</source>
        <translation>由標準機製作；機型：%1。</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeLimitsTable</name>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="33"/>
        <source>Parameter</source>
        <translation>參數</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="33"/>
        <source>Statistic</source>
        <translation>統計量</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="33"/>
        <source>Lower</source>
        <translation>下限</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="33"/>
        <source>Upper</source>
        <translation>上限</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="33"/>
        <source>Unit</source>
        <translation>單位</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="54"/>
        <source>Add limit</source>
        <translation>新增限值</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="55"/>
        <source>Remove limit</source>
        <translation>刪除限值</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="64"/>
        <source>Limits (measured over the hold):</source>
        <translation>限值（於保持期間量測）：</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="78"/>
        <source>(unknown: %1)</source>
        <translation>（未知：%1）</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeParser</name>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="48"/>
        <source>not a JSON file: %1 at byte %2</source>
        <translation>不是 JSON 檔：%1 (第 %2 位元組)</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="52"/>
        <source>not an OpenTOP recipe file: the JSON is not an object</source>
        <translation>不是 OpenTOP 配方檔：JSON 不是物件</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="78"/>
        <source>&quot;positions&quot;: the recipe names no drive</source>
        <translation>&quot;positions&quot;：配方未指定驅動器</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="83"/>
        <source>%1: must be an object</source>
        <translation>%1：必須是物件</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="100"/>
        <source>not an OpenTOP recipe file (&quot;format&quot; is &quot;%1&quot;, not &quot;%2&quot;)</source>
        <translation>不是 OpenTOP 配方檔 (&quot;format&quot; 為 &quot;%1&quot;，而非 &quot;%2&quot;)</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="102"/>
        <source>not an OpenTOP recipe file (no &quot;format&quot;: &quot;%1&quot;)</source>
        <translation>不是 OpenTOP 配方檔 (沒有 &quot;format&quot;: &quot;%1&quot;)</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="107"/>
        <source>&quot;formatVersion&quot; must be a whole number from 1</source>
        <translation>&quot;formatVersion&quot; 必須是 1 以上的整數</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="109"/>
        <source>written by a newer OpenTOP (recipe format version %1); this version reads recipe format version %2</source>
        <translation>由較新版的 OpenTOP 寫入 (配方格式版本 %1)；此版本可讀取配方格式版本 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="115"/>
        <source>the recipe has no checksum (&quot;checksum&quot;: &quot;sha256:…&quot;); it was not written by OpenTOP or was changed afterwards</source>
        <translation>配方沒有檢查碼 (&quot;checksum&quot;: &quot;sha256:…&quot;)；並非由 OpenTOP 寫入，或寫入後曾被修改</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="121"/>
        <source>the recipe was changed after it was written (checksum mismatch); open and save it with OpenTOP to accept the change</source>
        <translation>配方寫入後曾被修改 (檢查碼不符)；請以 OpenTOP 開啟並儲存，以接受此變更</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="138"/>
        <source>%1: &quot;machineNumber&quot; must be a machine number 1–247</source>
        <translation>%1：&quot;machineNumber&quot; 必須是 1–247 的機號</translation>
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
        <translation>%1 (%2)：&quot;value&quot; 必須是數字或文字</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="201"/>
        <source>%1 (%2): &quot;source&quot; must be &quot;csv&quot; or &quot;operator&quot;, not &quot;%3&quot;</source>
        <translation>%1 (%2)：&quot;source&quot; 必須是 &quot;csv&quot; 或 &quot;operator&quot;，而非 &quot;%3&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="214"/>
        <source>%1: unknown step type &quot;%2&quot;; known: %3</source>
        <translation>%1：未知的步驟類型 &quot;%2&quot;；已知：%3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="230"/>
        <source>%1: &quot;spno&quot; must be a running data number such as 2</source>
        <translation>%1：&quot;spno&quot; 必須是運轉資料編號，例如 2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="241"/>
        <source>%1: &quot;direction&quot; must be &quot;cw&quot; or &quot;ccw&quot;</source>
        <translation>%1：&quot;direction&quot; 必須是 &quot;cw&quot; 或 &quot;ccw&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="279"/>
        <source>%1: give either &quot;equals&quot; or limits, not both</source>
        <translation>%1：&quot;equals&quot; 與限值只能擇一</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="285"/>
        <source>%1: unknown step</source>
        <translation>%1：未知步驟</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="301"/>
        <source>%1: &quot;unit&quot; must be a text (&quot;&quot; for a value without a unit)</source>
        <translation>%1：&quot;unit&quot; 必須是文字 (無單位的值請用 &quot;&quot;)</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="304"/>
        <source>%1: a limit needs &quot;lower&quot;, &quot;upper&quot; or both</source>
        <translation>%1：限值需要 &quot;lower&quot;、&quot;upper&quot; 或兩者</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="325"/>
        <source>&quot;retest&quot; must be an object</source>
        <translation>&quot;retest&quot; 必須是物件</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="334"/>
        <source>retest: &quot;maxAttempts&quot; must be a whole number from 0 (no limit) to 100</source>
        <translation>retest：&quot;maxAttempts&quot; 必須是 0 (不限) 到 100 的整數</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="344"/>
        <source>retest: &quot;passedSerial&quot; must be technician, refuse or allow, not &quot;%1&quot;</source>
        <translation>retest：&quot;passedSerial&quot; 必須是 technician、refuse 或 allow，而非 &quot;%1&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="356"/>
        <source>%1: unknown key &quot;%2&quot;; allowed: %3</source>
        <translation>%1：未知的鍵 &quot;%2&quot;；允許：%3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="370"/>
        <source>%1&quot;%2&quot; must be a non-empty text</source>
        <translation>%1&quot;%2&quot; 必須是非空的文字</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="371"/>
        <source>%1&quot;%2&quot; must be a text</source>
        <translation>%1&quot;%2&quot; 必須是文字</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="383"/>
        <source>%1: &quot;%2&quot; must be a list of texts</source>
        <translation>%1：&quot;%2&quot; 必須是文字清單</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="386"/>
        <source>%1: &quot;%2&quot; must be a list of non-empty texts</source>
        <translation>%1：&quot;%2&quot; 必須是非空文字的清單</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="396"/>
        <source>%1: &quot;%2&quot; must be a number</source>
        <translation>%1：&quot;%2&quot; 必須是數字</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="422"/>
        <source>%1&quot;%2&quot; must be a list</source>
        <translation>%1&quot;%2&quot; 必須是清單</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="425"/>
        <source>%1&quot;%2&quot; has %3 entries; at most %4 are allowed</source>
        <translation>%1&quot;%2&quot; 有 %3 個項目；最多允許 %4 個</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="431"/>
        <source>%1&quot;%2&quot;: every entry must be an object</source>
        <translation>%1&quot;%2&quot;：每個項目都必須是物件</translation>
    </message>
</context>
<context>
    <name>opentop::RecipePositionForm</name>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="125"/>
        <source>every variant of the family, e.g. dbu200, dbu400</source>
        <translation>此系列的所有機型，例如 dbu200, dbu400</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="127"/>
        <source>any firmware, e.g. 1.5, 1.6</source>
        <translation>任何韌體，例如 1.5, 1.6</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="129"/>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="131"/>
        <source>Setting</source>
        <translation>設定</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="129"/>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="131"/>
        <source>Name</source>
        <translation>名稱</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="129"/>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="129"/>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="131"/>
        <source>Unit</source>
        <translation>單位</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="131"/>
        <source>Min</source>
        <translation>最小值</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="131"/>
        <source>Max</source>
        <translation>最大值</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="131"/>
        <source>Source</source>
        <translation>來源</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="137"/>
        <source>Add per-unit value…</source>
        <translation>新增單台數值…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="137"/>
        <source>Add setting…</source>
        <translation>新增設定…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="138"/>
        <source>Remove</source>
        <translation>移除</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="151"/>
        <source>Settings</source>
        <translation>設定</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="152"/>
        <source>Per-unit values</source>
        <translation>單台數值</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="153"/>
        <source>Test steps</source>
        <translation>測試步驟</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="156"/>
        <source>Machine number:</source>
        <translation>機號：</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="157"/>
        <source>Name:</source>
        <translation>名稱：</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="158"/>
        <source>Family:</source>
        <translation>系列：</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="159"/>
        <source>Allowed variants:</source>
        <translation>允許的機型：</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="160"/>
        <source>Allowed firmware:</source>
        <translation>允許的韌體：</translation>
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
        <translation>CSV 檔</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="229"/>
        <source>typed by the operator</source>
        <translation>由作業員輸入</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="279"/>
        <source>(unknown: %1)</source>
        <translation>(未知：%1)</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="342"/>
        <source>Add a per-unit value</source>
        <translation>新增單台數值</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="342"/>
        <source>Add a setting</source>
        <translation>新增設定</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="343"/>
        <source>Setting:</source>
        <translation>設定：</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeStepChecker</name>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="22"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="40"/>
        <source>a %1 cannot do this step</source>
        <translation>%1 無法執行此步驟</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="53"/>
        <source>%1, step %2 (%3)</source>
        <translation>%1，步驟 %2 (%3)</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="63"/>
        <source>the drive takes motion commands only with communication priority; put a priority step before it</source>
        <translation>驅動器只在通訊優先時接受運轉指令；請在此之前加入優先權步驟</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="71"/>
        <source>the motor is not running here; put a start step before it</source>
        <translation>此時馬達未運轉；請在此之前加入啟動步驟</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="82"/>
        <source>%1: the steps leave the motor running; end them with a stop step</source>
        <translation>%1：步驟結束後馬達仍在運轉；請以停止步驟結尾</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="92"/>
        <source>%1 %2 s is not sane; give more than 0 s and at most %3 s</source>
        <translation>%1 %2 s 不合理；請指定大於 0 s 且不超過 %3 s 的值</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="105"/>
        <source>unit &quot;%1&quot;, but %2 is measured in &quot;%3&quot;</source>
        <translation>單位為 &quot;%1&quot;，但 %2 以 &quot;%3&quot; 量測</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="129"/>
        <source>the profile&apos;s selection parameter is missing</source>
        <translation>缺少定義檔中的選擇參數</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="131"/>
        <source>running data %1: %2</source>
        <translation>運轉資料 %1：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="146"/>
        <source>what %1 means depends on %2, which the recipe does not set; add it to the settings</source>
        <translation>%1 的意義取決於配方未設定的 %2；請將其加入設定</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="154"/>
        <source>a speed of 0 stops the motor; use a stop step</source>
        <translation>速度 0 會使馬達停止；請使用停止步驟</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="168"/>
        <source>unit &quot;%1&quot;, but with these settings %2 is in &quot;%3&quot;</source>
        <translation>單位為 &quot;%1&quot;，但依這些設定 %2 以 &quot;%3&quot; 表示</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="185"/>
        <source>a %1 does not report its target speed; give the target</source>
        <translation>%1 不回報目標速度；請指定目標值</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="187"/>
        <source>the target speed must be above 0</source>
        <translation>目標速度必須大於 0</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="190"/>
        <source>the tolerance %1 must be above 0 and below the target speed</source>
        <translation>容許誤差 %1 必須大於 0 且小於目標速度</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="194"/>
        <source>the time to reach the speed</source>
        <translation>到達速度時間</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="198"/>
        <source>the hold time</source>
        <translation>保持時間</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="200"/>
        <source>the step measures nothing; give limits</source>
        <translation>此步驟未量測任何項目；請指定限值</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="208"/>
        <source>the margin</source>
        <translation>裕度</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="211"/>
        <source>a %1 has no deceleration time setting to wait for; give the deceleration (0 s when it brakes at once)</source>
        <translation>%1 沒有可等待的減速時間設定；請指定減速時間 (立即煞車時為 0 s)</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="217"/>
        <source>the deceleration time %1 s is not sane; give 0–%2 s</source>
        <translation>減速時間 %1 s 不合理；請指定 0–%2 s</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="232"/>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="274"/>
        <source>the %1 has no readable value &quot;%2&quot;</source>
        <translation>%1 沒有可讀取的值 &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="237"/>
        <source>%1 is not a number</source>
        <translation>%1 不是數字</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="247"/>
        <source>%1: &quot;%2&quot; is not a statistic; use min, mean or max</source>
        <translation>%1：&quot;%2&quot; 不是統計量；請使用 min、mean 或 max</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="254"/>
        <source>%1: the limit&apos;s unit is &quot;%2&quot;, but the value is measured in &quot;%3&quot;</source>
        <translation>%1：限值的單位為 &quot;%2&quot;，但量測值以 &quot;%3&quot; 表示</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="261"/>
        <source>%1: the lower limit %2 %4 is above the upper limit %3 %4</source>
        <translation>%1：下限 %2 %4 大於上限 %3 %4</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="283"/>
        <source>%1 is a number; compare it with lower and upper limits</source>
        <translation>%1 是數值；請以下限與上限比較</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeStepKinds</name>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="29"/>
        <source>take communication priority</source>
        <translation>取得通訊優先</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="32"/>
        <source>select running data</source>
        <translation>選擇運轉資料</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="33"/>
        <source>Running data:</source>
        <translation>運轉資料：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="36"/>
        <source>set the speed command</source>
        <translation>設定速度指令</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="37"/>
        <source>Speed command:</source>
        <translation>速度指令：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="38"/>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="50"/>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="70"/>
        <source>Unit:</source>
        <translation>單位：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="39"/>
        <source>the speed command&apos;s unit</source>
        <translation>速度指令的單位</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="42"/>
        <source>start</source>
        <translation>啟動</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="43"/>
        <source>Direction:</source>
        <translation>旋轉方向：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="46"/>
        <source>wait for speed</source>
        <translation>等待到達速度</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="47"/>
        <source>Target speed:</source>
        <translation>目標速度：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="48"/>
        <source>empty: the drive&apos;s own target speed</source>
        <translation>留空：驅動器本身的目標速度</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="49"/>
        <source>Tolerance (±):</source>
        <translation>容許誤差（±）：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="50"/>
        <source>the speed&apos;s unit</source>
        <translation>速度的單位</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="51"/>
        <source>Within:</source>
        <translation>時限：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="54"/>
        <source>hold and measure</source>
        <translation>保持並量測</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="55"/>
        <source>Duration:</source>
        <translation>保持時間：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="59"/>
        <source>stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="60"/>
        <source>Deceleration time:</source>
        <translation>減速時間：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="61"/>
        <source>empty: the drive&apos;s setting</source>
        <translation>留空：驅動器的設定值</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="62"/>
        <source>Margin:</source>
        <translation>裕度：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="63"/>
        <source>check for alarms and warnings</source>
        <translation>檢查警報與警告</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="66"/>
        <source>read and compare</source>
        <translation>讀取並比較</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="67"/>
        <source>Parameter:</source>
        <translation>參數：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="68"/>
        <source>Lower limit:</source>
        <translation>下限：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="68"/>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="69"/>
        <source>empty: none</source>
        <translation>留空：無</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="69"/>
        <source>Upper limit:</source>
        <translation>上限：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="70"/>
        <source>the value&apos;s unit</source>
        <translation>數值的單位</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="71"/>
        <source>Or equals:</source>
        <translation>或等於：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="72"/>
        <source>the expected text, instead of limits</source>
        <translation>期望的文字，取代限值</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="123"/>
        <source>SPno%1</source>
        <translation>SPno%1</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="125"/>
        <source>to %1</source>
        <translation>設為 %1</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="129"/>
        <source>%1 ± %2 within %3 s</source>
        <translation>%3 s 內達到 %1 ± %2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="131"/>
        <source>the drive&apos;s target speed</source>
        <translation>驅動器的目標速度</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="134"/>
        <source>for %1 s; limits: %2</source>
        <translation>持續 %1 s；限值：%2 項</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="139"/>
        <source>stopped within %1 s + %2 s</source>
        <translation>%1 s + %2 s 內停止</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="140"/>
        <source>stopped within the deceleration time + %1 s</source>
        <translation>減速時間 + %1 s 內停止</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="144"/>
        <source>no value chosen to read yet</source>
        <translation>尚未選擇要讀取的值</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="148"/>
        <source>%1 is &quot;%2&quot;</source>
        <translation>%1 為「%2」</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="149"/>
        <source>%1 between %2 and %3</source>
        <translation>%1 介於 %2 至 %3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="150"/>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="151"/>
        <source>any</source>
        <translation>不限</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="163"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
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
        <translation>步驟</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="48"/>
        <source>What it does</source>
        <translation>內容</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="56"/>
        <source>Add step</source>
        <translation>新增步驟</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="61"/>
        <source>Remove</source>
        <translation>刪除</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="62"/>
        <source>Move up</source>
        <translation>上移</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="63"/>
        <source>Move down</source>
        <translation>下移</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="93"/>
        <source>(unknown step: %1)</source>
        <translation>（未知步驟：%1）</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="216"/>
        <source>No step selected</source>
        <translation>未選擇步驟</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="217"/>
        <source>Add a step, or select one to edit it.</source>
        <translation>新增步驟，或選擇一個步驟進行編輯。</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="223"/>
        <source>Step %1: %2</source>
        <translation>步驟 %1：%2</translation>
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
        <translation>此步驟沒有設定項目。</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="323"/>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="325"/>
        <source>(unknown: %1)</source>
        <translation>（未知：%1）</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="335"/>
        <source>Parameter:</source>
        <translation>參數：</translation>
    </message>
</context>
<context>
    <name>opentop::Reconnection</name>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="31"/>
        <source>&amp;Reconnect</source>
        <translation>重新連線(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="38"/>
        <source>Open the last connection again, with the same drives and page (Ctrl+R)</source>
        <translation>以相同的驅動器與頁面重新開啟上一次的連線 (Ctrl+R)</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="92"/>
        <source>Reconnecting to %1…</source>
        <translation>正在重新連線至 %1…</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="123"/>
        <source>Reconnected to %1: reading every drive again…</source>
        <translation>已重新連線至 %1：正在重新讀取所有驅動器…</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="176"/>
        <source>Reconnected to %1.</source>
        <translation>已重新連線至 %1。</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="200"/>
        <source>Reconnecting failed: %1</source>
        <translation>重新連線失敗：%1</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="218"/>
        <location filename="../ui/main/Reconnection.cpp" line="262"/>
        <source>Connection lost</source>
        <translation>連線中斷</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="226"/>
        <location filename="../ui/main/Reconnection.cpp" line="267"/>
        <source>Reconnect</source>
        <translation>重新連線</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="268"/>
        <source>Go on anyway</source>
        <translation>仍要繼續</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="269"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
</context>
<context>
    <name>opentop::RelayAnalysis</name>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="47"/>
        <source>no steady oscillation: %1 full cycles around %2, %3 needed</source>
        <translation>無穩定振盪：在 %2 附近只有 %1 個完整週期，需要 %3 個</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="51"/>
        <source>Raise the relay amplitude, or choose an operating speed that leaves the output room on both sides.</source>
        <translation>請加大繼電器振幅，或選擇輸出上下都留有餘裕的運轉速度。</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="86"/>
        <source>the oscillation (±%1) is no larger than the hysteresis (%2)</source>
        <translation>振盪 (±%1) 未大於遲滯 (%2)</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="89"/>
        <source>Raise the relay amplitude.</source>
        <translation>請加大繼電器振幅。</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="97"/>
        <source>the oscillation&apos;s period, %1 ms, holds only %2 readings (one every %3 ms): at least %4 are needed, or its period and amplitude are the bus&apos;s rather than the motor&apos;s</source>
        <translation>振盪週期 %1 ms 內只讀取了 %2 次 (每 %3 ms 一次)：至少需要 %4 次，否則週期與振幅反映的是匯流排而非馬達</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="104"/>
        <source>Raise the line rate (115200 bit/s if every drive on the bus allows it) or stop polling other drives on this bus during the test; a larger relay amplitude or another speed does not change this.</source>
        <translation>請提高鮑率 (若匯流排上所有驅動器都支援，用 115200 bit/s)，或在測試期間暫停輪詢此匯流排上的其他驅動器；加大繼電器振幅或改變速度都無法改善。</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="110"/>
        <source>the oscillation is not steady: periods differ by %1 %, amplitudes by %2 % (at most %3 % and %4 %)</source>
        <translation>振盪不穩定：週期相差 %1 %，振幅相差 %2 % (上限分別為 %3 % 與 %4 %)</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="116"/>
        <source>Raise the relay amplitude so that the oscillation stands out of friction and load changes, keep the load steady during the test, and stop polling other drives on this bus meanwhile.</source>
        <translation>請加大繼電器振幅，使振盪不被摩擦與負載變化淹沒；測試期間保持負載穩定，並暫停輪詢此匯流排上的其他驅動器。</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="123"/>
        <source>the oscillation is lopsided: its time above and below %1 differ by %2 % of the period (at most %3 %)</source>
        <translation>振盪不對稱：高於與低於 %1 的時間相差週期的 %2 % (上限 %3 %)</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="128"/>
        <source>The output for the operating speed was misjudged or the load changed: keep the load steady, choose an operating speed further from standstill and from full output, and repeat the test.</source>
        <translation>運轉速度所需的輸出估計有誤或負載改變：請保持負載穩定，選擇離靜止與最大輸出都較遠的運轉速度，再重新測試。</translation>
    </message>
</context>
<context>
    <name>opentop::RelayAutotune</name>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="65"/>
        <source>the operating speed must be above 0 and below the test&apos;s speed limit %1 %2</source>
        <translation>運轉速度必須大於 0 且小於測試的速度限值 %1 %2</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="72"/>
        <source>the relay amplitude must be 0–50 % of full output</source>
        <translation>繼電器振幅必須為最大輸出的 0–50 %</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="75"/>
        <source>Open loop: finding the output for %1 %2</source>
        <translation>開迴路：正在尋找 %1 %2 所需的輸出</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="148"/>
        <source>the motor did not turn at %1 % output</source>
        <translation>輸出 %1 % 時馬達未轉動</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="180"/>
        <source>the operating speed needs %1 % output: no room for ±%2 % around it</source>
        <translation>運轉速度需要 %1 % 的輸出：上下沒有 ±%2 % 的裕度</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="185"/>
        <source>Relay test around %1 %2 (output %3 % ± %4 %)</source>
        <translation>正在 %1 %2 附近進行繼電器測試 (輸出 %3 % ± %4 %)</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="224"/>
        <source>no steady oscillation within %1 s: %2</source>
        <translation>%1 s 內未出現穩定振盪：%2</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="226"/>
        <source>try a larger amplitude</source>
        <translation>請嘗試加大振幅</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="259"/>
        <source>the relay result was refused: %1</source>
        <translation>繼電器測試結果不予採用：%1</translation>
    </message>
</context>
<context>
    <name>opentop::RelayTuning</name>
    <message>
        <location filename="../model/tuning/RelayTuning.cpp" line="28"/>
        <source>Raise the relay amplitude.</source>
        <translation>請加大繼電器振幅。</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayTuning.cpp" line="49"/>
        <source>the drive&apos;s own loop, as the model extrapolates it, would oscillate with a period of %1 ms, under %2 readings (one every %3 ms): the step after Accept could not show whether the gains work</source>
        <translation>依模型外推，驅動器本身的迴路會以 %1 ms 的週期振盪，不到 %2 次讀取 (每 %3 ms 一次)：接受後的步階無法顯示增益是否可用</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayTuning.cpp" line="55"/>
        <source>Raise the line rate (115200 bit/s if every drive on the bus allows it) or stop polling other drives on this bus during the test.</source>
        <translation>請提高鮑率 (若匯流排上所有驅動器都支援，用 115200 bit/s)，或在測試期間暫停輪詢此匯流排上的其他驅動器。</translation>
    </message>
</context>
<context>
    <name>opentop::RestoreChoice</name>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="28"/>
        <source>Drive in file / setting</source>
        <translation>檔案中的驅動器 / 設定</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="28"/>
        <source>Value in file</source>
        <translation>檔案中的值</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="28"/>
        <source>Restore to</source>
        <translation>還原至</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="55"/>
        <source>(do not restore)</source>
        <translation>(不還原)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="59"/>
        <source>Drive %1 (%2)</source>
        <translation>驅動器 %1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="121"/>
        <source>Two drives of the file would be restored to drive %1.</source>
        <translation>檔案中有兩台驅動器將還原至驅動器 %1。</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="126"/>
        <source>Drive %1 is not on the bus (or not identified).</source>
        <translation>驅動器 %1 不在匯流排上 (或未識別)。</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="138"/>
        <source>Nothing chosen: tick at least one setting of a drive with a target.</source>
        <translation>未選擇任何項目：請至少勾選一台已指定還原目標之驅動器的一項設定。</translation>
    </message>
</context>
<context>
    <name>opentop::RestoreCommand</name>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="37"/>
        <source>Show what a backup file would change on its drives; with --yes write it, verified</source>
        <translation>顯示備份檔將在驅動器上變更的內容；加上 --yes 則寫入並驗證</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="42"/>
        <source>Restore only these drives of the file, e.g. 1,5-7.</source>
        <translation>只還原檔案中的這些驅動器，例如 1,5-7。</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="43"/>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="44"/>
        <source>Read the drives and show the plan; write nothing.</source>
        <translation>讀取驅動器並顯示還原計畫；不寫入任何資料。</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="45"/>
        <source>Write the plan (without it restore only shows it).</source>
        <translation>寫入還原計畫 (未指定時 restore 只會顯示計畫)。</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="55"/>
        <source>%1: the drive&apos;s settings were not read; nothing compared, nothing written</source>
        <translation>%1：未讀取驅動器的設定；未比較，也未寫入任何資料</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="61"/>
        <location filename="../cli/RestoreCommand.cpp" line="99"/>
        <source>note: %1</source>
        <translation>注意：%1</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="66"/>
        <source>parameter</source>
        <translation>參數</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="66"/>
        <source>file value</source>
        <translation>檔案值</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="66"/>
        <source>device value</source>
        <translation>裝置值</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="67"/>
        <source>result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="67"/>
        <source>action</source>
        <translation>動作</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="81"/>
        <source>%1 written and verified, %2 unchanged, %3 failed, %4 not attempted</source>
        <translation>%1 項已寫入並驗證，%2 項未變更，%3 項失敗，%4 項未執行</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="87"/>
        <source>, %1 not confirmed</source>
        <translation>，%1 項未確認</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="89"/>
        <source>; %1 of %2 store commands written</source>
        <translation>；已寫入 %2 個保存指令中的 %1 個</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="124"/>
        <source>error: name one backup file: restore FILE [--ids LIST] [--yes]</source>
        <translation>錯誤：請指定一個備份檔：restore FILE [--ids LIST] [--yes]</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="138"/>
        <source>error: --ids: %1</source>
        <translation>錯誤：--ids：%1</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="144"/>
        <source>error: %1 holds no drive with machine number %2; it holds %3</source>
        <translation>錯誤：%1 中沒有機號 %2 的驅動器；檔案中有 %3</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="165"/>
        <source>error: %1; nothing written</source>
        <translation>錯誤：%1；未寫入任何資料</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="184"/>
        <source>error: %1: %2</source>
        <translation>錯誤：%1：%2</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="205"/>
        <source>%1: not attempted</source>
        <translation>%1：未執行</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="234"/>
        <source>dry run: nothing written</source>
        <translation>僅預覽：未寫入任何資料</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="235"/>
        <source>nothing written; add --yes to write</source>
        <translation>未寫入任何資料；加上 --yes 才會寫入</translation>
    </message>
</context>
<context>
    <name>opentop::RestoreDialog</name>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="38"/>
        <source>&amp;Preview</source>
        <translation>預覽(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="39"/>
        <source>&amp;Write to drives…</source>
        <translation>寫入驅動器(&amp;W)…</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="40"/>
        <source>&amp;Cancel</source>
        <translation>取消(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="41"/>
        <source>&amp;Save report…</source>
        <translation>儲存報告(&amp;S)…</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="43"/>
        <source>Restore from a backup file</source>
        <translation>從備份檔還原</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="45"/>
        <source>No file chosen</source>
        <translation>未選擇檔案</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="46"/>
        <source>&amp;Choose file…</source>
        <translation>選擇檔案(&amp;C)…</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="48"/>
        <source>File:</source>
        <translation>檔案：</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="60"/>
        <source>Read the drives and show what would change; writes nothing</source>
        <translation>讀取驅動器並顯示將變更的內容；不寫入任何資料</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="61"/>
        <source>Write the previewed changes, each verified by reading it back</source>
        <translation>寫入預覽的變更，每項皆以回讀驗證</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="62"/>
        <source>Stop after the write in progress has been verified</source>
        <translation>目前進行中的寫入驗證完成後停止</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="63"/>
        <source>Save the report as text, or as CSV when the name ends in .csv</source>
        <translation>將報告儲存為文字檔；檔名以 .csv 結尾時儲存為 CSV</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="64"/>
        <source>C&amp;lose</source>
        <translation>關閉(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="113"/>
        <source>%1: no such file</source>
        <translation>%1：檔案不存在</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="118"/>
        <source>the file could not be read</source>
        <translation>無法讀取檔案</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="119"/>
        <location filename="../ui/files/RestoreDialog.cpp" line="179"/>
        <source>Refused, nothing will be written: %1</source>
        <translation>已拒絕，不會寫入任何資料：%1</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/RestoreDialog.cpp" line="124"/>
        <source>%n drive(s) in the file. Choose what to restore, then Preview.</source>
        <translation>
            <numerusform>檔案中有 %n 台驅動器。請選擇要還原的項目，然後按「預覽」。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="146"/>
        <source>Refused, nothing written:</source>
        <translation>已拒絕，未寫入任何資料：</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="148"/>
        <source>Drive %1 from %2: %3</source>
        <translation>驅動器 %1 (來自 %2)：%3</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="178"/>
        <source>Choose a backup file first.</source>
        <translation>請先選擇備份檔。</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="194"/>
        <source>Nothing was read or written: %1.</source>
        <translation>未讀取也未寫入任何資料：%1。</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="86"/>
        <source>Reading drive %1…</source>
        <translation>正在讀取驅動器 %1…</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="86"/>
        <source>Writing drive %1…</source>
        <translation>正在寫入驅動器 %1…</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="94"/>
        <source>drive %1: %2 (%v of %m)</source>
        <translation>驅動器 %1：%2 (%v / %m)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="229"/>
        <source>Stopping after the write in progress has been verified…</source>
        <translation>目前進行中的寫入驗證完成後將停止…</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="244"/>
        <location filename="../ui/files/RestoreDialog.cpp" line="325"/>
        <location filename="../ui/files/RestoreDialog.cpp" line="330"/>
        <source>Drive %1: %2</source>
        <translation>驅動器 %1：%2</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/RestoreDialog.cpp" line="247"/>
        <source>%n setting(s) to write</source>
        <translation>
            <numerusform>%n 項設定待寫入</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="254"/>
        <source>  Note: %1</source>
        <translation>  注意：%1</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="257"/>
        <source>Nothing written yet. Write to drives to apply.</source>
        <translation>尚未寫入任何資料。請按「寫入驅動器」以套用。</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="258"/>
        <source>Nothing written.</source>
        <translation>未寫入任何資料。</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="306"/>
        <source>Restore from backup file</source>
        <translation>從備份檔還原</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="307"/>
        <source>OpenTOP backups (*.json);;All files (*)</source>
        <translation>OpenTOP 備份檔 (*.json);;所有檔案 (*)</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/RestoreDialog.cpp" line="333"/>
        <source>Write %n setting(s) to drive(s) %1, each verified by reading it back?</source>
        <translation>
            <numerusform>要將 %n 項設定寫入驅動器 %1，並逐項以回讀驗證嗎？</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="338"/>
        <source>Write to drives</source>
        <translation>寫入驅動器</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="338"/>
        <source>&amp;Write</source>
        <translation>寫入(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="343"/>
        <source>Save restore report</source>
        <translation>儲存還原報告</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="344"/>
        <source>Text (*.txt);;CSV (*.csv)</source>
        <translation>文字檔 (*.txt);;CSV (*.csv)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="349"/>
        <source>Could not save %1: %2</source>
        <translation>無法儲存 %1：%2</translation>
    </message>
</context>
<context>
    <name>opentop::RestorePlan</name>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="71"/>
        <source>the file holds a %1 drive (%2), but machine number %3 is a %4 drive; nothing written</source>
        <translation>檔案中為 %1 驅動器 (%2)，但機號 %3 是 %4 驅動器；未寫入任何資料</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="78"/>
        <source>the file is from a %1 (%2), but machine number %3 is a %4 (%5); their allowed values differ, nothing written</source>
        <translation>檔案來自 %1 (%2)，但機號 %3 是 %4 (%5)；兩者的允許值不同，未寫入任何資料</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="85"/>
        <source>the drive does not tell its variant: every value must suit all variants (name it with --variant to use its own ranges)</source>
        <translation>驅動器不回報機型：每個值都必須適用於所有機型 (以 --variant 指定機型即可使用其範圍)</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="143"/>
        <source>%1: the value cannot be written exactly</source>
        <translation>%1：無法精確寫入此值</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/files/RestorePlan.cpp" line="163"/>
        <source>%n value(s) of the file may not be written to this drive; nothing written</source>
        <translation>
            <numerusform>檔案中有 %n 個值不可寫入此驅動器；未寫入任何資料</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="245"/>
        <source>%1 sent after the writes, so that the settings written survive power-off</source>
        <translation>寫入後送出 %1，使寫入的設定在斷電後仍保留</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="248"/>
        <source>%1 sent: settings written to this drive earlier (by an interrupted restore, a page or the command line) are not stored yet</source>
        <translation>已送出 %1：先前寫入此驅動器的設定 (中斷的還原、頁面或命令列) 尚未保存</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="252"/>
        <source>%1 not sent: nothing it stores is written. What a drive has stored cannot be read back: if it loses settings at power-off, switch it off and on and restore again</source>
        <translation>未送出 %1：沒有寫入它所保存的設定。驅動器已保存的內容無法讀回：若斷電後遺失設定，請斷電再上電後重新還原</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="286"/>
        <source>keep</source>
        <translation>保留</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="288"/>
        <source>write</source>
        <translation>寫入</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="290"/>
        <source>store</source>
        <translation>保存</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="301"/>
        <source>unchanged</source>
        <translation>未變更</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="304"/>
        <source>written, not verified: %1</source>
        <translation>已寫入，未確認：%1</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="305"/>
        <source>written</source>
        <translation>已寫入</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="305"/>
        <source>written and verified</source>
        <translation>已寫入並驗證</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="307"/>
        <source>failed: %1</source>
        <translation>失敗：%1</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="309"/>
        <source>not attempted</source>
        <translation>未執行</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="311"/>
        <source>not confirmed (%1): the drive may or may not hold it; run the restore again to read it back</source>
        <translation>未確認 (%1)：驅動器可能已保有此值，也可能沒有；請再次執行還原以回讀</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="336"/>
        <source>planned</source>
        <translation>已規劃</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="338"/>
        <source>restored</source>
        <translation>已還原</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="340"/>
        <source>refused</source>
        <translation>已拒絕</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="342"/>
        <source>communication failure</source>
        <translation>通訊失敗</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="344"/>
        <source>verification mismatch</source>
        <translation>驗證不符</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="346"/>
        <source>interrupted</source>
        <translation>已中斷</translation>
    </message>
</context>
<context>
    <name>opentop::RestorePlanTable</name>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="14"/>
        <source>Drive</source>
        <translation>驅動器</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="14"/>
        <source>Parameter</source>
        <translation>參數</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="14"/>
        <source>Action</source>
        <translation>動作</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="14"/>
        <source>File value</source>
        <translation>檔案值</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="15"/>
        <source>Drive value before</source>
        <translation>驅動器原值</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="15"/>
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="93"/>
        <source>&amp;Differences only</source>
        <translation>僅顯示差異(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="95"/>
        <source>Show only the settings that would be written (or were), and what went wrong</source>
        <translation>只顯示將寫入 (或已寫入) 的設定及出錯的項目</translation>
    </message>
</context>
<context>
    <name>opentop::RestoreReport</name>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="18"/>
        <source>%1 written and verified, %2 unchanged, %3 failed, %4 not attempted</source>
        <translation>%1 項已寫入並驗證，%2 項未變更，%3 項失敗，%4 項未執行</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="24"/>
        <source>, %1 not confirmed</source>
        <translation>，%1 項未確認</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="26"/>
        <source>; %1 of %2 store commands written</source>
        <translation>；已寫入 %2 個保存指令中的 %1 個</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="35"/>
        <source>OpenTOP restore report</source>
        <translation>OpenTOP 還原報告</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="35"/>
        <source>File: %1</source>
        <translation>檔案：%1</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="36"/>
        <source>Date: %1 (UTC)</source>
        <translation>日期：%1 (UTC)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="39"/>
        <source>Written to the drives</source>
        <translation>已寫入驅動器</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="39"/>
        <source>Preview only: nothing written</source>
        <translation>僅預覽：未寫入任何資料</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="42"/>
        <source>Machine number %1 from %2: %3</source>
        <translation>機號 %1 (來自 %2)：%3</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="53"/>
        <source>  %1: %2</source>
        <translation>  %1：%2</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="55"/>
        <source>  %1: file %2, drive %3: %4</source>
        <translation>  %1：檔案 %2，驅動器 %3：%4</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="61"/>
        <source>  Note: %1</source>
        <translation>  注意：%1</translation>
    </message>
</context>
<context>
    <name>opentop::Restorer</name>
    <message>
        <location filename="../model/files/Restorer.cpp" line="51"/>
        <source>interrupted before anything was written</source>
        <translation>在寫入任何資料前中斷</translation>
    </message>
    <message>
        <location filename="../model/files/Restorer.cpp" line="66"/>
        <source>reading the drive failed, nothing written (%1)</source>
        <translation>讀取驅動器失敗，未寫入任何資料 (%1)</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/files/Restorer.cpp" line="119"/>
        <source>%n value(s) of the file may not be written to the drives of the communication group; nothing written</source>
        <translation>
            <numerusform>檔案中有 %n 個值不可寫入通訊群組的驅動器；未寫入任何值</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/files/Restorer.cpp" line="147"/>
        <source>interrupted after %1 of %2 writes; run the restore again to complete it</source>
        <translation>在 %2 項寫入中完成 %1 項後中斷；請再次執行還原以完成</translation>
    </message>
    <message>
        <location filename="../model/files/Restorer.cpp" line="183"/>
        <source>%1 not confirmed (%2): the drive may or may not hold it; run the restore again, it reads the drive back first</source>
        <translation>%1 未確認 (%2)：驅動器可能已保有此值，也可能沒有；請再次執行還原，它會先回讀驅動器</translation>
    </message>
    <message>
        <location filename="../model/files/Restorer.cpp" line="217"/>
        <source>after storing, the drive holds %1</source>
        <translation>保存後驅動器中為 %1</translation>
    </message>
    <message>
        <location filename="../model/files/Restorer.cpp" line="222"/>
        <source>the settings could not be read back after storing</source>
        <translation>保存後無法回讀設定</translation>
    </message>
    <message>
        <location filename="../model/files/Restorer.cpp" line="255"/>
        <source>communication settings changed (%1): they take effect when the drive is next powered on; connect with the new settings after that</source>
        <translation>通訊設定已變更 (%1)：將於驅動器下次上電時生效；之後請以新設定連線</translation>
    </message>
</context>
<context>
    <name>opentop::ResultDatabase</name>
    <message>
        <location filename="../model/eol/ResultDatabase.cpp" line="45"/>
        <source>results database %1: %2</source>
        <translation>結果資料庫 %1：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultDatabase.cpp" line="49"/>
        <source>the Qt SQL driver %1 is not installed (Debian: %2)</source>
        <translation>未安裝 Qt SQL 驅動程式 %1 (Debian：%2)</translation>
    </message>
</context>
<context>
    <name>opentop::ResultQueries</name>
    <message>
        <location filename="../model/eol/ResultQueries.cpp" line="207"/>
        <source>no unit record %1</source>
        <translation>沒有產品記錄 %1</translation>
    </message>
</context>
<context>
    <name>opentop::ResultSchema</name>
    <message>
        <location filename="../model/eol/ResultSchema.cpp" line="242"/>
        <source>the results database has schema version %1, newer than this program knows (%2): update OpenTOP on this station; nothing was written</source>
        <translation>結果資料庫的結構版本為 %1，比本程式支援的版本 (%2) 還新：請更新此工站的 OpenTOP；未寫入任何資料</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultSchema.cpp" line="277"/>
        <source>the migration left a record pointing at no unit (table %1)</source>
        <translation>資料庫結構遷移後留下未對應任何產品的記錄 (資料表 %1)</translation>
    </message>
</context>
<context>
    <name>opentop::ResultSink</name>
    <message>
        <location filename="../model/eol/ResultSink.cpp" line="137"/>
        <source>the results database is not open</source>
        <translation>結果資料庫未開啟</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultSink.cpp" line="210"/>
        <source>the results database refuses unit %1 (serial %2): %3</source>
        <translation>結果資料庫拒絕單元 %1（序號 %2）：%3</translation>
    </message>
</context>
<context>
    <name>opentop::ResultSpool</name>
    <message>
        <location filename="../model/eol/ResultSpool.cpp" line="67"/>
        <location filename="../model/eol/ResultSpool.cpp" line="103"/>
        <source>the station&apos;s spool %1: %2</source>
        <translation>工作站暫存檔 %1：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultSpool.cpp" line="71"/>
        <source>its folder cannot be made</source>
        <translation>無法建立其資料夾</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultSpool.cpp" line="131"/>
        <source>the station&apos;s spool %1: entry %2 cannot be read (%3)</source>
        <translation>工作站暫存檔 %1：第 %2 筆無法讀取（%3）</translation>
    </message>
</context>
<context>
    <name>opentop::ResultStore</name>
    <message>
        <location filename="../model/eol/ResultStore.cpp" line="64"/>
        <source>interrupted: the station stopped before the unit was finished (killed, power lost or crashed); the unit was not proven</source>
        <translation>已中斷：工站在產品測試完成前停止 (被終止、斷電或當機)；此產品未經驗證</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultStore.cpp" line="72"/>
        <source>a unit needs a serial number</source>
        <translation>產品需要序號</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultStore.cpp" line="197"/>
        <source>a unit is finished with pass, fail, error or aborted, not %1</source>
        <translation>產品只能以 pass、fail、error 或 aborted 結束，而非 %1</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultStore.cpp" line="227"/>
        <source>unit %1 (serial %2) was never begun in the results database</source>
        <translation>產品 %1 (序號 %2) 從未在結果資料庫中開始</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultStore.cpp" line="229"/>
        <source>unit %1 (serial %2) is already recorded as %3; its record is kept</source>
        <translation>產品 %1 (序號 %2) 已記錄為 %3；保留其記錄</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultStore.cpp" line="251"/>
        <source>unit %1 (serial %2) is not running in the results database: it was never begun, or was already finished or marked interrupted</source>
        <translation>產品 %1 (序號 %2) 在結果資料庫中並非測試中：從未開始，或已完成或已標記為中斷</translation>
    </message>
</context>
<context>
    <name>opentop::ResultUrl</name>
    <message>
        <location filename="../model/eol/ResultUrl.cpp" line="45"/>
        <source>no database given: name a file or a postgresql:// URL</source>
        <translation>未指定資料庫：請指定檔案或 postgresql:// URL</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultUrl.cpp" line="53"/>
        <source>unknown database URL &quot;%1&quot;: use a file path, sqlite:PATH or postgresql://user@host/database</source>
        <translation>未知的資料庫 URL &quot;%1&quot;：請使用檔案路徑、sqlite:PATH 或 postgresql://user@host/database</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultUrl.cpp" line="57"/>
        <source>sqlite: needs a file path</source>
        <translation>sqlite: 需要檔案路徑</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultUrl.cpp" line="86"/>
        <source>the host in &quot;%1&quot; has no closing ]</source>
        <translation>&quot;%1&quot; 中的主機缺少結尾的 ]</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultUrl.cpp" line="114"/>
        <source>unknown connection option &quot;%1&quot; in the database URL; known: %2</source>
        <translation>資料庫 URL 中有未知的連線選項 &quot;%1&quot;；已知：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultUrl.cpp" line="137"/>
        <source>the port &quot;%1&quot; in the database URL is not a number from 1 to 65535</source>
        <translation>資料庫 URL 中的連接埠 &quot;%1&quot; 不是 1 到 65535 的數字</translation>
    </message>
</context>
<context>
    <name>opentop::ResultsBrowser</name>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="61"/>
        <source>End-of-line results</source>
        <translation>終檢結果</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="64"/>
        <source>Started</source>
        <translation>開始時間</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="64"/>
        <source>Serial</source>
        <translation>序號</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="64"/>
        <source>Recipe</source>
        <translation>配方</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="64"/>
        <source>Station</source>
        <translation>工站</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="65"/>
        <source>Operator</source>
        <translation>作業員</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="65"/>
        <source>Verdict</source>
        <translation>判定</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="65"/>
        <source>Time (s)</source>
        <translation>時間 (s)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="66"/>
        <source>First failure</source>
        <translation>首個不合格項目</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="84"/>
        <source>Export CSV…</source>
        <translation>匯出 CSV…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="85"/>
        <source>Certificate PDF…</source>
        <translation>測試證書 PDF…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="136"/>
        <source>There is no results database at %1 yet: a station makes it when it records its first unit.</source>
        <translation>%1 尚無結果資料庫：工站記錄第一台產品時會建立。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="142"/>
        <source>Opening the results database %1…</source>
        <translation>正在開啟結果資料庫 %1…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="154"/>
        <source>Results database %1</source>
        <translation>結果資料庫 %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="178"/>
        <source>Searching…</source>
        <translation>正在搜尋…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="189"/>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="278"/>
        <source>the results database is not open</source>
        <translation>結果資料庫未開啟</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="220"/>
        <source>%1 rev. %2</source>
        <translation>%1 版次 %2</translation>
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
            <numerusform>%n 台產品：合格 %1、不合格 %2、工站錯誤 %3 · %4</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="253"/>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="306"/>
        <source>no unit is selected</source>
        <translation>未選擇產品</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="258"/>
        <source>Reading unit %1…</source>
        <translation>正在讀取產品 %1…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="307"/>
        <source>the unit&apos;s record is still being read</source>
        <translation>仍在讀取該產品的記錄</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="316"/>
        <source>Export units as CSV</source>
        <translation>將產品匯出為 CSV</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="316"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV 檔 (*.csv)</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/eol/ResultsBrowser.cpp" line="321"/>
        <source>%n unit(s) written to %1</source>
        <translation>
            <numerusform>已將 %n 台產品寫入 %1</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="332"/>
        <source>Save certificate</source>
        <translation>儲存測試證書</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="333"/>
        <source>PDF files (*.pdf)</source>
        <translation>PDF 檔 (*.pdf)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="338"/>
        <source>Certificate written to %1</source>
        <translation>測試證書已寫入 %1</translation>
    </message>
</context>
<context>
    <name>opentop::ResultsFilterBar</name>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="21"/>
        <source>SQLite file or postgresql://user@host/database</source>
        <translation>SQLite 檔或 postgresql://user@host/database</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="22"/>
        <source>Open</source>
        <translation>開啟</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="23"/>
        <source>File…</source>
        <translation>檔案…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="30"/>
        <source>any; * and ? as wildcards (SN-10*)</source>
        <translation>全部；可用 * 與 ? 作萬用字元（SN-10*）</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="32"/>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="34"/>
        <source>any</source>
        <translation>不限</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="36"/>
        <source>Today</source>
        <translation>今天</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="37"/>
        <source>Last 24 hours</source>
        <translation>最近 24 小時</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="38"/>
        <source>Last 7 days</source>
        <translation>最近 7 天</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="39"/>
        <source>Last 30 days</source>
        <translation>最近 30 天</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="40"/>
        <source>All</source>
        <translation>全部</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="43"/>
        <source>Any</source>
        <translation>不限</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="47"/>
        <source>Search</source>
        <translation>搜尋</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="51"/>
        <source>Serial:</source>
        <translation>序號：</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="52"/>
        <source>Recipe:</source>
        <translation>配方：</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="53"/>
        <source>Station:</source>
        <translation>工站：</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="54"/>
        <source>Period:</source>
        <translation>期間：</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="55"/>
        <source>Verdict:</source>
        <translation>判定：</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="63"/>
        <source>Database:</source>
        <translation>資料庫：</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="105"/>
        <source>Open results database</source>
        <translation>開啟結果資料庫</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="106"/>
        <source>SQLite databases (*.db *.sqlite);;All files (*)</source>
        <translation>SQLite 資料庫 (*.db *.sqlite);;所有檔案 (*)</translation>
    </message>
</context>
<context>
    <name>opentop::RetestPolicy</name>
    <message>
        <location filename="../model/eol/RetestPolicy.cpp" line="20"/>
        <source>serial %1 has passed already; this recipe never tests a passed unit again</source>
        <translation>序號 %1 已合格；此配方不會再次測試已合格的產品</translation>
    </message>
    <message>
        <location filename="../model/eol/RetestPolicy.cpp" line="23"/>
        <source>serial %1 has passed already; testing it again needs a technician</source>
        <translation>序號 %1 已合格；須由技術員許可才能重新測試</translation>
    </message>
    <message>
        <location filename="../model/eol/RetestPolicy.cpp" line="29"/>
        <source>serial %1 was tested %2 times under this recipe, its limit; another attempt needs a technician</source>
        <translation>序號 %1 在此配方下已測試 %2 次，已達上限；再次測試須由技術員許可</translation>
    </message>
    <message>
        <location filename="../model/eol/RetestPolicy.cpp" line="50"/>
        <source>the results database is not open</source>
        <translation>結果資料庫未開啟</translation>
    </message>
    <message>
        <location filename="../model/eol/RetestPolicy.cpp" line="58"/>
        <source>earlier tests of %1 were not checked (%2): the result is kept in the station&apos;s spool</source>
        <translation>未能檢查 %1 先前的測試記錄（%2）：結果會保存在工站暫存檔中</translation>
    </message>
</context>
<context>
    <name>opentop::RoleEvaluator</name>
    <message>
        <location filename="../model/profile/RoleEvaluator.cpp" line="102"/>
        <source>%1 = %2 (%3, function %4)</source>
        <translation>%1 = %2 (%3，功能 %4)</translation>
    </message>
</context>
<context>
    <name>opentop::RunCommand</name>
    <message>
        <location filename="../cli/RunCommand.cpp" line="50"/>
        <source>Test run: start, stop, direction, running data, hold/free, speed (needs --yes)</source>
        <translation>試運轉：啟動、停止、方向、運轉資料、保持/釋放、速度 (需要 --yes)</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="55"/>
        <source>Send the command (it moves or stops a motor).</source>
        <translation>送出指令 (會使馬達運轉或停止)。</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="65"/>
        <source>error: usage: %1 (one machine number; a negative speed after --)</source>
        <translation>錯誤：用法：%1 (一個機號；負速度請放在 -- 之後)</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="73"/>
        <location filename="../cli/RunCommand.cpp" line="78"/>
        <location filename="../cli/RunCommand.cpp" line="83"/>
        <location filename="../cli/RunCommand.cpp" line="145"/>
        <source>error: %1</source>
        <translation>錯誤：%1</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="88"/>
        <source>Would send to machine number %1: %2
This moves or stops a motor: add --yes to send it.</source>
        <translation>將送往機號 %1：%2
此操作會使馬達運轉或停止：加上 --yes 才會送出。</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="109"/>
        <source>note: %1</source>
        <translation>注意：%1</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="137"/>
        <source>Sent to machine number %1: %2</source>
        <translation>已送往機號 %1：%2</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="139"/>
        <source>Sent to machine number %1, executed also by %2 (communication group): %3</source>
        <translation>已送往機號 %1，%2 也會執行 (通訊群組)：%3</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="175"/>
        <source>(not read: %1)</source>
        <translation>(未讀取：%1)</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="184"/>
        <source>State of machine number %1:</source>
        <translation>機號 %1 的狀態：</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="200"/>
        <source>Communication group of %1, read after the command:</source>
        <translation>%1 的通訊群組，指令後讀取：</translation>
    </message>
</context>
<context>
    <name>opentop::RunControl</name>
    <message>
        <location filename="../model/run/RunControl.cpp" line="59"/>
        <source>%1 needs one value, e.g. &quot;%1 %2&quot;</source>
        <translation>%1 需要一個值，例如 &quot;%1 %2&quot;</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="62"/>
        <source>%1 takes no value</source>
        <translation>%1 不接受值</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="70"/>
        <source>select needs a running data number, e.g. &quot;select 2&quot;; got &quot;%1&quot;</source>
        <translation>select 需要運轉資料編號，例如 &quot;select 2&quot;；收到 &quot;%1&quot;</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="80"/>
        <source>unknown run command &quot;%1&quot;; use start, stop, cw, ccw, select N, hold, free, coast or speed VALUE</source>
        <translation>未知的運轉指令 &quot;%1&quot;；請使用 start、stop、cw、ccw、select N、hold、free、coast 或 speed VALUE</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="127"/>
        <source>%1 drives have no &quot;%2&quot; command; they take: %3</source>
        <translation>%1 驅動器沒有 &quot;%2&quot; 指令；可用指令：%3</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="148"/>
        <source>%1 has no selection codes</source>
        <translation>%1 沒有選擇代碼</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="149"/>
        <source>select %1: choose %2–%3 (%4 … %5)</source>
        <translation>select %1：請選擇 %2–%3 (%4 … %5)</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="186"/>
        <source>cannot read %1 to check that the drive takes motion commands: %2</source>
        <translation>無法讀取 %1 以確認驅動器是否接受運轉指令：%2</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="206"/>
        <source>machine number %1 is in &quot;%2&quot; (%3); nothing was sent</source>
        <translation>機號 %1 處於 &quot;%2&quot; (%3)；未送出任何資料</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="210"/>
        <source>In &quot;%1&quot; the drive takes run, stop, direction and speed selection from its input terminals and refuses motion commands over the bus. To test-run it from here, switch it to &quot;%2&quot;: opentop-cli set %3 %4=%5 (and back to &quot;%1&quot;, =%6, when the machine&apos;s own controls should run it again).</source>
        <translation>在 &quot;%1&quot; 下，驅動器的運轉、停止、方向與速度選擇均來自輸入端子，並拒絕來自匯流排的運轉指令。若要從這裡試運轉，請切換為 &quot;%2&quot;：opentop-cli set %3 %4=%5 (當要由機台本身的控制再次運轉時，請切回 &quot;%1&quot;，=%6)。</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="265"/>
        <source>An alarm is active: the drive refuses to run until it is cleared. See opentop-cli alarms %1, then alarms %1 --reset --yes.</source>
        <translation>警報發生中：警報解除前驅動器拒絕運轉。請參閱 opentop-cli alarms %1，然後執行 alarms %1 --reset --yes。</translation>
    </message>
</context>
<context>
    <name>opentop::RunLiveState</name>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="26"/>
        <source>The drive now</source>
        <translation>驅動器目前狀態</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="49"/>
        <source>State</source>
        <translation>狀態</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="51"/>
        <source>Alarm</source>
        <translation>警報</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="58"/>
        <source>Running data</source>
        <translation>運轉資料</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="95"/>
        <source>%1:</source>
        <translation>%1：</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="133"/>
        <source>%1 (%2 %3)</source>
        <translation>%1 (%2 %3)</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="135"/>
        <source>not reported</source>
        <translation>未回報</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="143"/>
        <location filename="../ui/run/RunLiveState.cpp" line="146"/>
        <location filename="../ui/run/RunLiveState.cpp" line="156"/>
        <source>not read</source>
        <translation>未讀取</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="143"/>
        <source>SPno%1</source>
        <translation>SPno%1</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="148"/>
        <source>none</source>
        <translation>無</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="151"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="153"/>
        <source>active</source>
        <translation>發生中</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="172"/>
        <source>waiting for the first answer…</source>
        <translation>等待第一次回應…</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="172"/>
        <source>not watched</source>
        <translation>未監視</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="178"/>
        <source>Not live: %1</source>
        <translation>非即時：%1</translation>
    </message>
</context>
<context>
    <name>opentop::RunningData</name>
    <message>
        <location filename="../model/profile/RunningData.cpp" line="76"/>
        <source>SPno%1 slows down from %2 r/min in %3 s: the manual asks for a deceleration time of more than %4 s when slowing down from high speed (about %5 r/min and above).</source>
        <translation>SPno%1 在 %3 s 內從 %2 r/min 減速：手冊要求從高速 (約 %5 r/min 以上) 減速時，減速時間應大於 %4 s。</translation>
    </message>
    <message>
        <location filename="../model/profile/RunningData.cpp" line="144"/>
        <source>Short deceleration from high speed on %1 (%2 r/min in %3 s): the manual asks for a deceleration time of more than %4 s when slowing down from high speed (about %5 r/min and above).</source>
        <translation>%1 從高速減速的時間過短 (%3 s 內從 %2 r/min 減速)：手冊要求從高速 (約 %5 r/min 以上) 減速時，減速時間應大於 %4 s。</translation>
    </message>
</context>
<context>
    <name>opentop::RunningDataPage</name>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="40"/>
        <location filename="../ui/pages/RunningDataPage.cpp" line="55"/>
        <source>Running data</source>
        <translation>運轉資料</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="55"/>
        <source>Speed (r/min)</source>
        <translation>速度 (r/min)</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="55"/>
        <source>Acceleration (s)</source>
        <translation>加速時間 (s)</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="56"/>
        <source>Deceleration (s)</source>
        <translation>減速時間 (s)</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="56"/>
        <source>Direction</source>
        <translation>方向</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="69"/>
        <source>SPno%1</source>
        <translation>SPno%1</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="72"/>
        <source>Selected by the inputs M0 = %1, M1 = %2, M2 = %3 or by the running data selection command</source>
        <translation>由輸入 M0 = %1、M1 = %2、M2 = %3 或運轉資料選擇指令選擇</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="95"/>
        <source>SS trimmer</source>
        <translation>SS 旋鈕</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="96"/>
        <source>SPno1 has no acceleration register: the SS trimmer on the drive sets it (0.5–30 s); it is not stored in the drive</source>
        <translation>SPno1 沒有加速時間暫存器：由驅動器上的 SS 旋鈕設定 (0.5–30 s)；不會儲存於驅動器中</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="99"/>
        <source>SD trimmer</source>
        <translation>SD 旋鈕</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="100"/>
        <source>SPno1 has no deceleration register: the SD trimmer on the drive sets it (0.5 s or 2–30 s); it is not stored in the drive</source>
        <translation>SPno1 沒有減速時間暫存器：由驅動器上的 SD 旋鈕設定 (0.5 s 或 2–30 s)；不會儲存於驅動器中</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="104"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="105"/>
        <source>This drive has no register for this value</source>
        <translation>此驅動器沒有此值的暫存器</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="112"/>
        <source>Initialize</source>
        <translation>初始化</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="114"/>
        <source>Reset SPno%1 on the drive to its factory defaults</source>
        <translation>將驅動器上的 SPno%1 恢復為出廠預設值</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="115"/>
        <location filename="../ui/pages/RunningDataPage.cpp" line="315"/>
        <location filename="../ui/pages/RunningDataPage.cpp" line="322"/>
        <source>Initialize SPno%1</source>
        <translation>初始化 SPno%1</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="145"/>
        <source>SPno1 runs at the speed of the external speed-setting VR (CN3) with the SS/SD trimmer times; it is not stored in the drive</source>
        <translation>SPno1 以外部速度設定 VR (CN3) 的速度運轉，加減速時間依 SS/SD 旋鈕；不會儲存於驅動器中</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="255"/>
        <source>Allowed speed on this %1: %2 (0 stops the motor)</source>
        <translation>此 %1 的允許速度：%2 (0 使馬達停止)</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="168"/>
        <location filename="../ui/pages/RunningDataPage.cpp" line="265"/>
        <location filename="../ui/pages/RunningDataPage.cpp" line="281"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="268"/>
        <source>Allowed speed: %1</source>
        <translation>允許速度：%1</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="269"/>
        <source>The drive&apos;s variant is not known, so a speed must suit every variant (0 stops the motor): %1</source>
        <translation>驅動器機型未知，因此速度必須適用於所有機型 (0 使馬達停止)：%1</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="281"/>
        <source>its factory default</source>
        <translation>其出廠預設值</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="303"/>
        <source>The SPno1 speed and times come from the external VR and the SS/SD trimmers; they do not change.</source>
        <translation>SPno1 的速度與時間來自外部 VR 與 SS/SD 旋鈕；不會變更。</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="310"/>
        <source>Your unwritten edits in this row are discarded.</source>
        <translation>此列中未寫入的變更將被捨棄。</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="316"/>
        <source>Reset running data SPno%1 of drive %2 to these factory defaults?</source>
        <translation>要將驅動器 %2 的運轉資料 SPno%1 恢復為這些出廠預設值嗎？</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="328"/>
        <source>Initializing SPno%1…</source>
        <translation>正在初始化 SPno%1…</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="343"/>
        <source>SPno%1 was not initialized: %2</source>
        <translation>SPno%1 未初始化：%2</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/pages/RunningDataPage.cpp" line="359"/>
        <source>SPno%1 initialized; %n value(s) could not be read back</source>
        <translation>
            <numerusform>SPno%1 已初始化；%n 個值無法回讀</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="361"/>
        <source>SPno%1 initialized to its factory defaults</source>
        <translation>SPno%1 已初始化為出廠預設值</translation>
    </message>
</context>
<context>
    <name>opentop::ScanCommand</name>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="66"/>
        <source>Find and identify the drives on the bus (machine numbers 1–247)</source>
        <translation>尋找並識別匯流排上的驅動器 (機號 1–247)</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="72"/>
        <source>First machine number to ask, 1–247 (default 1).</source>
        <translation>起始詢問機號，1–247 (預設 1)。</translation>
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
        <translation>最後詢問機號，1–247 (預設 247)。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="75"/>
        <source>Wait per machine number in ms, 10–5000 (default: derived from the baud rate; raise it for slow adapters or gateways).</source>
        <translation>每個機號的等待時間，單位 ms，10–5000 (預設：依鮑率計算；轉接器或閘道器較慢時請加大)。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="77"/>
        <source>MS</source>
        <translation>MS</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="79"/>
        <source>Also ask the machine numbers not found in every other line format a drive can be set to (a DC controller at 8E1 on a DBU bus at 8N1): one more pass per format, off by default.</source>
        <translation>對沒有找到的機號，也以驅動器可設定的其他每種通訊格式詢問（8N1 的 DBU 匯流排上 8E1 的 DC 控制器）：每種格式多掃描一輪，預設關閉。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="94"/>
        <source>error: --%1 must be a number %2–%3, not &quot;%4&quot;</source>
        <translation>錯誤：--%1 必須是 %2–%3 的數字，而非 &quot;%4&quot;</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="106"/>
        <source>error: scan takes no arguments; use --from N --to N</source>
        <translation>錯誤：scan 不接受引數；請使用 --from N --to N</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="115"/>
        <source>error: --from %1 is after --to %2</source>
        <translation>錯誤：--from %1 大於 --to %2</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="133"/>
        <source>Scanning machine numbers %1–%2 on %3, %4 ms each…</source>
        <translation>正在 %3 上掃描機號 %1–%2，每個 %4 ms…</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="180"/>
        <source>Interrupted before any machine number was scanned.</source>
        <translation>在掃描任何機號前中斷。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="182"/>
        <source>Interrupted: machine numbers %1–%2 were scanned (%3 of %4); %5–%6 were not asked.</source>
        <translation>已中斷：已掃描機號 %1–%2 (%4 個中的 %3 個)；%5–%6 未詢問。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="196"/>
        <source>error: the scan stopped at machine number %1: %2</source>
        <translation>錯誤：掃描在機號 %1 停止：%2</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="208"/>
        <source>note: remembered for %1: %2; set, run and restore read their communication groups before a write</source>
        <translation>注意：已為 %1 記住：%2；set、run 與 restore 寫入前會讀取其通訊群組</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="217"/>
        <source>warning: %1</source>
        <translation>警告：%1</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="219"/>
        <source>note: %1 drive(s) answered only after the %2 ms wait and were asked again; if scans miss drives, give a longer --wait.</source>
        <translation>注意：%1 台驅動器在 %2 ms 等待時間後才回應，已重新詢問；若掃描遺漏驅動器，請加長 --wait。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="228"/>
        <source>warning: machine number %1 answered, but its identification failed, also when asked again %2 more times; it is not counted as a drive. Add it by hand: name it in a command (it is identified again then, within --timeout; raise it for a slow device), or check its line settings and scan again with a longer --wait.</source>
        <translation>警告：機號 %1 有回應，但識別失敗，再詢問 %2 次也一樣；它不計為驅動器。請手動加入：在指令中指定這個機號 (屆時會在 --timeout 內重新識別；裝置回應慢時請加大)，或檢查它的通訊設定後以較長的 --wait 重新掃描。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="237"/>
        <source>No drive answered at machine numbers %1–%2. Check:
  - the wiring, and the A/B polarity (swap A and B if unsure);
  - baud rate and parity: the drives&apos; settings must match %3 (--baud, --parity, --family);
  - the termination (120 Ω at both ends of the bus) and that the drives are powered.</source>
        <translation>機號 %1–%2 沒有驅動器回應。請檢查：
  - 配線及 A/B 極性 (不確定時請對調 A 與 B)；
  - 鮑率與同位元：驅動器的設定必須與 %3 相符 (--baud、--parity、--family)；
  - 終端電阻 (匯流排兩端各 120 Ω) 以及驅動器是否已通電。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="250"/>
        <source>hint: %1 Retry with the same connection and: %2</source>
        <translation>提示：%1 請以相同連線加上以下選項重試：%2</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="263"/>
        <source>Serial line: %1</source>
        <translation>序列線路：%1</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="266"/>
        <source>warning: %1 The scan waits up to %2 ms longer per machine number because of it.</source>
        <translation>警告：%1 因此掃描時每個機號最多會多等待 %2 ms。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="390"/>
        <source>warning: machine number %1 (%2) answers with garbled replies: two drives probably have the same machine number. Check the address switches of the drives on this bus, give each drive its own machine number, power them off and on, and scan again.</source>
        <translation>警告：機號 %1 (%2) 的回應損壞：可能有兩台驅動器使用相同機號。請檢查此匯流排上各驅動器的位址開關，為每台驅動器設定各自的機號，斷電再上電後重新掃描。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="276"/>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="276"/>
        <source>hex</source>
        <translation>十六進位</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="276"/>
        <source>switches</source>
        <translation>開關</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="276"/>
        <source>family</source>
        <translation>系列</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="277"/>
        <source>model</source>
        <translation>型號</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="277"/>
        <source>firmware</source>
        <translation>韌體</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="277"/>
        <source>state</source>
        <translation>狀態</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="283"/>
        <source>name</source>
        <translation>名稱</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="289"/>
        <source>comm. group</source>
        <translation>通訊群組</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="294"/>
        <source>line format</source>
        <translation>通訊格式</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="311"/>
        <source>the port&apos;s</source>
        <translation>連接埠的</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="371"/>
        <source>1 drive found in %1 s</source>
        <translation>於 %1 s 內找到 1 台驅動器</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="372"/>
        <source>%1 drives found in %2 s</source>
        <translation>於 %2 s 內找到 %1 台驅動器</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="374"/>
        <source>; 1 possible duplicate machine number: %1</source>
        <translation>；1 個可能重複的機號：%1</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="376"/>
        <source>; %1 possible duplicate machine numbers: %2</source>
        <translation>；%1 個可能重複的機號：%2</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="380"/>
        <source>; answered, identification failed: %1 (add by hand)</source>
        <translation>；有回應但識別失敗：%1 (請手動加入)</translation>
    </message>
</context>
<context>
    <name>opentop::ScanDrives</name>
    <message>
        <location filename="../cli/ScanDrives.cpp" line="43"/>
        <source>%1 — variant unknown</source>
        <translation>%1 — 機型未知</translation>
    </message>
    <message>
        <location filename="../cli/ScanDrives.cpp" line="44"/>
        <source>the drive does not report its variant; give it with --variant %1=VARIANT (%2)</source>
        <translation>驅動器不回報機型；請以 --variant %1=VARIANT 指定 (%2)</translation>
    </message>
</context>
<context>
    <name>opentop::ScanFormats</name>
    <message>
        <location filename="../cli/ScanFormats.cpp" line="44"/>
        <source>Scanning machine numbers %1–%2 at %3 (--try-formats), %4 ms each…</source>
        <translation>以 %3 掃描機號 %1–%2（--try-formats），每個 %4 ms…</translation>
    </message>
    <message>
        <location filename="../cli/ScanFormats.cpp" line="71"/>
        <source>Machine number %1 answered at %2: it is asked at that format from now on (--drive-format %1=%3).</source>
        <translation>機號 %1 以 %2 回應：之後都以該格式詢問它（--drive-format %1=%3）。</translation>
    </message>
    <message>
        <location filename="../cli/ScanFormats.cpp" line="99"/>
        <source>hint: %1 If one is on this bus, give its machine number its format with --drive-format ID=BAUD:FORMAT (e.g. 7=9600:8E1), or scan with --try-formats: %2 more passes, %3 more requests, about %4 s more.</source>
        <translation>提示：%1 若匯流排上有這種驅動器，請用 --drive-format ID=BAUD:FORMAT（例如 7=9600:8E1）指定它的機號的格式，或用 --try-formats 掃描：多 %2 輪、多 %3 個要求，約多 %4 s。</translation>
    </message>
</context>
<context>
    <name>opentop::ScanProgress</name>
    <message>
        <location filename="../cli/ScanProgress.cpp" line="34"/>
        <source>scanning %1/%2 (%3 %), machine number %4, %5 found</source>
        <translation>掃描中 %1/%2 (%3 %)，機號 %4，已找到 %5 台</translation>
    </message>
    <message>
        <location filename="../cli/ScanProgress.cpp" line="49"/>
        <source>scan: %1 % (%2 of %3 machine numbers), %4 found</source>
        <translation>掃描：%1 % (%3 個機號中的第 %2 個)，已找到 %4 台</translation>
    </message>
    <message>
        <location filename="../cli/ScanProgress.cpp" line="60"/>
        <source>scan: machine number %1 answered, identification failed: retrying (%2 of %3)…</source>
        <translation>掃描：機號 %1 有回應，但識別失敗：重試中 (第 %2 次，共 %3 次)…</translation>
    </message>
</context>
<context>
    <name>opentop::SerialEntry</name>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="28"/>
        <source>Scan or type the serial number, then Enter</source>
        <translation>掃描或輸入序號後按 Enter</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="29"/>
        <source>Cancel unit (Esc)</source>
        <translation>取消此產品 (Esc)</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="73"/>
        <source>Serial number NOT taken: %1.</source>
        <translation>序號未被接受：%1。</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="102"/>
        <source>Serial %1 was NOT taken: unit %2 is being tested. Scan it again once its verdict shows.</source>
        <translation>序號 %1 未被接受：單元 %2 正在檢測中。請在其判定結果顯示後再掃描一次。</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="104"/>
        <location filename="../ui/eol/SerialEntry.cpp" line="106"/>
        <source>another</source>
        <translation>另一個單元</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="105"/>
        <source>A serial number was NOT taken: %1. Unit %2 is being tested.</source>
        <translation>序號未被接受：%1。單元 %2 正在檢測中。</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="122"/>
        <source>Per-unit value</source>
        <translation>單台數值</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="123"/>
        <source>Drive %1: %2 (%3–%4 %5)</source>
        <translation>驅動器 %1：%2 (%3–%4 %5)</translation>
    </message>
</context>
<context>
    <name>opentop::SerialLineFields</name>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="29"/>
        <source>Adapter switches itself</source>
        <translation>轉接器自行切換</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="30"/>
        <source>Auto (kernel, else RTS)</source>
        <translation>自動 (核心，否則 RTS)</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="31"/>
        <source>Kernel RS-485 mode</source>
        <translation>核心 RS-485 模式</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="32"/>
        <source>RTS from the program</source>
        <translation>由程式控制 RTS</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="34"/>
        <source>Who switches the RS-485 transceiver between sending and receiving. USB–RS-485 adapters do it themselves; on-board RS-485 ports need the driver&apos;s RS-485 mode (kernel) or RTS switched by the program. The status bar says what the driver accepted.</source>
        <translation>由誰切換 RS-485 收發器的傳送與接收。USB–RS-485 轉接器會自行切換；主機板內建的 RS-485 埠需要驅動程式的 RS-485 模式 (核心) 或由程式切換 RTS。狀態列會顯示驅動程式接受的設定。</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="38"/>
        <source>RS-485 d&amp;irection:</source>
        <translation>RS-485 收發方向(&amp;I)：</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="43"/>
        <source>high while sending</source>
        <translation>傳送時為高準位</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="44"/>
        <source>low while sending</source>
        <translation>傳送時為低準位</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="45"/>
        <source>The RTS level that enables the transceiver&apos;s driver</source>
        <translation>使收發器發送端致能的 RTS 準位</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="50"/>
        <source>delay </source>
        <translation>延遲 </translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="51"/>
        <source> µs</source>
        <translation> µs</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="52"/>
        <source>default delay</source>
        <translation>預設延遲</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="53"/>
        <source>Before and after sending. Default: the driver&apos;s own, or one character time from the program; the kernel rounds up to whole ms.</source>
        <translation>傳送前後的延遲。預設：使用驅動程式本身的延遲，或由程式使用 1 個字元時間；核心會進位到整數 ms。</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="58"/>
        <source>RTS le&amp;vel:</source>
        <translation>RTS 準位(&amp;V)：</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="62"/>
        <source>&amp;Low latency (no 16 ms hold-back in USB adapters)</source>
        <translation>低延遲 (USB 轉接器不再保留 16 ms)(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="65"/>
        <source>Asks the driver to pass received bytes on at once. Many USB–serial chips otherwise hold them for up to 16 ms, which slows scans and polling.</source>
        <translation>要求驅動程式立即轉交收到的位元組。否則許多 USB 轉序列晶片最多會保留 16 ms，使掃描與輪詢變慢。</translation>
    </message>
</context>
<context>
    <name>opentop::SerialLock</name>
    <message>
        <location filename="../model/session/SerialLock.cpp" line="39"/>
        <source>%1 = %2 prohibits configuration over the serial interface: OpenTOP may then no longer be able to change this drive&apos;s settings over the serial line it talks on. To undo it: write %1 = %3 again if the drive still accepts it; while it is not stored, switch the drive off and on; otherwise switch the controller to potentiometer/analog control, connect at 9600 bit/s, 8E1, address 1 and write %1 = %3 there.</source>
        <translation>%1 = %2 會禁止透過序列介面進行組態設定：之後 OpenTOP 可能無法再透過目前通訊的序列線路變更此驅動器的設定。復原方式：若驅動器仍接受，再次寫入 %1 = %3；尚未保存時，將驅動器斷電再上電；否則將控制器切換為可變電阻/類比控制，以 9600 bit/s、8E1、位址 1 連線，並在該連線下寫入 %1 = %3。</translation>
    </message>
</context>
<context>
    <name>opentop::SerialRule</name>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="65"/>
        <source>no serial number</source>
        <translation>無序號</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="67"/>
        <source>a serial number has at most %1 characters; this one has %2</source>
        <translation>序號最多 %1 個字元；此序號有 %2 個</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="71"/>
        <source>a serial number may not hold control characters, format characters or line breaks; character %1 is %2</source>
        <translation>序號不可包含控制字元、格式字元或換行；第 %1 個字元為 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="75"/>
        <source>serial number &quot;%1&quot; begins or ends with white space; a serial number is tested exactly as given</source>
        <translation>序號 &quot;%1&quot; 的開頭或結尾有空白；序號會完全依輸入內容檢測</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="85"/>
        <source>serial number &quot;%1&quot; does not match the recipe&apos;s serial pattern %2</source>
        <translation>序號 &quot;%1&quot; 不符合配方的序號格式 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="87"/>
        <source>serial number &quot;%1&quot; does not match the recipe&apos;s serial pattern %2 (e.g. %3)</source>
        <translation>序號 &quot;%1&quot; 不符合配方的序號格式 %2（例如 %3）</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="104"/>
        <source>&quot;serialPattern&quot; has %1 characters; at most %2 are allowed</source>
        <translation>&quot;serialPattern&quot; 有 %1 個字元；最多允許 %2 個</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="108"/>
        <source>&quot;serialPattern&quot; may not hold control characters, format characters or line breaks (no serial number holds one); character %1 is %2</source>
        <translation>&quot;serialPattern&quot; 不可包含控制字元、格式字元或換行（序號不會包含這些字元）；第 %1 個字元為 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="115"/>
        <source>&quot;serialPattern&quot; %1 is not a valid regular expression: %2 at character %3</source>
        <translation>&quot;serialPattern&quot; %1 不是有效的正規表示式：第 %3 個字元處 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="121"/>
        <source>&quot;serialPattern&quot; %1 cannot be matched against a whole serial number</source>
        <translation>&quot;serialPattern&quot; %1 無法與整個序號比對</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="127"/>
        <source>&quot;serialExample&quot; needs a &quot;serialPattern&quot; that it matches</source>
        <translation>&quot;serialExample&quot; 需要一個與其相符的 &quot;serialPattern&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="130"/>
        <source>&quot;serialExample&quot;: %1</source>
        <translation>&quot;serialExample&quot;：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="140"/>
        <source>any, at most %1 characters</source>
        <translation>任意，最多 %1 個字元</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="143"/>
        <source>%1 (e.g. %2)</source>
        <translation>%1（例如 %2）</translation>
    </message>
</context>
<context>
    <name>opentop::SetCommand</name>
    <message>
        <location filename="../cli/SetCommand.cpp" line="43"/>
        <source>Write parameters by name, validated, read back and verified</source>
        <translation>依名稱寫入參數，經檢查、回讀並驗證</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="53"/>
        <source>Write registers by address: ADDR=VALUE (repeatable; VALUE,VALUE... with --fc 16).</source>
        <translation>依位址寫入暫存器：ADDR=VALUE (可重複指定；搭配 --fc 16 時可寫 VALUE,VALUE...)。</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="54"/>
        <source>ADDR=VALUE</source>
        <translation>ADDR=VALUE</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="55"/>
        <source>Function code for --raw writes: 6 (default) or 16.</source>
        <translation>--raw 寫入使用的功能碼：6 (預設) 或 16。</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="55"/>
        <source>FC</source>
        <translation>FC</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="64"/>
        <source>error: usage: set ID NAME=VALUE... (e.g. set 1 spno2.accel=2.5), or set ID --raw ADDR=VALUE</source>
        <translation>錯誤：用法：set ID NAME=VALUE... (例如 set 1 spno2.accel=2.5)，或 set ID --raw ADDR=VALUE</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="76"/>
        <source>error: &quot;%1&quot; is not NAME=VALUE</source>
        <translation>錯誤：&quot;%1&quot; 不是 NAME=VALUE 格式</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="83"/>
        <location filename="../cli/SetCommand.cpp" line="92"/>
        <location filename="../cli/SetCommand.cpp" line="108"/>
        <source>error: %1</source>
        <translation>錯誤：%1</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="105"/>
        <location filename="../cli/SetCommand.cpp" line="117"/>
        <source>warning: %1</source>
        <translation>警告：%1</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="50"/>
        <source>Confirm commands that move a motor, reset, erase, initialise or store, and setting the serial configuration lock.</source>
        <translation>確認會使馬達運轉、重置、清除、初始化或保存的指令，以及序列組態鎖定的設定。</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="149"/>
        <source>next: %1</source>
        <translation>下一步：%1</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="151"/>
        <source>next: opentop-cli --baud %1 --parity %2 --stop-bits %3 ... (the factory line settings)</source>
        <translation>下一步：opentop-cli --baud %1 --parity %2 --stop-bits %3 ... (出廠通訊設定)</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="196"/>
        <source>Parameter</source>
        <translation>參數</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="196"/>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="196"/>
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="202"/>
        <source>written, verified</source>
        <translation>已寫入，已驗證</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="204"/>
        <source>written, not verified: %1</source>
        <translation>已寫入，未確認：%1</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="205"/>
        <source>written (command, not readable)</source>
        <translation>已寫入 (指令，不可讀取)</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="207"/>
        <source>not confirmed (%1): the drive may or may not hold it; &quot;get&quot; reads it back</source>
        <translation>未確認 (%1)：驅動器可能已保有此值，也可能沒有；可用 &quot;get&quot; 回讀</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="218"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="225"/>
        <source>note: the drive uses %1 from its next power-up on: switch the drive off and on, then connect with the new setting (--baud, --parity)</source>
        <translation>注意：驅動器自下次上電起使用 %1：請將驅動器斷電再上電，然後以新設定 (--baud、--parity) 連線</translation>
    </message>
</context>
<context>
    <name>opentop::SetRaw</name>
    <message>
        <location filename="../cli/SetRaw.cpp" line="30"/>
        <source>error: --fc for raw writes is 6 or 16</source>
        <translation>錯誤：raw 寫入的 --fc 為 6 或 16</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="56"/>
        <source>error: &quot;%1&quot; is not ADDR=VALUE (0x.. or decimal, 0–65535; several values, comma separated, only with --fc 16)</source>
        <translation>錯誤：&quot;%1&quot; 不是 ADDR=VALUE 格式 (0x.. 或十進位，0–65535；多個值以逗號分隔，僅限 --fc 16)</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="73"/>
        <source>error: 0x%1 is not a register the profile knows; add --yes to write it anyway; nothing was written</source>
        <translation>錯誤：0x%1 不是定義檔中的暫存器；若仍要寫入請加上 --yes；未寫入任何資料</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="83"/>
        <location filename="../cli/SetRaw.cpp" line="128"/>
        <source>error: %1; nothing was written</source>
        <translation>錯誤：%1；未寫入任何資料</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="84"/>
        <source>%1 is a %2 command; add --yes</source>
        <translation>%1 是 %2 指令；請加上 --yes</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="91"/>
        <source>error: the write covers part of %1; add --yes to write it anyway; nothing was written</source>
        <translation>錯誤：此寫入只涵蓋 %1 的一部分；若仍要寫入請加上 --yes；未寫入任何資料</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="141"/>
        <source>Address</source>
        <translation>位址</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="141"/>
        <source>Written</source>
        <translation>寫入值</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="141"/>
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="174"/>
        <source>written</source>
        <translation>已寫入</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="176"/>
        <source>written, verified</source>
        <translation>已寫入，已驗證</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="178"/>
        <source>written, but reads back differently</source>
        <translation>已寫入，但回讀值不同</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="181"/>
        <source>written (not readable back: %1)</source>
        <translation>已寫入 (無法回讀：%1)</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="193"/>
        <source>Also written to %1 (communication group); not read back: no parameter of the profile</source>
        <translation>也已寫入 %1 (通訊群組)；未回讀：不是定義檔中的參數</translation>
    </message>
</context>
<context>
    <name>opentop::SettingsWrite</name>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="29"/>
        <source>%1 is given twice (%2=%3 and %4); give each setting once; nothing written</source>
        <translation>%1 重複指定 (%2=%3 與 %4)；每項設定只能指定一次；未寫入任何資料</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="76"/>
        <source>%1 has no parameter &quot;%2&quot;; see &quot;opentop-cli params --family %1&quot;</source>
        <translation>%1 沒有參數 &quot;%2&quot;；請參閱 &quot;opentop-cli params --family %1&quot;</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="80"/>
        <source>%1 is read-only</source>
        <translation>%1 為唯讀</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="83"/>
        <source>%1 is a %2 command; add --yes to send it</source>
        <translation>%1 是 %2 指令；加上 --yes 才會送出</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="105"/>
        <source>cannot read %1 to check the values; nothing written</source>
        <translation>無法讀取 %1 以檢查數值；未寫入任何資料</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="157"/>
        <source>Add --yes to set it.</source>
        <translation>加上 --yes 才會設定。</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="229"/>
        <source>interrupted as it was sent</source>
        <translation>送出時已中斷</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="231"/>
        <source>not written (interrupted)</source>
        <translation>未寫入 (已中斷)</translation>
    </message>
</context>
<context>
    <name>opentop::ShiftPlan</name>
    <message>
        <location filename="../model/eol/ShiftPlan.cpp" line="30"/>
        <source>&quot;%1&quot; is not a time of day such as 06:00</source>
        <translation>&quot;%1&quot; 不是 06:00 這樣的時刻</translation>
    </message>
    <message>
        <location filename="../model/eol/ShiftPlan.cpp" line="35"/>
        <source>shift starts must be in order from the day&apos;s first: %1</source>
        <translation>班別開始時間必須從當天第一班起依序排列：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/ShiftPlan.cpp" line="42"/>
        <source>no shift start given; e.g. 06:00,14:00,22:00</source>
        <translation>未指定班別開始時間；例如 06:00,14:00,22:00</translation>
    </message>
</context>
<context>
    <name>opentop::ShortcutsDialog</name>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="63"/>
        <source>Main window</source>
        <translation>主視窗</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="36"/>
        <source>Everywhere, dialogs included</source>
        <translation>所有位置 (包含對話框)</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="37"/>
        <source>STOP ALL (stop every drive on the bus)</source>
        <translation>全部停止 (停止匯流排上的所有驅動器)</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="73"/>
        <source>Keyboard shortcuts</source>
        <translation>鍵盤快速鍵</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="77"/>
        <source>Where</source>
        <translation>適用範圍</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="77"/>
        <source>Command</source>
        <translation>指令</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="77"/>
        <source>Keys</source>
        <translation>按鍵</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="87"/>
        <source> or </source>
        <translation> 或 </translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="96"/>
        <source>STOP ALL&apos;s keys work in every window of the program, also while a dialog is open.</source>
        <translation>「全部停止」的按鍵在程式的每個視窗中都有效，開啟對話框時也一樣。</translation>
    </message>
</context>
<context>
    <name>opentop::SimApp</name>
    <message>
        <location filename="../sim/SimApp.cpp" line="77"/>
        <source>opentop-sim: %1@%2 talks %3 (its own line settings): it answers only frames sent in that format</source>
        <translation>opentop-sim：%1@%2 使用 %3（它自己的線路設定）：只回應以該格式送出的訊框</translation>
    </message>
    <message>
        <location filename="../sim/SimApp.cpp" line="83"/>
        <source>opentop-sim: warning: %1@%2 cannot use %3 %4 and will not answer</source>
        <translation>opentop-sim：警告：%1@%2 無法使用 %3 %4，將不會回應</translation>
    </message>
    <message>
        <location filename="../sim/SimApp.cpp" line="97"/>
        <source>opentop-sim: --defect %1:%2: no drive with machine number %1 on the bus %3</source>
        <translation>opentop-sim：--defect %1:%2：匯流排 %3 上沒有機號 %1 的驅動器</translation>
    </message>
    <message>
        <location filename="../sim/SimApp.cpp" line="104"/>
        <source>opentop-sim: --defect %1 (%2@%1): %3</source>
        <translation>opentop-sim：--defect %1 (%2@%1)：%3</translation>
    </message>
    <message>
        <location filename="../sim/SimApp.cpp" line="138"/>
        <source>the port is unplugged already</source>
        <translation>連接埠已拔除</translation>
    </message>
    <message>
        <location filename="../sim/SimApp.cpp" line="140"/>
        <source>unplugged</source>
        <translation>已拔除</translation>
    </message>
    <message>
        <location filename="../sim/SimApp.cpp" line="167"/>
        <source>error: %1</source>
        <translation>錯誤：%1</translation>
    </message>
</context>
<context>
    <name>opentop::SimBackdoor</name>
    <message>
        <location filename="../sim/SimBackdoor.cpp" line="17"/>
        <source>usage: set ID ADDR VALUE [fc]</source>
        <translation>用法：set ID ADDR VALUE [fc]</translation>
    </message>
    <message>
        <location filename="../sim/SimBackdoor.cpp" line="18"/>
        <source>usage: get ID ADDR [fc]</source>
        <translation>用法：get ID ADDR [fc]</translation>
    </message>
    <message>
        <location filename="../sim/SimBackdoor.cpp" line="21"/>
        <source>address must be 0..0xFFFF, got &apos;%1&apos;</source>
        <translation>位址必須為 0..0xFFFF，收到 &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../sim/SimBackdoor.cpp" line="27"/>
        <source>function must be 3, 4 or 6 (write-only), got &apos;%1&apos;</source>
        <translation>功能碼必須為 3、4 或 6 (僅寫入)，收到 &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../sim/SimBackdoor.cpp" line="40"/>
        <source>value must be -32768..65535, got &apos;%1&apos;</source>
        <translation>值必須為 -32768..65535，收到 &apos;%1&apos;</translation>
    </message>
</context>
<context>
    <name>opentop::SimBackend</name>
    <message>
        <location filename="../sim/SimBackend.cpp" line="24"/>
        <source>no simulated bus</source>
        <translation>沒有模擬匯流排</translation>
    </message>
    <message>
        <location filename="../sim/SimBackend.cpp" line="47"/>
        <source>the simulated bus is not open</source>
        <translation>模擬匯流排未開啟</translation>
    </message>
    <message>
        <location filename="../sim/SimBackend.cpp" line="53"/>
        <source>the simulated adapter was unplugged</source>
        <translation>模擬轉接器已拔除</translation>
    </message>
    <message>
        <location filename="../sim/SimBackend.cpp" line="85"/>
        <source>interrupted while waiting</source>
        <translation>等待中被中斷</translation>
    </message>
    <message>
        <location filename="../sim/SimBackend.cpp" line="92"/>
        <source>no reply within %1 ms</source>
        <translation>%1 ms 內無回應</translation>
    </message>
</context>
<context>
    <name>opentop::SimBus</name>
    <message>
        <location filename="../sim/SimBus.cpp" line="38"/>
        <source>unknown device type &apos;%1&apos;; known: %2</source>
        <translation>未知的裝置類型 &apos;%1&apos;；已知：%2</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="66"/>
        <location filename="../sim/SimBus.cpp" line="74"/>
        <source>%1@%2{%3}: %4</source>
        <translation>%1@%2{%3}：%4</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="107"/>
        <source>no device with machine number %1</source>
        <translation>沒有機號 %1 的裝置</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="118"/>
        <source>baud=%1: this drive talks at %2 bit/s</source>
        <translation>baud=%1：此驅動器的鮑率為 %2 bit/s</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="126"/>
        <source>format=%1: this drive offers %2 only</source>
        <translation>format=%1：此驅動器只提供 %2</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="132"/>
        <source>this simulated drive has no line settings of its own</source>
        <translation>此模擬驅動器沒有自己的線路設定</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="145"/>
        <source>machine number %1 is outside 1..247</source>
        <translation>機號 %1 超出 1..247</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="146"/>
        <source>machine number %1 is used twice</source>
        <translation>機號 %1 重複使用</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="317"/>
        <source>no device with machine number %1 (bus: %2)</source>
        <translation>沒有機號 %1 的裝置 (匯流排：%2)</translation>
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
        <translation>指令：
  help                      本說明
  list                      裝置及其狀態
  alarm ID CODE             觸發警報 (DBU)
  warning ID CODE           觸發警告，CODE 0 解除警告 (DBU)
  load ID PERCENT           增加負載率 (DBU) 或電流 (DC)
  vr ID RPM                 Ext-VR 速度，供 SPno1 使用 (DBU)
  input ID MASK             輸入端子：X0..X3 (DBU)，SQ1 SQ2 DE (DC)
  ignore-stop ID on|off     回應停止指令但繼續運轉 (DBU)
  power-cycle ID            將裝置斷電再上電
  get ID ADDR [fc]          顯示暫存器 (fc 3、4，僅寫入者用 6)
  set ID ADDR VALUE [fc]    不經任何檢查直接變更暫存器
  defect ID DEFECT[,...]    為驅動器加入缺陷 (參閱 --help)，例如
                            defect 3 max_speed=800 或 defect 4 alarm=0x07@2s
  defect ID clear           清除驅動器的所有缺陷
  defects                   各驅動器的缺陷
  motor ID [KEY=VALUE ...]  顯示或變更 DC 控制器的馬達與負載，
                            例如 motor 7 load=0.05 inertia=3e-4 (參閱 --motor)
  unplug                    在用戶端仍連接時關閉 pty (模擬拔除轉接器)
  replug                    在同一符號連結後建立新的 pty
  quit                      停止模擬器</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="66"/>
        <source>bye</source>
        <translation>再見</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="71"/>
        <source>%1 needs the pty server (--pty)</source>
        <translation>%1 需要 pty 伺服器 (--pty)</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="82"/>
        <source>, defects: %1</source>
        <translation>，缺陷：%1</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="95"/>
        <source>no drive has defects</source>
        <translation>沒有驅動器有缺陷</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="101"/>
        <source>unknown command &apos;%1&apos;; type help for the list</source>
        <translation>未知指令 &apos;%1&apos;；輸入 help 查看清單</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="105"/>
        <source>usage: %1 ID ...; ID is a machine number on the bus (%2)</source>
        <translation>用法：%1 ID ...；ID 為匯流排上的機號 (%2)</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="111"/>
        <source>&apos;%1&apos; is not a machine number; the bus has %2</source>
        <translation>&apos;%1&apos; 不是機號；匯流排上有 %2</translation>
    </message>
</context>
<context>
    <name>opentop::SimDefectSpec</name>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="45"/>
        <source>firmware=MAJOR.MINOR (e.g. firmware=1.4), max_speed=N (e.g. max_speed=800), stall, load=+N, load=-N or load=xF (e.g. load=+40, load=x1.5), alarm=CODE@TIME (e.g. alarm=0x07@1500ms, alarm=overload@2s; DC: alarm=stall@1s), nostick=PARAM, nostore=PARAM (a parameter name or register address, e.g. nostick=spno2.speed, nostore=0x0081), turnaround=MS (e.g. turnaround=14), clear</source>
        <translation>firmware=MAJOR.MINOR (例如 firmware=1.4)、max_speed=N (例如 max_speed=800)、stall、load=+N、load=-N 或 load=xF (例如 load=+40、load=x1.5)、alarm=CODE@TIME (例如 alarm=0x07@1500ms、alarm=overload@2s；DC：alarm=stall@1s)、nostick=PARAM、nostore=PARAM (參數名稱或暫存器位址，例如 nostick=spno2.speed、nostore=0x0081)、turnaround=MS (例如 turnaround=14)、clear</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="123"/>
        <source>unknown defect &quot;%1&quot;; allowed: %2</source>
        <translation>未知的缺陷 &quot;%1&quot;；允許：%2</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="126"/>
        <source>&quot;%1&quot; needs a value: %2=...</source>
        <translation>&quot;%1&quot; 需要值：%2=...</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="128"/>
        <source>&quot;%1&quot; takes no value; write %2</source>
        <translation>&quot;%1&quot; 不接受值；請寫成 %2</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="141"/>
        <source>firmware=%1: write MAJOR.MINOR with each 0..255, e.g. firmware=1.4</source>
        <translation>firmware=%1：請寫成 MAJOR.MINOR，各為 0..255，例如 firmware=1.4</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="148"/>
        <source>max_speed=%1: write a whole number 0..%2, e.g. max_speed=800</source>
        <translation>max_speed=%1：請寫 0..%2 的整數，例如 max_speed=800</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="158"/>
        <source>load=%1: a factor is x0.1..x10, e.g. load=x1.5</source>
        <translation>load=%1：倍率為 x0.1..x10，例如 load=x1.5</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="163"/>
        <source>load=%1: an offset is -200..+200, e.g. load=+40</source>
        <translation>load=%1：偏移量為 -200..+200，例如 load=+40</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="166"/>
        <source>load=%1: write load=+N, load=-N (an offset) or load=xF (a factor), e.g. load=+40 or load=x1.5</source>
        <translation>load=%1：請寫成 load=+N、load=-N (偏移量) 或 load=xF (倍率)，例如 load=+40 或 load=x1.5</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="175"/>
        <source>alarm=%1: write alarm=CODE@TIME, e.g. alarm=0x07@1500ms or alarm=overload@2s</source>
        <translation>alarm=%1：請寫成 alarm=CODE@TIME，例如 alarm=0x07@1500ms 或 alarm=overload@2s</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="180"/>
        <source>alarm=%1: the time after the start is 0..3600 s, written 1500ms, 1.5s or 1500 (ms)</source>
        <translation>alarm=%1：啟動後的時間為 0..3600 s，可寫成 1500ms、1.5s 或 1500 (ms)</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="189"/>
        <source>turnaround=%1: write the answer delay in ms, 0..1000, e.g. turnaround=14</source>
        <translation>turnaround=%1：請寫入回應延遲 (ms)，範圍 0..1000，例如 turnaround=14</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="194"/>
        <source>%1=%2: name a parameter (e.g. spno2.speed) or a register address (e.g. 0x1102)</source>
        <translation>%1=%2：請指定參數 (例如 spno2.speed) 或暫存器位址 (例如 0x1102)</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="210"/>
        <source>no defect given; allowed: %1</source>
        <translation>未指定缺陷；允許：%1</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="216"/>
        <source>empty item in &quot;%1&quot;</source>
        <translation>&quot;%1&quot; 中有空項目</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="234"/>
        <source>&quot;%1&quot;: write ID:DEFECT[,DEFECT...] with ID the machine number 1..247, e.g. 3:firmware=1.4 or 5:max_speed=800,load=+40</source>
        <translation>&quot;%1&quot;：請寫成 ID:DEFECT[,DEFECT...]，ID 為機號 1..247，例如 3:firmware=1.4 或 5:max_speed=800,load=+40</translation>
    </message>
</context>
<context>
    <name>opentop::SimDefects</name>
    <message>
        <location filename="../sim/SimDefects.cpp" line="71"/>
        <source>a %1 reports no firmware version</source>
        <translation>%1 不回報韌體版本</translation>
    </message>
    <message>
        <location filename="../sim/SimDefects.cpp" line="83"/>
        <source>alarm=%1: a %2 has no alarm codes; its protection is the stall stop: write alarm=stall@TIME</source>
        <translation>alarm=%1：%2 沒有警報代碼；其保護功能為堵轉停止：請寫成 alarm=stall@TIME</translation>
    </message>
    <message>
        <location filename="../sim/SimDefects.cpp" line="99"/>
        <source>alarm=%1: not an alarm of a %2; allowed: %3</source>
        <translation>alarm=%1：不是 %2 的警報；允許：%3</translation>
    </message>
    <message>
        <location filename="../sim/SimDefects.cpp" line="110"/>
        <source>%1=%2: no writable parameter of a %3 has this name or address; e.g. %4</source>
        <translation>%1=%2：%3 沒有此名稱或位址的可寫入參數；例如 %4</translation>
    </message>
</context>
<context>
    <name>opentop::SimDevice</name>
    <message>
        <location filename="../sim/SimDevice.cpp" line="248"/>
        <source>missing command</source>
        <translation>缺少指令</translation>
    </message>
    <message>
        <location filename="../sim/SimDevice.cpp" line="257"/>
        <source>slave %1 power cycled</source>
        <translation>從站 %1 已斷電重新上電</translation>
    </message>
    <message>
        <location filename="../sim/SimDevice.cpp" line="299"/>
        <source>usage: defect ID DEFECT[,DEFECT...] or defect ID clear; DEFECT: %1</source>
        <translation>用法：defect ID DEFECT[,DEFECT...] 或 defect ID clear；DEFECT：%1</translation>
    </message>
    <message>
        <location filename="../sim/SimDevice.cpp" line="306"/>
        <source>slave %1 defects: %2</source>
        <translation>從站 %1 的缺陷：%2</translation>
    </message>
    <message>
        <location filename="../sim/SimDevice.cpp" line="308"/>
        <source>none</source>
        <translation>無</translation>
    </message>
    <message>
        <location filename="../sim/SimDevice.cpp" line="313"/>
        <source>&apos;%1&apos; is not supported by a %2 device</source>
        <translation>%2 裝置不支援 &apos;%1&apos;</translation>
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
        <translation>用法：opentop-sim --devices SPEC [選項]
在虛擬終端機上或以 Modbus TCP 閘道器形式模擬 Modbus RTU 驅動器。

  --devices SPEC     裝置與機號，例如 dbu200@1,dbu400@150,dcpid@7
                     驅動器自己的線路設定寫在大括號內，例如
                     dcpid@7{format=8E1,baud=19200}：只接收以該格式送出的
                     訊框（pty 會傳遞用戶端的速率與同位元）
  --pty [PATH]       在 pty 上提供服務 (預設)；PATH：同時建立此符號連結
  --tcp HOST:PORT    提供 Modbus TCP 服務 (HOST 預設為 127.0.0.1，PORT 0：任意)
  --baud N           用於線路時序與裝置設定的鮑率 (19200)；驅動器只接收
                     自己速率與同位元的訊框
  --parity N|E|O     線路同位元 (N)：沒有自己設定的驅動器
                     設為 --baud 與 --parity
  --wire-timing      依實際線路在 --baud 下的速度延遲回應
  --turnaround MS    搭配 --wire-timing 的裝置回轉時間 (2)
  --half-duplex      搭配 --wire-timing：請求與線路上的回應重疊時
                     兩者皆會錯亂，距回應 3.5 個字元以內的請求會遺失
  --faults LIST      例如 drop=0.02,crc=0.01,late=0.01,busy=0.01,late_ms=1000
  --seed N           故障注入的亂數種子 (1)
  --defect ID:LIST   驅動器 ID 的缺陷 (可重複指定)，LIST 可包含：
                       firmware=MAJOR.MINOR  識別時回報此版本
                       max_speed=N           馬達在 N 飽和 (DBU 為 r/min，
                                             DC 為換相次數/s)，負載偏高
                       stall                 馬達不轉動，負載偏高
                       load=+N|-N|xF         負載率 (DC：電流 %) 偏移或縮放
                       alarm=CODE@TIME       運轉 TIME 後發生警報，例如
                                             0x07@1500ms、overload@2s (DC：stall@1s)
                       nostick=PARAM         寫入有回應確認，但保留舊值
                       nostore=PARAM         下次斷電重新上電後值遺失
                     例如 --defect 3:firmware=1.4 --defect 5:max_speed=800,load=+40
  --motor LIST       DC 控制器的馬達與負載，例如 inertia=2e-4,load=0.05；
                     supply (V)、resistance (ohm)、no_load (全責任週期時的 1/s)、
                     commutations (每轉換相次數)、inertia (kg m2)、viscous
                     (N m s/rad)、coulomb (N m)、load (N m)、gate (ms)、tacho (V s)
  --quiet            不在 stderr 輸出訊框追蹤
  --lang CODE        訊息的語言：en, zh_TW, zh_CN, ko, ja
  --help             本說明
  --version          程式版本

輸出 &quot;pty: PATH&quot; (以及 &quot;tcp: HOST:PORT&quot;)，然後輸出 &quot;ready&quot;。從 stdin 讀取主控台
指令 (輸入 help)。收到 SIGINT、SIGTERM 或 quit 時停止。
</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="92"/>
        <source>--lang needs a language code such as ko</source>
        <translation>--lang 需要語言代碼，例如 ko</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="95"/>
        <source>--devices needs a device list such as dbu200@1,dcpid@7</source>
        <translation>--devices 需要裝置清單，例如 dbu200@1,dcpid@7</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="104"/>
        <source>--tcp needs HOST:PORT, e.g. 127.0.0.1:5020</source>
        <translation>--tcp 需要 HOST:PORT，例如 127.0.0.1:5020</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="110"/>
        <source>--tcp needs HOST:PORT with PORT 0..65535, got &apos;%1&apos;</source>
        <translation>--tcp 需要 HOST:PORT，PORT 為 0..65535，收到 &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="122"/>
        <source>--baud must be one of %1, got &apos;%2&apos;</source>
        <translation>--baud 必須是 %1 其中之一，收到 &apos;%2&apos;</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="129"/>
        <source>--parity must be N, E or O, got &apos;%1&apos;</source>
        <translation>--parity 必須為 N、E 或 O，收到 &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="139"/>
        <source>--turnaround must be 0..1000 ms, got &apos;%1&apos;</source>
        <translation>--turnaround 必須為 0..1000 ms，收到 &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="143"/>
        <source>--faults needs a list such as drop=0.02,crc=0.01</source>
        <translation>--faults 需要清單，例如 drop=0.02,crc=0.01</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="147"/>
        <source>--faults: %1</source>
        <translation>--faults：%1</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="153"/>
        <source>--seed must be a whole number 0..4294967295, got &apos;%1&apos;</source>
        <translation>--seed 必須是 0..4294967295 的整數，收到 &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="157"/>
        <source>--defect needs ID:DEFECT[,DEFECT...], e.g. 3:firmware=1.4; DEFECT: %1</source>
        <translation>--defect 需要 ID:DEFECT[,DEFECT...]，例如 3:firmware=1.4；DEFECT：%1</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="164"/>
        <source>--defect: %1</source>
        <translation>--defect：%1</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="168"/>
        <source>--motor needs a list such as inertia=2e-4,load=0.05</source>
        <translation>--motor 需要清單，例如 inertia=2e-4,load=0.05</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="172"/>
        <source>--motor: %1</source>
        <translation>--motor：%1</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="177"/>
        <source>unknown argument &apos;%1&apos;; options: --devices, --pty, --tcp, --baud, --parity, --wire-timing, --half-duplex, --turnaround, --faults, --seed, --defect, --motor, --quiet, --help, --version</source>
        <translation>未知引數 &apos;%1&apos;；選項：--devices, --pty, --tcp, --baud, --parity, --wire-timing, --half-duplex, --turnaround, --faults, --seed, --defect, --motor, --quiet, --help, --version</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="186"/>
        <source>--devices SPEC is required, e.g. --devices dbu200@1,dcpid@7</source>
        <translation>必須指定 --devices SPEC，例如 --devices dbu200@1,dcpid@7</translation>
    </message>
</context>
<context>
    <name>opentop::SpeedDisplay</name>
    <message>
        <location filename="../model/profile/SpeedDisplay.cpp" line="90"/>
        <source>speed display settings not known: %1</source>
        <translation>速度顯示設定未知：%1</translation>
    </message>
    <message>
        <location filename="../model/profile/SpeedDisplay.cpp" line="92"/>
        <source>speed display unit code %1 is unknown (0–3)</source>
        <translation>速度顯示單位代碼 %1 未知 (0–3)</translation>
    </message>
    <message>
        <location filename="../model/profile/SpeedDisplay.cpp" line="94"/>
        <source>speed display ratios must be positive (reduction %1, increase %2)</source>
        <translation>速度顯示的比率必須為正數 (減速比 %1，增速比 %2)</translation>
    </message>
    <message>
        <location filename="../model/profile/SpeedDisplay.cpp" line="98"/>
        <source>speed display decimals %1 outside 0–3</source>
        <translation>速度顯示小數位數 %1 超出 0–3</translation>
    </message>
</context>
<context>
    <name>opentop::SpeedUnitsPage</name>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="36"/>
        <source>Speed display</source>
        <translation>速度顯示</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="52"/>
        <source>Unit shown</source>
        <translation>顯示單位</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="53"/>
        <source>&amp;Unit:</source>
        <translation>單位(&amp;U)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="54"/>
        <source>Reduction r&amp;atio:</source>
        <translation>減速比(&amp;A)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="55"/>
        <source>&amp;Increasing ratio:</source>
        <translation>增速比(&amp;I)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="60"/>
        <source>Linear speed</source>
        <translation>線速度</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="61"/>
        <source>Roller diameter for &amp;yd/min:</source>
        <translation>yd/min 用滾輪直徑(&amp;Y)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="62"/>
        <source>Roller diameter for &amp;m/min:</source>
        <translation>m/min 用滾輪直徑(&amp;M)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="65"/>
        <source>Time for a distance</source>
        <translation>行經距離所需時間</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="66"/>
        <source>Roller &amp;diameter:</source>
        <translation>滾輪直徑(&amp;D)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="67"/>
        <source>Dis&amp;tance:</source>
        <translation>距離(&amp;T)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="68"/>
        <source>Distance u&amp;nit:</source>
        <translation>距離單位(&amp;N)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="69"/>
        <source>Time &amp;format (min = m:ss):</source>
        <translation>時間格式 (min = m:ss)(&amp;F)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="72"/>
        <source>Display</source>
        <translation>顯示</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="73"/>
        <source>D&amp;ecimals (0–3):</source>
        <translation>小數位數 (0–3)(&amp;E)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="74"/>
        <source>U&amp;pdate time:</source>
        <translation>更新時間(&amp;P)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="78"/>
        <source>Display corrections (motor r/min)</source>
        <translation>顯示修正量 (馬達 r/min)</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="79"/>
        <source>ro-&amp;0, 250 (300)–500 r/min:</source>
        <translation>ro-0，250 (300)–500 r/min(&amp;0)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="79"/>
        <source>ro-&amp;1, 501–1000 r/min:</source>
        <translation>ro-1，501–1000 r/min(&amp;1)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="80"/>
        <source>ro-&amp;2, 1001–2000 r/min:</source>
        <translation>ro-2，1001–2000 r/min(&amp;2)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="80"/>
        <source>ro-&amp;3, 2001–3000 r/min:</source>
        <translation>ro-3，2001–3000 r/min(&amp;3)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="85"/>
        <source>Preview of the drive&apos;s display</source>
        <translation>驅動器顯示預覽</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="88"/>
        <source> r/min</source>
        <translation> r/min</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="89"/>
        <source>Motor speed for the preview</source>
        <translation>預覽用的馬達速度</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="90"/>
        <source>Motor &amp;speed:</source>
        <translation>馬達速度(&amp;S)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="93"/>
        <source>Forward</source>
        <translation>正轉</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="94"/>
        <source>Reverse (shown with “-”)</source>
        <translation>反轉 (以「-」顯示)</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="95"/>
        <source>Dire&amp;ction:</source>
        <translation>方向(&amp;C)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="110"/>
        <source>Drive shows:</source>
        <translation>驅動器顯示：</translation>
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
        <translation>驅動器顯示 %1 %2</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="259"/>
        <source>Section ro-%1: correction %2 r/min, shaft speed %3 r/min.</source>
        <translation>區段 ro-%1：修正量 %2 r/min，軸速度 %3 r/min。</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="264"/>
        <source>%1 has more digits than the drive&apos;s %2-digit display can show.</source>
        <translation>%1 的位數超過驅動器 %2 位數顯示器可顯示的範圍。</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="268"/>
        <source>Computed %1 %2; the %3-digit display drops the decimals that do not fit.</source>
        <translation>計算值為 %1 %2；%3 位數顯示器會捨去放不下的小數位。</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="275"/>
        <source>Includes edits not yet written.</source>
        <translation>包含尚未寫入的變更。</translation>
    </message>
</context>
<context>
    <name>opentop::SpnoSelector</name>
    <message>
        <location filename="../ui/run/SpnoSelector.cpp" line="29"/>
        <source>The running data that Select running data sends; &quot;The drive now&quot; shows the running data the drive runs</source>
        <translation>「選擇運轉資料」所送出的運轉資料；「驅動器目前狀態」顯示驅動器正在使用的運轉資料</translation>
    </message>
    <message>
        <location filename="../ui/run/SpnoSelector.cpp" line="70"/>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <location filename="../ui/run/SpnoSelector.cpp" line="84"/>
        <source>The running data that Select running data sends. The drive reported SPno%1 at %2; &quot;The drive now&quot; shows what it runs now.</source>
        <translation>「選擇運轉資料」所送出的運轉資料。驅動器於 %2 回報 SPno%1；「驅動器目前狀態」顯示其目前的運轉資料。</translation>
    </message>
</context>
<context>
    <name>opentop::StaleLook</name>
    <message>
        <location filename="../ui/widgets/StaleLook.cpp" line="52"/>
        <source>not read yet</source>
        <translation>尚未讀取</translation>
    </message>
    <message>
        <location filename="../ui/widgets/StaleLook.cpp" line="55"/>
        <source>updated %1 s ago</source>
        <translation>%1 s 前更新</translation>
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
        <translation>%1 的通訊群組</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="182"/>
        <source>It runs with running data SPno%1</source>
        <translation>將以運轉資料 SPno%1 運轉</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="184"/>
        <source> at %1</source>
        <translation> (速度 %1)</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="187"/>
        <source>, direction %1 (the direction command sent since)</source>
        <translation>，方向 %1 (依之後送出的方向指令)</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="188"/>
        <source>, direction %1</source>
        <translation>，方向 %1</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="191"/>
        <source>Which running data it runs with could not be read.</source>
        <translation>無法讀取將以哪一組運轉資料運轉。</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="194"/>
        <source>Warning: %1</source>
        <translation>警告：%1</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="196"/>
        <source>The start also reaches machine number(s) %1: %2.</source>
        <translation>啟動指令也會送達機號 %1：%2。</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="202"/>
        <source>Not read: %1.</source>
        <translation>未讀取：%1。</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="219"/>
        <source>This starts the motor of machine number %1.</source>
        <translation>這會啟動機號 %1 的馬達。</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="221"/>
        <source>This sets the speed command of machine number %1 to %2: its motor runs.</source>
        <translation>這會將機號 %1 的速度指令設為 %2：其馬達將運轉。</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="225"/>
        <source>Make sure that nobody is near the machine and that it may move. STOP ALL stops every drive at any time.</source>
        <translation>請確認機台附近沒有人員，且機台可以動作。「全部停止」可隨時停止所有驅動器。</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="228"/>
        <source>You are asked once per drive while the program runs.</source>
        <translation>程式執行期間，每台驅動器只會詢問一次。</translation>
    </message>
</context>
<context>
    <name>opentop::StationAccess</name>
    <message>
        <location filename="../model/access/StationAccess.cpp" line="74"/>
        <location filename="../model/access/StationAccess.cpp" line="127"/>
        <source>the results database is not open</source>
        <translation>結果資料庫未開啟</translation>
    </message>
    <message>
        <location filename="../model/access/StationAccess.cpp" line="105"/>
        <source>the results database is not open, so nobody can be identified</source>
        <translation>結果資料庫未開啟，因此無法確認任何人的身分</translation>
    </message>
    <message>
        <location filename="../model/access/StationAccess.cpp" line="160"/>
        <source>the station&apos;s users are being read from the results database</source>
        <translation>正在從結果資料庫讀取工站使用者</translation>
    </message>
    <message>
        <location filename="../model/access/StationAccess.cpp" line="161"/>
        <source>the station&apos;s users cannot be read: %1</source>
        <translation>無法讀取工站使用者：%1</translation>
    </message>
    <message>
        <location filename="../model/access/StationAccess.cpp" line="166"/>
        <source>nobody is logged in: log in with your user name and password (or badge)</source>
        <translation>無人登入：請以使用者名稱和密碼（或識別證）登入</translation>
    </message>
    <message>
        <location filename="../model/access/StationAccess.cpp" line="170"/>
        <source>the recipe&apos;s approval is being read from the results database</source>
        <translation>正在從結果資料庫讀取配方核准</translation>
    </message>
</context>
<context>
    <name>opentop::StationActions</name>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="24"/>
        <source>Reset alarm and test again</source>
        <translation>重置警報並重新測試</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="25"/>
        <source>Technician: test again…</source>
        <translation>技術員：重新測試…</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="50"/>
        <source>A technician may allow unit %1 to be tested again.</source>
        <translation>技術員可允許單元 %1 重新測試。</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="57"/>
        <source>Resetting the alarm of machine number %1…</source>
        <translation>正在重置機號 %1 的警報…</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="66"/>
        <source>The alarm is not cleared; nothing was started:
%1</source>
        <translation>警報未解除；未開始任何測試：
%1</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="76"/>
        <source>reset the alarm</source>
        <translation>警報重置</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="82"/>
        <source>serial %1</source>
        <translation>序號 %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="91"/>
        <source>test serial %1 again</source>
        <translation>重新測試序號 %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="105"/>
        <source>An alarm was active on machine number %1 before the test: nothing was written. Reset it (the drive&apos;s own reset; one that needs a power cycle says so) and the unit is tested again.</source>
        <translation>測試前機號 %1 已有警報發生：未寫入任何資料。請重置警報（使用驅動器本身的重置功能；需要斷電重新上電的警報會另行提示），產品即會重新測試。</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="134"/>
        <source>(no name)</source>
        <translation>（未填姓名）</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="136"/>
        <source>Test again</source>
        <translation>重新測試</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="137"/>
        <source>%1

Test unit %2 again? It is recorded as allowed by %3.</source>
        <translation>%1

要重新測試產品 %2 嗎？將記錄為由 %3 許可。</translation>
    </message>
</context>
<context>
    <name>opentop::StationAlarmReset</name>
    <message>
        <location filename="../model/eol/StationAlarmReset.cpp" line="56"/>
        <source>machine number %1: not connected to a bus</source>
        <translation>機號 %1：未連線至匯流排</translation>
    </message>
    <message>
        <location filename="../model/eol/StationAlarmReset.cpp" line="57"/>
        <source>machine number %1 is not a position of the recipe</source>
        <translation>機號 %1 不是配方中的位置</translation>
    </message>
    <message>
        <location filename="../model/eol/StationAlarmReset.cpp" line="65"/>
        <source>machine number %1: %2 drives have no alarm reset command; switch the drive off and on</source>
        <translation>機號 %1：%2 驅動器沒有警報重置指令；請將驅動器斷電再重新上電</translation>
    </message>
    <message>
        <location filename="../model/eol/StationAlarmReset.cpp" line="75"/>
        <source>machine number %1: %2</source>
        <translation>機號 %1：%2</translation>
    </message>
</context>
<context>
    <name>opentop::StationFigures</name>
    <message>
        <location filename="../ui/eol/StationFigures.cpp" line="27"/>
        <source>This shift: no figures yet (%1)</source>
        <translation>本班別：尚無數據（%1）</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationFigures.cpp" line="28"/>
        <source>results database not read</source>
        <translation>尚未讀取結果資料庫</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationFigures.cpp" line="31"/>
        <source>This shift: tested %1 · passed %2 · failed %3 · station errors %4 · %5</source>
        <translation>本班別：已測 %1 · 合格 %2 · 不合格 %3 · 工站錯誤 %4 · %5</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationFigures.cpp" line="39"/>
        <source>This station, this recipe version, since %1 (read %2). The same figures: %3</source>
        <translation>本工站、此配方版本，自 %1 起（讀取於 %2）。以指令查看相同數據：%3</translation>
    </message>
</context>
<context>
    <name>opentop::StationLogin</name>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="38"/>
        <source>operator</source>
        <translation>作業員</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="40"/>
        <source>Operator:</source>
        <translation>作業員:</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="44"/>
        <source>user name</source>
        <translation>使用者名稱</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="49"/>
        <source>password</source>
        <translation>密碼</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="51"/>
        <source>Log in</source>
        <translation>登入</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="52"/>
        <source>Log in:</source>
        <translation>登入:</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="57"/>
        <source>Log out</source>
        <translation>登出</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="104"/>
        <source>Not logged in: %1</source>
        <translation>未登入：%1</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="125"/>
        <source>Logged in: &lt;b&gt;%1&lt;/b&gt; (%2)</source>
        <translation>已登入：&lt;b&gt;%1&lt;/b&gt;（%2）</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="131"/>
        <source>No users set up: anyone can run, edit and leave; set up users with opentop-cli eol user add</source>
        <translation>尚未設定使用者：任何人都可執行、編輯和離開；請以 opentop-cli eol user add 設定使用者</translation>
    </message>
</context>
<context>
    <name>opentop::StationNotice</name>
    <message numerus="yes">
        <location filename="../ui/eol/StationNotice.cpp" line="31"/>
        <source>%n result(s) kept on this station, not yet in the results database: %1. They are sent by themselves, in order, when it answers.</source>
        <translation>
            <numerusform>本工作站保存了 %n 筆結果，尚未存入結果資料庫：%1。資料庫回應後會依序自動送出。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/eol/StationNotice.cpp" line="35"/>
        <source>it does not answer</source>
        <translation>資料庫沒有回應</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationNotice.cpp" line="38"/>
        <source>Unit %1 (begun %2) was not finished: the station stopped during its test. It is recorded as interrupted; test it again.</source>
        <translation>單元 %1（開始於 %2）未完成：工作站在檢測中停止。已記錄為「中斷」，請重新檢測。</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationNotice.cpp" line="44"/>
        <source>Making the recipe&apos;s drives safe: reading each, stopping one left running, giving control back to their inputs…</source>
        <translation>正在使配方的驅動器進入安全狀態：逐一讀取、停止仍在運轉者、將控制權交還其輸入端子…</translation>
    </message>
</context>
<context>
    <name>opentop::StationRecipe</name>
    <message>
        <location filename="../model/station/StationRecipe.cpp" line="68"/>
        <source>this recipe takes per-unit values from a CSV file: open it first</source>
        <translation>此配方的單台數值取自 CSV 檔：請先開啟該檔</translation>
    </message>
</context>
<context>
    <name>opentop::StationResults</name>
    <message>
        <location filename="../model/station/StationResults.cpp" line="63"/>
        <source>opening the results database</source>
        <translation>正在開啟結果資料庫</translation>
    </message>
    <message>
        <location filename="../model/station/StationResults.cpp" line="65"/>
        <source>NOT REACHABLE (%1); trying again by itself</source>
        <translation>無法連線（%1）；自動重試中</translation>
    </message>
    <message>
        <location filename="../model/station/StationResults.cpp" line="66"/>
        <source>no results database</source>
        <translation>無結果資料庫</translation>
    </message>
    <message>
        <location filename="../model/station/StationResults.cpp" line="72"/>
        <source>the result of unit %1 (%2) is not in the results database yet: nothing is tested until it is. The station tries again by itself (%3)</source>
        <translation>產品 %1 的結果（%2）尚未寫入結果資料庫：寫入前不會進行任何測試。工作站會自動重試（%3）</translation>
    </message>
    <message>
        <location filename="../model/station/StationResults.cpp" line="77"/>
        <source>the results database is being opened; try again in a moment</source>
        <translation>正在開啟結果資料庫；請稍後再試</translation>
    </message>
    <message>
        <location filename="../model/station/StationResults.cpp" line="79"/>
        <source>the results database is not open; nothing is tested unless it is recorded</source>
        <translation>結果資料庫未開啟；無法記錄結果時不會進行測試</translation>
    </message>
    <message>
        <location filename="../model/station/StationResults.cpp" line="80"/>
        <source>the results database cannot be reached (%1); nothing is tested unless it is recorded. The station tries again by itself.</source>
        <translation>無法連線至結果資料庫（%1）；無法記錄結果時不會進行測試。工作站會自動重試。</translation>
    </message>
</context>
<context>
    <name>opentop::StationSafeState</name>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="44"/>
        <source>%1: no answer (%2); not checked</source>
        <translation>%1：沒有回應（%2）；未檢查</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="49"/>
        <source>%1 was RUNNING (%2)</source>
        <translation>%1 原本在運轉（%2）</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="52"/>
        <source>: stopped by the station</source>
        <translation>：已由工作站停止</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="55"/>
        <source>%1 stopped</source>
        <translation>%1 已停止</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="58"/>
        <source>; control given back to its inputs (I/O priority)</source>
        <translation>；控制權已交還其輸入端子（I/O 優先）</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="99"/>
        <source>drive %1</source>
        <translation>驅動器 %1</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="100"/>
        <source>drive %1 (%2)</source>
        <translation>驅動器 %1（%2）</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="104"/>
        <source>the recipe&apos;s family %1 is not known</source>
        <translation>配方的機種系列 %1 未知</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="148"/>
        <source>whether its motor runs cannot be read</source>
        <translation>無法讀取馬達是否在運轉</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="159"/>
        <source>it runs from its input terminals (I/O priority): not the station&apos;s to stop; stop it at the machine</source>
        <translation>它由輸入端子控制運轉（I/O 優先）：不由工作站停止；請在機台上停止</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="184"/>
        <source>the stop was refused: %1</source>
        <translation>停止命令被拒絕：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="198"/>
        <source>NOT CONFIRMED STOPPED: %1</source>
        <translation>未確認停止：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="240"/>
        <source>control could not be given back to its inputs: %1</source>
        <translation>無法將控制權交還其輸入端子：%1</translation>
    </message>
</context>
<context>
    <name>opentop::StationYield</name>
    <message>
        <location filename="../model/eol/StationYield.cpp" line="48"/>
        <source>the results database is not open</source>
        <translation>結果資料庫未開啟</translation>
    </message>
</context>
<context>
    <name>opentop::StatusLight</name>
    <message>
        <location filename="../ui/widgets/StatusLight.cpp" line="30"/>
        <source>Status not known yet</source>
        <translation>狀態尚未得知</translation>
    </message>
    <message>
        <location filename="../ui/widgets/StatusLight.cpp" line="44"/>
        <source>Status light %1: %2</source>
        <translation>狀態燈 %1：%2</translation>
    </message>
    <message>
        <location filename="../ui/widgets/StatusLight.cpp" line="48"/>
        <source>The drive&apos;s manual: %1</source>
        <translation>驅動器手冊：%1</translation>
    </message>
</context>
<context>
    <name>opentop::StepMeasure</name>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="85"/>
        <source>%1: the drive stopped answering: %2</source>
        <translation>%1：驅動器停止回應：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="93"/>
        <source>%1: the drive raised an alarm while running</source>
        <translation>%1：驅動器在運轉中發生警報</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="113"/>
        <source>%1: %2 %3</source>
        <translation>%1：%2 %3</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="132"/>
        <source>%1: the drive has no speed to wait for</source>
        <translation>%1：驅動器沒有可等待的速度</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="155"/>
        <source>time to reach speed</source>
        <translation>到達速度時間</translation>
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
        <translation>未知</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="169"/>
        <source>%1: did not reach %2 %3 ±%4 %3 within %5 s (last read %6 %3)</source>
        <translation>%1：%5 s 內未達到 %2 %3 ±%4 %3 (最後讀取值 %6 %3)</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="170"/>
        <source>its target</source>
        <translation>其目標值</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="205"/>
        <location filename="../model/eol/StepMeasure.cpp" line="220"/>
        <location filename="../model/eol/StepMeasure.cpp" line="240"/>
        <location filename="../model/eol/StepMeasure.cpp" line="301"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="215"/>
        <source>%1: the drive reports no alarms</source>
        <translation>%1：此驅動器沒有可讀取的警報狀態</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="225"/>
        <source>alarms raised</source>
        <translation>發生的警報</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="227"/>
        <source>%1: the drive has an alarm</source>
        <translation>%1：驅動器有警報</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="234"/>
        <source>%1: nothing to read</source>
        <translation>%1：無可讀取的項目</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="248"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="251"/>
        <source>%1: %2 reads &quot;%3&quot;, expected &quot;%4&quot;</source>
        <translation>%1：%2 讀取為 &quot;%3&quot;，預期為 &quot;%4&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="259"/>
        <source>%1: %2 reads %3 %4, %5</source>
        <translation>%1：%2 讀取為 %3 %4，%5</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="299"/>
        <source>time to stop</source>
        <translation>停止所需時間</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="303"/>
        <source>%1: stopped after %2 s, allowed at most %3 s</source>
        <translation>%1：%2 s 後停止，最多允許 %3 s</translation>
    </message>
</context>
<context>
    <name>opentop::StepMetrics</name>
    <message>
        <location filename="../model/tuning/StepMetrics.cpp" line="18"/>
        <source>the step has no height (from = to)</source>
        <translation>步階幅度為零 (from = to)</translation>
    </message>
    <message>
        <location filename="../model/tuning/StepMetrics.cpp" line="19"/>
        <source>too few samples after the step (%1)</source>
        <translation>步階後的取樣點過少 (%1)</translation>
    </message>
</context>
<context>
    <name>opentop::StepTest</name>
    <message>
        <location filename="../model/tuning/StepTest.cpp" line="39"/>
        <source>a step test runs forward from one speed to another: from and to must differ and be 0 or more</source>
        <translation>步階測試是從一個速度正轉到另一個速度：起始與目標速度必須不同，且須為 0 以上</translation>
    </message>
    <message>
        <location filename="../model/tuning/StepTest.cpp" line="47"/>
        <source>%1 %2 is beyond the test&apos;s speed limit %3 %2</source>
        <translation>%1 %2 超過測試的速度限值 %3 %2</translation>
    </message>
    <message>
        <location filename="../model/tuning/StepTest.cpp" line="55"/>
        <source>Running to %1 %2</source>
        <translation>正在運轉至 %1 %2</translation>
    </message>
    <message>
        <location filename="../model/tuning/StepTest.cpp" line="88"/>
        <source>Step to %1 %2</source>
        <translation>步階至 %1 %2</translation>
    </message>
</context>
<context>
    <name>opentop::StepTestPanel</name>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="22"/>
        <source>Run step test…</source>
        <translation>執行步階測試…</translation>
    </message>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="29"/>
        <source>From:</source>
        <translation>從：</translation>
    </message>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="30"/>
        <source>To:</source>
        <translation>到：</translation>
    </message>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="31"/>
        <source>Record time:</source>
        <translation>記錄時間：</translation>
    </message>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="32"/>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="75"/>
        <source>Enter two different speeds of 0 %1 or more.</source>
        <translation>請輸入兩個不同且不小於 0 %1 的速度。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="79"/>
        <source>Enter a record time of 100–60000 ms.</source>
        <translation>請輸入 100–60000 ms 的記錄時間。</translation>
    </message>
</context>
<context>
    <name>opentop::StopAllButton</name>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="16"/>
        <location filename="../ui/run/StopAllButton.cpp" line="92"/>
        <source>STOP ALL</source>
        <translation>全部停止</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="20"/>
        <source>Stops every drive on the bus at once (%1), then checks that each has stopped.</source>
        <translation>立即停止匯流排上的所有驅動器 (%1)，然後確認每台均已停止。</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="87"/>
        <source>STOPPING…</source>
        <translation>停止中…</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="103"/>
        <source>The stop broadcast to %1 drives FAILED: %2</source>
        <translation>對 %1 驅動器的停止廣播「失敗」：%2</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="106"/>
        <source>Stop sent to every drive. No drives are known on the bus, so none was checked; scan the bus to have them checked.</source>
        <translation>已對所有驅動器送出停止指令。匯流排上沒有已知的驅動器，因此未確認任何驅動器；請掃描匯流排以便確認。</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="114"/>
        <source>Machine number %1: stopped after %2 s</source>
        <translation>機號 %1：%2 s 後停止</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="117"/>
        <source>Machine number %1: STILL RUNNING (%2)</source>
        <translation>機號 %1：仍在運轉 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="120"/>
        <source>Machine number %1: NO ANSWER, not confirmed stopped</source>
        <translation>機號 %1：無回應，未確認停止</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="135"/>
        <source>STOP ALL: the stop broadcast FAILED</source>
        <translation>全部停止：停止廣播「失敗」</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="136"/>
        <source>STOP ALL: stop sent, no drive checked</source>
        <translation>全部停止：已送出停止指令，未確認任何驅動器</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="137"/>
        <source>STOP ALL: every drive stopped</source>
        <translation>全部停止：所有驅動器均已停止</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="138"/>
        <source>STOP ALL: not every drive is confirmed stopped</source>
        <translation>全部停止：並非所有驅動器都已確認停止</translation>
    </message>
</context>
<context>
    <name>opentop::StopAllCommand</name>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="54"/>
        <source>Broadcast stop to every drive, then confirm each has stopped (needs --yes)</source>
        <translation>對所有驅動器廣播停止指令，然後確認每台均已停止 (需要 --yes)</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="60"/>
        <source>Send the stop broadcast.</source>
        <translation>送出停止廣播。</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="62"/>
        <source>Machine numbers to confirm, e.g. 1,2,5-7 (default on a simulated bus: its drives).</source>
        <translation>要確認的機號，例如 1,2,5-7 (模擬匯流排預設為其所有驅動器)。</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="63"/>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="72"/>
        <source>error: usage: %1 (no other arguments)</source>
        <translation>錯誤：用法：%1 (不接受其他引數)</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="80"/>
        <source>error: --ids: %1</source>
        <translation>錯誤：--ids：%1</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="87"/>
        <source>Would broadcast to every drive on the bus (machine number 0, no reply):</source>
        <translation>將廣播至匯流排上的所有驅動器 (機號 0，無回應)：</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="91"/>
        <source>Add --yes to send it.</source>
        <translation>加上 --yes 才會送出。</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="119"/>
        <source>Broadcast %1: %2</source>
        <translation>廣播 %1：%2</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="120"/>
        <source>Broadcast %1 FAILED: %2: %3</source>
        <translation>廣播 %1「失敗」：%2：%3</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="124"/>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="124"/>
        <source>Family</source>
        <translation>系列</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="124"/>
        <source>State</source>
        <translation>狀態</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="124"/>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="124"/>
        <source>After</source>
        <translation>經過時間</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="124"/>
        <source>Detail</source>
        <translation>詳細資料</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="156"/>
        <source>Only the broadcast was sent: drives do not answer a broadcast, so nothing confirms that they stopped. To confirm, pass the machine numbers on this bus, e.g. --ids 1,2,5-7 (opentop-cli scan finds them).</source>
        <translation>僅送出廣播：驅動器不會回應廣播，因此無法確認是否已停止。若要確認，請指定此匯流排上的機號，例如 --ids 1,2,5-7 (可用 opentop-cli scan 尋找)。</translation>
    </message>
</context>
<context>
    <name>opentop::StopConfirmer</name>
    <message>
        <location filename="../model/run/StopConfirmer.cpp" line="80"/>
        <source>%1 drives report neither running state nor speed</source>
        <translation>%1 驅動器不回報運轉狀態或速度</translation>
    </message>
    <message>
        <location filename="../model/run/StopConfirmer.cpp" line="111"/>
        <source>%1 is %2: the drive does not take motion commands over the bus (it follows its input terminals)</source>
        <translation>%1 為 %2：驅動器不接受來自匯流排的運轉指令 (由輸入端子控制)</translation>
    </message>
    <message>
        <location filename="../model/run/StopConfirmer.cpp" line="185"/>
        <source>still at %1 after %2 s</source>
        <translation>%2 s 後仍為 %1</translation>
    </message>
    <message>
        <location filename="../model/run/StopConfirmer.cpp" line="187"/>
        <source>still running after %1 s</source>
        <translation>%1 s 後仍在運轉</translation>
    </message>
</context>
<context>
    <name>opentop::TcpSimServer</name>
    <message>
        <location filename="../sim/TcpSimServer.cpp" line="36"/>
        <source>cannot listen on %1:%2: %3</source>
        <translation>無法在 %1:%2 上監聽：%3</translation>
    </message>
</context>
<context>
    <name>opentop::TerminalLamps</name>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="184"/>
        <source>n/a</source>
        <translation>不適用</translation>
    </message>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="185"/>
        <source>%1: not applicable (%2)</source>
        <translation>%1：不適用 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="188"/>
        <source>?</source>
        <translation>?</translation>
    </message>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="189"/>
        <source>%1: not read</source>
        <translation>%1：未讀取</translation>
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
        <translation>%1 為 ON</translation>
    </message>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="194"/>
        <source>%1 is OFF</source>
        <translation>%1 為 OFF</translation>
    </message>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="196"/>
        <source>%1 (last state read, not live)</source>
        <translation>%1 (最後讀取的狀態，非即時)</translation>
    </message>
</context>
<context>
    <name>opentop::TestRunPanel</name>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="48"/>
        <source>&lt;b&gt;Test run of machine number %1&lt;/b&gt;</source>
        <translation>&lt;b&gt;機號 %1 試運轉&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="54"/>
        <source>Machine number %1 has not been identified as a drive of a known family; a test run needs one.</source>
        <translation>機號 %1 尚未識別為已知系列的驅動器；試運轉需要已識別的驅動器。</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="31"/>
        <source>&amp;Start</source>
        <translation>啟動(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="32"/>
        <source>S&amp;top</source>
        <translation>停止(&amp;T)</translation>
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
        <translation>保持(&amp;H)</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="36"/>
        <source>&amp;Free</source>
        <translation>釋放(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="54"/>
        <source>Se&amp;lect running data</source>
        <translation>選擇運轉資料(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="67"/>
        <source>Return to &amp;I/O priority</source>
        <translation>恢復為 I/O 優先(&amp;I)</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="69"/>
        <source>Give run, stop, direction and speed selection back to the drive&apos;s input terminals</source>
        <translation>將運轉、停止、方向與速度選擇交還給驅動器的輸入端子</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="161"/>
        <source>Cannot read %1 to check that the drive takes motion commands: %2</source>
        <translation>無法讀取 %1 以確認驅動器是否接受運轉指令：%2</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="197"/>
        <source>Not started: the variant of %1 was not given.</source>
        <translation>未啟動：未指定 %1 的機型。</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="204"/>
        <source>Reading what the start will run…</source>
        <translation>正在讀取啟動後的運轉內容…</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="220"/>
        <source>Start the motor</source>
        <translation>啟動馬達</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="234"/>
        <source>Sending %1…</source>
        <translation>正在送出 %1…</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="263"/>
        <source>Not every drive of its communication group runs: see below.</source>
        <translation>通訊群組中並非所有驅動器都在運轉：請見下方。</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="281"/>
        <source>Sent: %1</source>
        <translation>已送出：%1</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="350"/>
        <source>Polling is paused: the controller brakes the motor %1 s after the last frame it receives (%2). Resume polling to keep the motor running.</source>
        <translation>輪詢已暫停：控制器會在收到最後一個訊框 %1 s 後煞車停止馬達 (%2)。請恢復輪詢以保持馬達運轉。</translation>
    </message>
</context>
<context>
    <name>opentop::TrafficDescriber</name>
    <message>
        <location filename="../model/traffic/TrafficDescriber.cpp" line="150"/>
        <source>broadcast: every drive executes it</source>
        <translation>廣播：所有驅動器都會執行</translation>
    </message>
    <message>
        <location filename="../model/traffic/TrafficDescriber.cpp" line="159"/>
        <source>to %1 (group parent: also %2)</source>
        <translation>送往 %1 (群組母站：%2 也會執行)</translation>
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
        <translation>時間</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="125"/>
        <source>Direction</source>
        <translation>方向</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="127"/>
        <source>Drive</source>
        <translation>驅動器</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="129"/>
        <source>Function</source>
        <translation>功能碼</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="131"/>
        <source>Bytes</source>
        <translation>位元組</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="133"/>
        <source>Meaning</source>
        <translation>意義</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="135"/>
        <source>Error</source>
        <translation>錯誤</translation>
    </message>
</context>
<context>
    <name>opentop::TrafficLogView</name>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="43"/>
        <source>&amp;Errors only</source>
        <translation>僅顯示錯誤(&amp;E)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="44"/>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="171"/>
        <source>&amp;Pause</source>
        <translation>暫停(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="53"/>
        <source>All drives</source>
        <translation>所有驅動器</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="55"/>
        <source>All</source>
        <translation>全部</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="56"/>
        <source>Tx (requests)</source>
        <translation>Tx (請求)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="57"/>
        <source>Rx (replies)</source>
        <translation>Rx (回應)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="58"/>
        <source>Events (no reply)</source>
        <translation>事件 (無回應)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="62"/>
        <source>&amp;Clear</source>
        <translation>清除(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="64"/>
        <source>&amp;Save…</source>
        <translation>儲存(&amp;S)…</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="67"/>
        <source>&amp;Drive:</source>
        <translation>驅動器(&amp;D)：</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="69"/>
        <source>Di&amp;rection:</source>
        <translation>方向(&amp;R)：</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="83"/>
        <source>Frames</source>
        <translation>訊框數</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="112"/>
        <source>Drive</source>
        <translation>驅動器</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="112"/>
        <source>Requests</source>
        <translation>請求數</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="112"/>
        <source>Replies</source>
        <translation>回應數</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="112"/>
        <source>Timeouts</source>
        <translation>逾時數</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="112"/>
        <source>CRC errors</source>
        <translation>CRC 錯誤</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="113"/>
        <source>Exceptions</source>
        <translation>例外</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="113"/>
        <source>Wrong/garbled</source>
        <translation>錯誤/錯亂</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="113"/>
        <source>Mean ms</source>
        <translation>平均 ms</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="113"/>
        <source>Late replies</source>
        <translation>延遲回應</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="113"/>
        <source>Max ms</source>
        <translation>最大 ms</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="115"/>
        <source>Statistics per drive</source>
        <translation>各驅動器統計</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="119"/>
        <source>Frames that answered nothing asked at the time: a reply to an earlier request that came too late, discarded and never taken as a value</source>
        <translation>不是回應當時請求的訊框：先前請求的回應遲到，已丟棄，從未當作數值使用</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="171"/>
        <source>&amp;Resume</source>
        <translation>繼續(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="242"/>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="320"/>
        <source>Broadcast</source>
        <translation>廣播</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="242"/>
        <source>Drive %1</source>
        <translation>驅動器 %1</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="309"/>
        <source>%1 addresses did not answer: %2</source>
        <translation>%1 個位址未回應：%2</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="311"/>
        <source>No reply from machine numbers %1</source>
        <translation>機號 %1 無回應</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="352"/>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="357"/>
        <source>Save traffic log</source>
        <translation>儲存通訊記錄</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="352"/>
        <source>Text files (*.txt)</source>
        <translation>文字檔 (*.txt)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="358"/>
        <source>Could not save %1: %2</source>
        <translation>無法儲存 %1：%2</translation>
    </message>
</context>
<context>
    <name>opentop::Transport</name>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="16"/>
        <source>No serial port given: enter a device such as /dev/ttyUSB0 or COM3.</source>
        <translation>未指定序列埠：請輸入裝置，例如 /dev/ttyUSB0 或 COM3。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="20"/>
        <source>Baud rate %1 is not supported: use 1200–115200 (e.g. 9600, 19200, 38400, 57600, 115200).</source>
        <translation>不支援鮑率 %1：請使用 1200–115200 (例如 9600、19200、38400、57600、115200)。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="26"/>
        <source>Parity &apos;%1&apos; is not supported: use N (none), E (even) or O (odd).</source>
        <translation>不支援同位元 &apos;%1&apos;：請使用 N (無)、E (偶同位) 或 O (奇同位)。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="31"/>
        <source>%1 data bits are not supported: use 7 or 8.</source>
        <translation>不支援 %1 個資料位元：請使用 7 或 8。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="35"/>
        <source>%1 stop bits are not supported: use 1 or 2.</source>
        <translation>不支援 %1 個停止位元：請使用 1 或 2。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="39"/>
        <source>Byte timeout %1 ms is not allowed: use 1–10000 ms, or 0 to derive it from the baud rate.</source>
        <translation>不允許位元組逾時 %1 ms：請使用 1–10000 ms，或設為 0 依鮑率計算。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="45"/>
        <source>RS-485 mode %1 is not supported: use off, auto, kernel or rts.</source>
        <translation>不支援 RS-485 模式 %1：請使用 off、auto、kernel 或 rts。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="52"/>
        <source>Line format of machine number %1: %2 Use machine numbers 1–247.</source>
        <translation>機號 %1 的通訊格式：%2 請使用機號 1–247。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="60"/>
        <source>RTS delay %1 µs is not allowed: use 0–%2 µs (0: the driver&apos;s or libmodbus&apos; own).</source>
        <translation>不允許 RTS 延遲 %1 µs：請使用 0–%2 µs (0：使用驅動程式或 libmodbus 本身的延遲)。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="69"/>
        <source>No host given: enter the gateway&apos;s address, e.g. 192.168.1.10.</source>
        <translation>未指定主機：請輸入閘道器位址，例如 192.168.1.10。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="73"/>
        <source>TCP port %1 is not allowed: use 1–65535 (Modbus TCP uses 502).</source>
        <translation>不允許 TCP 連接埠 %1：請使用 1–65535 (Modbus TCP 使用 502)。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="80"/>
        <source>No simulated devices given: use a list such as dbu200@1,dcpid@7.</source>
        <translation>未指定模擬裝置：請使用清單，例如 dbu200@1,dcpid@7。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="86"/>
        <source>Timeout %1 ms is not allowed: use 10–10000 ms.</source>
        <translation>不允許逾時 %1 ms：請使用 10–10000 ms。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="90"/>
        <source>%1 retries are not allowed: use 0–10.</source>
        <translation>不允許重試 %1 次：請使用 0–10。</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="56"/>
        <source>Vendor name</source>
        <translation>廠商名稱</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="58"/>
        <source>Product code</source>
        <translation>產品代碼</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="60"/>
        <source>Revision</source>
        <translation>版次</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="62"/>
        <source>Vendor URL</source>
        <translation>廠商網址</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="64"/>
        <source>Product name</source>
        <translation>產品名稱</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="66"/>
        <source>Model name</source>
        <translation>型號名稱</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="68"/>
        <source>User application name</source>
        <translation>使用者應用程式名稱</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="70"/>
        <source>Object 0x%1</source>
        <translation>物件 0x%1</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="26"/>
        <source>Cannot open %1: %2</source>
        <translation>無法開啟 %1：%2</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="89"/>
        <source>read twice: a read of the same length was unanswered, and the first reply could have been its late answer</source>
        <translation>讀取兩次：同樣長度的讀取尚未得到回應，第一個回應可能是它的延遲回應</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="102"/>
        <source>replies disagree: late answers to earlier reads are likely</source>
        <translation>回應不一致：很可能是先前讀取的延遲回應</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="115"/>
        <location filename="../transport/ModbusClientWorker.cpp" line="373"/>
        <source>%1 is not open</source>
        <translation>%1 未開啟</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="160"/>
        <source>send failed</source>
        <translation>傳送失敗</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="186"/>
        <source>interrupted while waiting</source>
        <translation>等待中被中斷</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="190"/>
        <location filename="../transport/MockBackend.cpp" line="101"/>
        <source>no reply within %1 ms</source>
        <translation>%1 ms 內無回應</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="226"/>
        <source>another reply followed: this one may have answered an earlier request</source>
        <translation>之後又收到另一個回應：此回應可能是對先前請求的回應</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="253"/>
        <source>a drive&apos;s own line format needs a serial port; a Modbus TCP gateway sets its line itself</source>
        <translation>驅動器自己的通訊格式需要序列埠；Modbus TCP 閘道器自行設定它的線路</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="269"/>
        <source>cannot switch the line to %1: %2</source>
        <translation>無法把線路切換到 %1：%2</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="312"/>
        <source>no reply within %1 ms (a late reply to an earlier request was discarded)</source>
        <translation>%1 ms 內無回應（先前請求的延遲回應已丟棄）</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="334"/>
        <location filename="../transport/RtuFrame.cpp" line="140"/>
        <source>reply from slave %1, expected %2</source>
        <translation>回應來自從站 %1，預期為 %2</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusContext.cpp" line="140"/>
        <location filename="../transport/RtuBackend.cpp" line="191"/>
        <location filename="../transport/TcpBackend.cpp" line="112"/>
        <source>reply incomplete</source>
        <translation>回應不完整</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusContext.cpp" line="144"/>
        <location filename="../transport/RtuFrame.cpp" line="133"/>
        <source>CRC mismatch</source>
        <translation>CRC 不符</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="344"/>
        <location filename="../transport/RtuBackend.cpp" line="198"/>
        <location filename="../transport/TcpBackend.cpp" line="118"/>
        <source>receive failed</source>
        <translation>接收失敗</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="362"/>
        <source>late reply discarded: complete %1 ms after the request, where an answer needs at least %2 ms on the wire</source>
        <translation>已丟棄延遲回應：請求後 %1 ms 即接收完畢，而回應在線路上至少需要 %2 ms</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="378"/>
        <source> (connection closed)</source>
        <translation> (連線已關閉)</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="393"/>
        <source>stale bytes discarded before sending</source>
        <translation>傳送前已捨棄殘留位元組</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="440"/>
        <source>late bytes discarded after an error</source>
        <translation>錯誤後已捨棄延遲到達的位元組</translation>
    </message>
    <message>
        <location filename="../transport/MockBackend.cpp" line="57"/>
        <source>mock is not open</source>
        <translation>mock 未開啟</translation>
    </message>
    <message>
        <location filename="../transport/ModbusBackend.cpp" line="39"/>
        <source>→ %1 bytes</source>
        <translation>→ %1 位元組</translation>
    </message>
    <message>
        <location filename="../transport/ModbusBackend.cpp" line="51"/>
        <source>echo %1 = %2</source>
        <translation>回傳 %1 = %2</translation>
    </message>
    <message>
        <location filename="../transport/ModbusBackend.cpp" line="54"/>
        <source>echo %1 ×%2</source>
        <translation>回傳 %1 ×%2</translation>
    </message>
    <message>
        <location filename="../transport/ModbusClientWorker.cpp" line="220"/>
        <location filename="../transport/ModbusClientWorker.cpp" line="239"/>
        <source>cancelled before sending</source>
        <translation>傳送前已取消</translation>
    </message>
    <message>
        <location filename="../transport/ModbusClientWorker.cpp" line="285"/>
        <source>cannot open %1</source>
        <translation>無法開啟 %1</translation>
    </message>
    <message>
        <location filename="../transport/ModbusClientWorker.cpp" line="327"/>
        <source>client closed</source>
        <translation>用戶端已關閉</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="142"/>
        <source>Slave address %1 is not allowed: use 1–247, or 0 to broadcast a write.</source>
        <translation>不允許從站位址 %1：請使用 1–247，或以 0 廣播寫入。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="147"/>
        <source>Function code 0x%1 is not allowed: use 0x01–0x7F.</source>
        <translation>不允許功能碼 0x%1：請使用 0x01–0x7F。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="151"/>
        <source>Timeout %1 ms is not allowed: use 10–10000 ms, or -1 for the default.</source>
        <translation>不允許逾時 %1 ms：請使用 10–10000 ms，或以 -1 使用預設值。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="156"/>
        <source>%1 retries are not allowed: use 0–10, or -1 for the default.</source>
        <translation>不允許重試 %1 次：請使用 0–10，或以 -1 使用預設值。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="169"/>
        <source>Function 0x%1 cannot be broadcast: only functions 06h and 10h (writes) may be sent to machine number 0; use slave address 1–247.</source>
        <translation>功能碼 0x%1 無法廣播：只有功能碼 06h 與 10h (寫入) 可送往機號 0；請使用從站位址 1–247。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="176"/>
        <source>Function code 0x%1 must be sent as a raw request.</source>
        <translation>功能碼 0x%1 必須以原始請求送出。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="180"/>
        <source>Raw request data of %1 bytes is too long: at most %2 bytes.</source>
        <translation>原始請求資料 %1 位元組過長：最多 %2 位元組。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="193"/>
        <source>Cannot read %1 registers at once: use 1–125 registers.</source>
        <translation>無法一次讀取 %1 個暫存器：請使用 1–125 個暫存器。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="200"/>
        <source>Write single register needs exactly 1 value, not %1.</source>
        <translation>寫入單一暫存器需要恰好 1 個值，而非 %1 個。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="206"/>
        <source>Cannot write %1 registers at once: use 1–123 registers.</source>
        <translation>無法一次寫入 %1 個暫存器：請使用 1–123 個暫存器。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="211"/>
        <source>%1 values given for %2 registers.</source>
        <translation>為 %2 個暫存器指定了 %1 個值。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="220"/>
        <source>Registers %1 ×%2 run past the last address 0xFFFF.</source>
        <translation>暫存器 %1 ×%2 超出最後位址 0xFFFF。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="231"/>
        <source>device identification code %1 object %2</source>
        <translation>裝置識別 代碼 %1 物件 %2</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="239"/>
        <source>raw %1 %2</source>
        <translation>原始 %1 %2</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="243"/>
        <source>read %1 %2 ×%3</source>
        <translation>讀取 %1 %2 ×%3</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="247"/>
        <source>write %1 %2 = %3</source>
        <translation>寫入 %1 %2 = %3</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="250"/>
        <source>write %1 %2 ×%3 = %4</source>
        <translation>寫入 %1 %2 ×%3 = %4</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="256"/>
        <source>broadcast %1</source>
        <translation>廣播 %1</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="11"/>
        <source>ok</source>
        <translation>OK</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="13"/>
        <source>timeout</source>
        <translation>逾時</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="15"/>
        <source>CRC error</source>
        <translation>CRC 錯誤</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="17"/>
        <source>reply from wrong slave</source>
        <translation>錯誤從站的回應</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="19"/>
        <source>exception</source>
        <translation>例外</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="21"/>
        <source>malformed reply</source>
        <translation>格式錯誤的回應</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="23"/>
        <source>port error</source>
        <translation>連接埠錯誤</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="25"/>
        <source>not connected</source>
        <translation>未連線</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="27"/>
        <source>invalid request</source>
        <translation>無效請求</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="29"/>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="38"/>
        <source>Illegal function</source>
        <translation>非法功能碼</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="40"/>
        <source>Illegal data address</source>
        <translation>非法資料位址</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="42"/>
        <source>Illegal data value</source>
        <translation>非法資料值</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="44"/>
        <source>Slave device failure</source>
        <translation>從站裝置故障</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="46"/>
        <source>Acknowledge (processing)</source>
        <translation>確認 (處理中)</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="48"/>
        <source>Slave device busy</source>
        <translation>從站裝置忙碌</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="50"/>
        <source>Negative acknowledge</source>
        <translation>否定確認</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="52"/>
        <source>Memory parity error</source>
        <translation>記憶體同位錯誤</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="54"/>
        <source>Gateway path unavailable</source>
        <translation>閘道器路徑無法使用</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="56"/>
        <source>Gateway target device failed to respond</source>
        <translation>閘道器目標裝置未回應</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="60"/>
        <source>Prohibited action</source>
        <translation>禁止的動作</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="62"/>
        <source>Undefined error</source>
        <translation>未定義的錯誤</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="64"/>
        <source>Unknown exception</source>
        <translation>未知例外</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="74"/>
        <source>exception %1 %2</source>
        <translation>例外 %1 %2</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="79"/>
        <source>timeout after %1 attempts</source>
        <translation>嘗試 %1 次後逾時</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="81"/>
        <source>timeout (no reply)</source>
        <translation>逾時 (無回應)</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="89"/>
        <source> (%1 attempts)</source>
        <translation> (嘗試 %1 次)</translation>
    </message>
    <message>
        <location filename="../transport/PortLock.cpp" line="22"/>
        <source>%1 is in use by another program; close it first.</source>
        <translation>%1 正被其他程式使用；請先關閉該程式。</translation>
    </message>
    <message>
        <location filename="../transport/PortLock.cpp" line="27"/>
        <source>another program</source>
        <translation>其他程式</translation>
    </message>
    <message>
        <location filename="../transport/PortLock.cpp" line="29"/>
        <source>%1 is in use by %2 (PID %3); close it first.</source>
        <translation>%1 正被 %2 (PID %3) 使用；請先關閉該程式。</translation>
    </message>
    <message>
        <location filename="../transport/RtuBackend.cpp" line="127"/>
        <source>: your user may not open serial ports. Add it to the dialout group with
    sudo usermod -aG dialout $USER
then log out and in again (the group applies to new sessions only).</source>
        <translation>：您的使用者帳號無權開啟序列埠。請以下列指令將其加入 dialout 群組
    sudo usermod -aG dialout $USER
然後登出再重新登入 (群組設定僅對新的登入工作階段生效)。</translation>
    </message>
    <message>
        <location filename="../transport/RtuBackend.cpp" line="134"/>
        <source> (the device may not support this parity; ptys need N)</source>
        <translation> (裝置可能不支援此同位元；pty 需使用 N)</translation>
    </message>
    <message>
        <location filename="../transport/RtuBackend.cpp" line="169"/>
        <source>reply announces %1 bytes, more than an RTU frame holds</source>
        <translation>回應宣告 %1 位元組，超過 RTU 訊框的容量</translation>
    </message>
    <message>
        <location filename="../transport/RtuBackend.cpp" line="190"/>
        <source>no reply</source>
        <translation>無回應</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="127"/>
        <source>reply too short (%1 bytes)</source>
        <translation>回應過短 (%1 位元組)</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="148"/>
        <source>exception reply of %1 bytes</source>
        <translation>%1 位元組的例外回應</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="159"/>
        <source>reply function %1, expected %2</source>
        <translation>回應功能碼為 %1，預期為 %2</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="166"/>
        <source>reply ends inside its own data</source>
        <translation>回應在其資料中途結束</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="171"/>
        <source>reply of %1 bytes, expected %2</source>
        <translation>回應為 %1 位元組，預期為 %2</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="181"/>
        <source>MEI type %1, expected %2</source>
        <translation>MEI 類型為 %1，預期為 %2</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="194"/>
        <source>byte count %1, expected %2</source>
        <translation>位元組數為 %1，預期為 %2</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="207"/>
        <source>echo %1 = %2 differs from the write</source>
        <translation>回傳 %1 = %2 與寫入內容不同</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="218"/>
        <source>echo %1 ×%2 differs from the write</source>
        <translation>回傳 %1 ×%2 與寫入內容不同</translation>
    </message>
    <message>
        <location filename="../transport/SerialPortList.cpp" line="87"/>
        <source>An adapter missing here has no driver: see Device Manager, Ports (COM &amp; LPT). A port can also be typed, e.g. COM12.</source>
        <translation>此處未列出的轉接器尚未安裝驅動程式：請查看裝置管理員的「連接埠 (COM 和 LPT)」。也可以直接輸入連接埠，例如 COM12。</translation>
    </message>
    <message>
        <location filename="../transport/SerialPortList.cpp" line="92"/>
        <source>Pseudo-terminals (e.g. /dev/pts/3 or a socat link) are not listed: type their path.</source>
        <translation>虛擬終端機 (例如 /dev/pts/3 或 socat 連結) 不會列出：請直接輸入其路徑。</translation>
    </message>
    <message>
        <location filename="../transport/TcpBackend.cpp" line="61"/>
        <source>Cannot open %1: the name %2 was not found (%3); check the gateway&apos;s name, or give its address</source>
        <translation>無法開啟 %1：找不到名稱 %2 (%3)；請檢查閘道器的名稱，或改用其位址</translation>
    </message>
    <message>
        <location filename="../transport/TcpBackend.cpp" line="128"/>
        <source>MBAP length %1</source>
        <translation>MBAP 長度 %1</translation>
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
        <translation>錯誤：%1</translation>
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
        <translation>傳送時 RTS 為高準位</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="32"/>
        <source>RTS low while sending</source>
        <translation>傳送時 RTS 為低準位</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="35"/>
        <source>, %1 before and after</source>
        <translation>，傳送前後各 %1</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="37"/>
        <source>, %1 before, %2 after</source>
        <translation>，傳送前 %1，傳送後 %2</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="43"/>
        <source>RS-485: switched by the adapter</source>
        <translation>RS-485：由轉接器切換</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="45"/>
        <source>RS-485: kernel mode left on by the driver (%1)</source>
        <translation>RS-485：驅動程式保持核心模式開啟 (%1)</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="49"/>
        <source>RS-485: kernel (%1)</source>
        <translation>RS-485：核心 (%1)</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="52"/>
        <source>RS-485: RTS from the program (%1; kernel mode refused: %2)</source>
        <translation>RS-485：由程式控制 RTS (%1；核心模式被拒絕：%2)</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="56"/>
        <source>RS-485: RTS from the program (%1)</source>
        <translation>RS-485：由程式控制 RTS (%1)</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="61"/>
        <source>RS-485: not available (kernel mode refused: %1; RTS not switchable: %2)</source>
        <translation>RS-485：無法使用 (核心模式被拒絕：%1；RTS 無法切換：%2)</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="66"/>
        <source>RS-485: RTS not switchable on this port (%1)</source>
        <translation>RS-485：此連接埠無法切換 RTS (%1)</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="69"/>
        <source>RS-485: kernel mode refused by the driver (%1)</source>
        <translation>RS-485：驅動程式拒絕核心模式 (%1)</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="78"/>
        <source>latency timer %1 ms</source>
        <translation>延遲計時器 %1 ms</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="86"/>
        <source>low latency: not a UART, no adapter latency</source>
        <translation>低延遲：非 UART，無轉接器延遲</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="90"/>
        <source>low latency: on (but %1)</source>
        <translation>低延遲：開啟 (但 %1)</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="92"/>
        <source>low latency: on</source>
        <translation>低延遲：開啟</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="95"/>
        <source>low latency: the driver&apos;s setting (FTDI: Latency Timer 1 ms in Device Manager)</source>
        <translation>低延遲：由驅動程式設定（FTDI：在裝置管理員將 Latency Timer 設為 1 ms）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="100"/>
        <source>low latency: not offered by the driver (%1)</source>
        <translation>低延遲：驅動程式不支援 (%1)</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="104"/>
        <source>low latency: not offered by the driver (USB adapter: up to %1 ms assumed)</source>
        <translation>低延遲：驅動程式不支援 (USB 轉接器：假設最多 %1 ms)</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="108"/>
        <source>low latency: not offered by the driver</source>
        <translation>低延遲：驅動程式不支援</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="112"/>
        <source>low latency: off</source>
        <translation>低延遲：關閉</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="113"/>
        <source>low latency: off (%1)</source>
        <translation>低延遲：關閉 (%1)</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="137"/>
        <source>low latency is off</source>
        <translation>低延遲已關閉</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="139"/>
        <source>the driver took low latency but kept its latency timer</source>
        <translation>驅動程式接受了低延遲，但保留了其延遲計時器</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="142"/>
        <source>the driver did not take low latency</source>
        <translation>驅動程式未接受低延遲</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="145"/>
        <source>see docs/hardware.md, or use an adapter whose driver offers low latency</source>
        <translation>請參閱 docs/hardware.md，或改用驅動程式支援低延遲的轉接器</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="149"/>
        <source>as root: echo 1 &gt; %1, or the udev rule in docs/hardware.md</source>
        <translation>以 root 執行：echo 1 &gt; %1，或使用 docs/hardware.md 中的 udev 規則</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="153"/>
        <source>The adapter holds received bytes for up to %1 ms before passing them on (%2). Fix: %3.</source>
        <translation>轉接器會將收到的位元組保留最多 %1 ms 才轉交 (%2)。解決方法：%3。</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineSetup.cpp" line="131"/>
        <source>the driver left it off</source>
        <translation>驅動程式仍維持關閉</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineSetup.cpp" line="200"/>
        <source>the port does not take %1</source>
        <translation>連接埠不接受 %1</translation>
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
        <translation>時間 (hh:mm:ss)</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendChart.cpp" line="109"/>
        <source>Drive %1</source>
        <translation>驅動器 %1</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendChart.cpp" line="300"/>
        <source>There is no trend data to export yet.</source>
        <translation>尚無可匯出的趨勢資料。</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendChart.cpp" line="313"/>
        <source>Cannot write the picture %1.</source>
        <translation>無法寫入圖片 %1。</translation>
    </message>
</context>
<context>
    <name>opentop::TrendCsv</name>
    <message>
        <location filename="../model/monitor/TrendCsv.cpp" line="28"/>
        <source>time</source>
        <translation>時間</translation>
    </message>
    <message>
        <location filename="../model/monitor/TrendCsv.cpp" line="28"/>
        <source>seconds</source>
        <translation>秒</translation>
    </message>
</context>
<context>
    <name>opentop::TrendPanel</name>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="50"/>
        <location filename="../ui/trends/TrendPanel.cpp" line="78"/>
        <source>Pause</source>
        <translation>暫停</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="51"/>
        <source>Live</source>
        <translation>即時</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="54"/>
        <source>How often each charted drive is polled. Commands you give always go first; the drives take turns on the bus.</source>
        <translation>每台繪圖中驅動器的輪詢頻率。您下達的指令一律優先；各驅動器輪流使用匯流排。</translation>
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
        <translation>凍結圖表；數值仍會持續記錄。</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="78"/>
        <source>Resume</source>
        <translation>繼續</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="81"/>
        <source>Back to the latest values after zooming or pausing.</source>
        <translation>縮放或暫停後回到最新數值。</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="86"/>
        <source>Clear markers</source>
        <translation>清除標記</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="89"/>
        <source>Export CSV…</source>
        <translation>匯出 CSV…</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="92"/>
        <source>Export PNG…</source>
        <translation>匯出 PNG…</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="97"/>
        <source>Drive / quantity</source>
        <translation>驅動器 / 量測項目</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="111"/>
        <source>Poll rate:</source>
        <translation>輪詢頻率：</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="113"/>
        <source>Window:</source>
        <translation>時間範圍：</translation>
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
        <translation>將趨勢圖匯出為 CSV</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="253"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV 檔 (*.csv)</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="256"/>
        <source>Export CSV</source>
        <translation>匯出 CSV</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="262"/>
        <source>Export trend as picture</source>
        <translation>將趨勢圖匯出為圖片</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="263"/>
        <source>PNG pictures (*.png)</source>
        <translation>PNG 圖片 (*.png)</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="266"/>
        <source>Export PNG</source>
        <translation>匯出 PNG</translation>
    </message>
</context>
<context>
    <name>opentop::TrendReadout</name>
    <message>
        <location filename="../ui/trends/TrendReadout.cpp" line="25"/>
        <source>Markers: click in the chart to set marker A, click again to set marker B.</source>
        <translation>標記：在圖表中按一下設定標記 A，再按一下設定標記 B。</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendReadout.cpp" line="28"/>
        <source>A %1   B %2   Δt = B − A = %3 s</source>
        <translation>A %1   B %2   Δt = B − A = %3 s</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendReadout.cpp" line="31"/>
        <source>A %1   (click in the chart to set marker B)</source>
        <translation>A %1   (在圖表中按一下以設定標記 B)</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendReadout.cpp" line="32"/>
        <source>B %1   (click in the chart to set marker A)</source>
        <translation>B %1   (在圖表中按一下以設定標記 A)</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendReadout.cpp" line="34"/>
        <source>no data</source>
        <translation>無資料</translation>
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
        <translation>DC 控制器的速度迴路步階測試與繼電器自動調諧 (需要 --yes)</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="88"/>
        <source>Run the test (it moves the motor).</source>
        <translation>執行測試 (會使馬達運轉)。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="89"/>
        <source>step: speed before the step (default 0).</source>
        <translation>step：步階前的速度 (預設 0)。</translation>
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
        <translation>step：步階後的速度。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="91"/>
        <source>step: record this long after the step (default 1500).</source>
        <translation>step：步階後記錄的時間長度 (預設 1500)。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="92"/>
        <source>MS</source>
        <translation>MS</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="93"/>
        <source>autotune: operating speed of the relay test.</source>
        <translation>autotune：繼電器測試的運轉速度。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="94"/>
        <source>autotune: output swing, % of full output (default 10).</source>
        <translation>autotune：輸出擺幅，以滿輸出的 % 表示 (預設 10)。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="95"/>
        <source>PERCENT</source>
        <translation>PERCENT</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="97"/>
        <source>autotune: soft, medium (default), stiff, tyreus-luyben or zn-pi.</source>
        <translation>autotune：soft、medium (預設)、stiff、tyreus-luyben 或 zn-pi。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="97"/>
        <source>RULE</source>
        <translation>RULE</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="98"/>
        <source>autotune: write the proposed gains, then run a step test from half the operating speed to it.</source>
        <translation>autotune：寫入建議增益，然後執行從運轉速度的一半到運轉速度的步階測試。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="101"/>
        <source>autotune: with --accept, store the gains in the drive if the step measured with them passes the check.</source>
        <translation>autotune：搭配 --accept 時，若以此增益量測的步階通過檢查，便將增益保存至驅動器。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="104"/>
        <source>autotune: with --accept, keep (and with --store, store) gains whose measured step failed the check; without it they are written back to what the drive had.</source>
        <translation>autotune：搭配 --accept 時，即使量測的步階未通過檢查仍保留增益 (搭配 --store 則保存)；不指定時會寫回驅動器原本的增益。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="107"/>
        <source>Stop at once beyond this speed (default 120 % of the test&apos;s highest).</source>
        <translation>速度超過此值時立即停止 (預設為測試最高速度的 120 %)。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="108"/>
        <source>Stop at once beyond this current in A (default 20).</source>
        <translation>電流超過此值 (A) 時立即停止 (預設 20)。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="109"/>
        <source>A</source>
        <translation>A</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="110"/>
        <source>Write the samples to FILE.</source>
        <translation>將取樣資料寫入 FILE。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="110"/>
        <source>FILE</source>
        <translation>FILE</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="124"/>
        <source>error: usage: %1</source>
        <translation>錯誤：用法：%1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="134"/>
        <source>error: --%1 must be a number 0 or more, got &apos;%2&apos;</source>
        <translation>錯誤：--%1 必須是 0 以上的數字，收到 &apos;%2&apos;</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="156"/>
        <location filename="../cli/TuneCommand.cpp" line="167"/>
        <location filename="../cli/TuneCommand.cpp" line="172"/>
        <location filename="../cli/TuneCommand.cpp" line="375"/>
        <source>error: %1</source>
        <translation>錯誤：%1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="157"/>
        <source>step needs --to SPEED</source>
        <translation>step 需要 --to SPEED</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="158"/>
        <source>--rule must be one of %1</source>
        <translation>--rule 必須是 %1 其中之一</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="160"/>
        <source>autotune needs --speed SPEED</source>
        <translation>autotune 需要 --speed SPEED</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="176"/>
        <source>Would run the motor of machine number %1 from %2 to %3 and record the step response.</source>
        <translation>將使機號 %1 的馬達從 %2 運轉到 %3，並記錄步階響應。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="181"/>
        <source>Would run the motor of machine number %1 in a relay test around %2 (output ±%3 %).</source>
        <translation>將使機號 %1 的馬達在 %2 附近進行繼電器測試 (輸出 ±%3 %)。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="187"/>
        <source>This moves the motor: add --yes to run it.</source>
        <translation>此操作會使馬達運轉：加上 --yes 才會執行。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="236"/>
        <source>Machine number %1, gains %2</source>
        <translation>機號 %1，增益 %2</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="238"/>
        <source>  rise time (10–90 %): %1</source>
        <translation>  上升時間 (10–90 %)：%1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="239"/>
        <source>  overshoot: %1 %</source>
        <translation>  超調：%1 %</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="240"/>
        <source>  settling time (2 %): %1</source>
        <translation>  安定時間 (2 %)：%1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="241"/>
        <source>  steady-state error: %1 %2</source>
        <translation>  穩態誤差：%1 %2</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="242"/>
        <source>  peak current: %1 A</source>
        <translation>  峰值電流：%1 A</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="268"/>
        <source>Step %1 → %2 %3:</source>
        <translation>步階 %1 → %2 %3：</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="273"/>
        <source>Relay test: Ku %1, Tu %2 ms measured (amplitude ±%3 %4, %5 cycles, %6 readings per period, one every %7 ms)</source>
        <translation>繼電器測試：Ku %1，實測 Tu %2 ms (振幅 ±%3 %4，%5 個週期，每週期讀取 %6 次，每 %7 ms 一次)</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="365"/>
        <source>What to change: %1</source>
        <translation>應變更的項目：%1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="282"/>
        <source>Model: gain %1, time constant %2 ms, dead time %3 ms (the bus&apos;s %4 ms left out)</source>
        <translation>模型：增益 %1，時間常數 %2 ms，延遲時間 %3 ms (已扣除匯流排的 %4 ms)</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="288"/>
        <source>The drive&apos;s own loop on the model: Ku %1, Tu %2 ms</source>
        <translation>模型上驅動器本身的迴路：Ku %1，Tu %2 ms</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="291"/>
        <source>Proposed (%1): %2</source>
        <translation>建議值 (%1)：%2</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="292"/>
        <source>  the rule&apos;s P × %1, Ti × %2; predicted step %3 → %4 %5: overshoot %6 %, settling time %7</source>
        <translation>  規則的 P × %1，Ti × %2；預測步階 %3 → %4 %5：超調 %6 %，安定時間 %7</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="308"/>
        <source>Writing the proposed gains failed: %1</source>
        <translation>寫入建議增益失敗：%1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="311"/>
        <source>Proposed gains written (not stored).</source>
        <translation>已寫入建議增益 (未保存)。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="314"/>
        <source>Measured step %1 → %2 %3 with them:</source>
        <translation>以此增益量測的步階 %1 → %2 %3：</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="322"/>
        <source>interrupted</source>
        <translation>已中斷</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="325"/>
        <source>Check after Accept: passed. %1</source>
        <translation>接受後的檢查：通過。%1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="326"/>
        <source>Check after Accept: FAILED. %1</source>
        <translation>接受後的檢查：未通過。%1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="335"/>
        <source>The gains before were written back (%1); nothing was stored. --override-check keeps the proposal (and with --store stores it) all the same.</source>
        <translation>已寫回原先的增益 (%1)；未保存任何內容。加上 --override-check 仍會保留建議值 (搭配 --store 則保存)。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="339"/>
        <source>Writing back the gains before failed: %1; the proposal is still in the drive (not stored).</source>
        <translation>寫回原先的增益失敗：%1；建議值仍在驅動器中 (未保存)。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="346"/>
        <source>Storing although the check failed (--override-check).</source>
        <translation>檢查未通過，仍予保存 (--override-check)。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="355"/>
        <source>Gains stored in the drive.</source>
        <translation>增益已保存至驅動器。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="356"/>
        <source>Storing the gains failed: %1</source>
        <translation>保存增益失敗：%1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="363"/>
        <source>Test ended: %1</source>
        <translation>測試已結束：%1</translation>
    </message>
</context>
<context>
    <name>opentop::TuningChart</name>
    <message>
        <location filename="../ui/tuning/TuningChart.cpp" line="41"/>
        <source>Time (ms)</source>
        <translation>時間 (ms)</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningChart.cpp" line="45"/>
        <location filename="../ui/tuning/TuningChart.cpp" line="83"/>
        <source>Current (A)</source>
        <translation>電流 (A)</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningChart.cpp" line="81"/>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningChart.cpp" line="81"/>
        <source>Speed (%1)</source>
        <translation>速度 (%1)</translation>
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
        <translation>已有調諧測試正在進行</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="88"/>
        <source>Reading the drive&apos;s settings</source>
        <translation>正在讀取驅動器設定</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="98"/>
        <source>could not read the drive&apos;s settings: %1</source>
        <translation>無法讀取驅動器設定：%1</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="139"/>
        <source>the drive is not in a closed-loop speed mode: set %1 (%2) to %3 first</source>
        <translation>驅動器不在閉迴路速度模式：請先將 %1 (%2) 設為 %3</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="141"/>
        <source> or </source>
        <translation> 或 </translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="146"/>
        <source>Setting the communication-loss braking time to %1 s</source>
        <translation>正在將通訊中斷停止時間設為 %1 s</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="201"/>
        <source>the drive stopped answering: %1</source>
        <translation>驅動器停止回應：%1</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="221"/>
        <source>speed %1 %2 beyond the test&apos;s limit %3 %2: stopped at once</source>
        <translation>速度 %1 %2 超過測試限值 %3 %2：已立即停止</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="228"/>
        <source>current %1 A beyond the test&apos;s limit %2 A: stopped at once</source>
        <translation>電流 %1 A 超過測試限值 %2 A：已立即停止</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="234"/>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="271"/>
        <source>Stopping the motor</source>
        <translation>正在停止馬達</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="303"/>
        <source>motor stopped (confirmed)</source>
        <translation>馬達已停止 (已確認)</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="304"/>
        <source>the motor could not be confirmed stopped: check it</source>
        <translation>無法確認馬達已停止：請檢查馬達</translation>
    </message>
</context>
<context>
    <name>opentop::TuningDriveSettings</name>
    <message>
        <location filename="../ui/tuning/TuningDriveSettings.cpp" line="53"/>
        <source>Could not read the speed mode: %1</source>
        <translation>無法讀取速度模式：%1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningDriveSettings.cpp" line="56"/>
        <source>The drive is not in a closed-loop speed mode (now: %1). Choose one on its settings page first.</source>
        <translation>驅動器不在閉迴路速度模式 (目前：%1)。請先在其設定頁面中選擇閉迴路模式。</translation>
    </message>
</context>
<context>
    <name>opentop::TuningGains</name>
    <message>
        <location filename="../ui/tuning/TuningGains.cpp" line="43"/>
        <source>Writing the gains failed: %1</source>
        <translation>寫入增益失敗：%1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningGains.cpp" line="62"/>
        <source>Proposal written (temporary until stored).</source>
        <translation>已寫入建議值 (保存前僅暫時有效)。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningGains.cpp" line="83"/>
        <source>%1: the gains before were written back (%2).</source>
        <translation>%1：已寫回原先的增益 (%2)。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningGains.cpp" line="102"/>
        <source>Gains stored in the drive.</source>
        <translation>增益已保存至驅動器。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningGains.cpp" line="104"/>
        <source>Storing the gains failed: %1</source>
        <translation>保存增益失敗：%1</translation>
    </message>
</context>
<context>
    <name>opentop::TuningLimitsBox</name>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="12"/>
        <source>Limits</source>
        <translation>限值</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="17"/>
        <source>Beyond it the motor is stopped at once. Empty: 125 % of the step test&apos;s highest speed, 150 % of the autotune&apos;s speed</source>
        <translation>超過此值時馬達會立即停止。留空：步階測試最高速度的 125 %，自動調諧速度的 150 %</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="19"/>
        <source>Beyond it the motor is stopped at once. Empty: 1.2 × the drive&apos;s maximum current</source>
        <translation>超過此值時馬達會立即停止。留空：1.2 × 驅動器最大電流</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="22"/>
        <source>Max. speed:</source>
        <translation>最高速度：</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="23"/>
        <source>Max. current:</source>
        <translation>最大電流：</translation>
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
        <translation>自動：%1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="39"/>
        <source>none</source>
        <translation>無</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="48"/>
        <source>Enter a speed limit above 0 %1, or leave it empty.</source>
        <translation>請輸入大於 0 %1 的速度限值，或留空。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="52"/>
        <source>Enter a current limit above 0 A, or leave it empty.</source>
        <translation>請輸入大於 0 A 的電流限值，或留空。</translation>
    </message>
</context>
<context>
    <name>opentop::TuningMetricsView</name>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="25"/>
        <source>Rise time (10–90 %):</source>
        <translation>上升時間 (10–90 %)：</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="26"/>
        <source>Overshoot:</source>
        <translation>超調：</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="27"/>
        <source>Settling time (2 %):</source>
        <translation>安定時間 (2 %)：</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="28"/>
        <source>Steady-state error:</source>
        <translation>穩態誤差：</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="29"/>
        <source>Peak current:</source>
        <translation>峰值電流：</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="40"/>
        <source>No run yet</source>
        <translation>尚未執行測試</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="41"/>
        <source>%1: recording</source>
        <translation>%1：記錄中</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="44"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
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
        <translation>未達到</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="54"/>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="56"/>
        <source>not settled</source>
        <translation>未安定</translation>
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
        <translation>上升時間 %1；超調 %2；安定時間 %3；穩態誤差 %4；峰值電流 %5</translation>
    </message>
</context>
<context>
    <name>opentop::TuningPage</name>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="53"/>
        <location filename="../ui/tuning/TuningPage.cpp" line="213"/>
        <source>Step test</source>
        <translation>步階測試</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="54"/>
        <location filename="../ui/tuning/TuningPage.cpp" line="234"/>
        <source>Relay autotune</source>
        <translation>繼電器自動調諧</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="112"/>
        <source>Ready. Nothing moves until you confirm a test.</source>
        <translation>就緒。確認測試之前，馬達不會運轉。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="191"/>
        <source>Limits: %1 %2, %3.</source>
        <translation>限值：%1 %2，%3。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="193"/>
        <source>%1 A</source>
        <translation>%1 A</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="193"/>
        <source>no current limit</source>
        <translation>無電流限值</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="208"/>
        <source>The motor of %1 will run from %2 to %3 %4 in its present speed mode, for about %5 s, and then stop.</source>
        <translation>%1 的馬達將以目前的速度模式從 %2 運轉到 %3 %4，持續約 %5 s，然後停止。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="213"/>
        <location filename="../ui/tuning/TuningPage.cpp" line="234"/>
        <source>Run</source>
        <translation>執行</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="229"/>
        <source>The motor of %1 will run in open loop (the speed loop off) around %2 %3, its output switching by ±%4 %, for up to %5 s, and then stop.</source>
        <translation>%1 的馬達將以開迴路 (速度迴路關閉) 在 %2 %3 附近運轉，輸出以 ±%4 % 切換，最長 %5 s，然後停止。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="252"/>
        <source>Stop command sent.</source>
        <translation>已送出停止指令。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="253"/>
        <source>Stop command failed: %1</source>
        <translation>停止指令失敗：%1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="263"/>
        <source>Stopping…</source>
        <translation>正在停止…</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="277"/>
        <source>Run %1: %2 → %3 %4</source>
        <translation>測試 %1：%2 → %3 %4</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="296"/>
        <source>Step test done.</source>
        <translation>步階測試完成。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="297"/>
        <source>Step test ended: %1</source>
        <translation>步階測試已結束：%1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="302"/>
        <source>The test was stopped</source>
        <translation>測試已停止</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="333"/>
        <source>Autotune ended: %1</source>
        <translation>自動調諧已結束：%1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="335"/>
        <source>The autotune was stopped</source>
        <translation>自動調諧已停止</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="344"/>
        <source>Predicted: %1 → %2 %3</source>
        <translation>預測：%1 → %2 %3</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="347"/>
        <source>Autotune done: proposal %1. Accept writes it to the drive.</source>
        <translation>自動調諧完成：建議值 %1。接受後即寫入驅動器。</translation>
    </message>
</context>
<context>
    <name>opentop::TuningRules</name>
    <message>
        <location filename="../model/tuning/TuningRules.cpp" line="61"/>
        <source>Soft (no overshoot)</source>
        <translation>柔和 (無超調)</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningRules.cpp" line="63"/>
        <source>Medium (some overshoot)</source>
        <translation>適中 (少量超調)</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningRules.cpp" line="65"/>
        <source>Stiff (Ziegler–Nichols)</source>
        <translation>高剛性 (Ziegler–Nichols)</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningRules.cpp" line="67"/>
        <source>Tyreus–Luyben (robust)</source>
        <translation>Tyreus–Luyben (強健)</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningRules.cpp" line="69"/>
        <source>PI only (Ziegler–Nichols)</source>
        <translation>僅 PI (Ziegler–Nichols)</translation>
    </message>
</context>
<context>
    <name>opentop::TuningRunList</name>
    <message>
        <location filename="../ui/tuning/TuningRunList.cpp" line="14"/>
        <source>Run</source>
        <translation>測試</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunList.cpp" line="14"/>
        <source>Gains</source>
        <translation>增益</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunList.cpp" line="43"/>
        <source>%1 (recording)</source>
        <translation>%1 (記錄中)</translation>
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
        <translation>儲存 CSV…</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="39"/>
        <source>Save PNG…</source>
        <translation>儲存 PNG…</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="44"/>
        <source>Saves the selected run: its samples, gains and metrics</source>
        <translation>儲存選取的測試：其取樣資料、增益與指標</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="45"/>
        <source>Saves the chart as it is shown</source>
        <translation>依目前的顯示儲存圖表</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="46"/>
        <source>solid: speed · dotted: command · dash-dot: current (right axis) · dashed: predicted speed</source>
        <translation>實線：速度 · 點線：指令 · 一點鏈線：電流 (右軸) · 虛線：預測速度</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="220"/>
        <source>no run to save</source>
        <translation>沒有可儲存的測試</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="233"/>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="237"/>
        <source>Save run as CSV</source>
        <translation>將測試儲存為 CSV</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="234"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV 檔 (*.csv)</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="242"/>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="245"/>
        <source>Save chart as PNG</source>
        <translation>將圖表儲存為 PNG</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="243"/>
        <source>PNG images (*.png)</source>
        <translation>PNG 圖片 (*.png)</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="245"/>
        <source>Could not write %1.</source>
        <translation>無法寫入 %1。</translation>
    </message>
</context>
<context>
    <name>opentop::TuningSpec</name>
    <message>
        <location filename="../model/tuning/TuningSpec.cpp" line="23"/>
        <source>%1 has no speed loop to tune</source>
        <translation>%1 沒有可調諧的速度迴路</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningSpec.cpp" line="51"/>
        <source>%1: the profile&apos;s tuning needs the roles pidP, pidI, pidD, pidDPeriod, pidStore, speedMode, speedCommand, commLossTime, loadCurrent and output</source>
        <translation>%1：定義檔的調諧需要以下角色：pidP、pidI、pidD、pidDPeriod、pidStore、speedMode、speedCommand、commLossTime、loadCurrent 與 output</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningSpec.cpp" line="61"/>
        <source>%1: the profile&apos;s tuning section needs periodMs ≥ 1, outputFullScale &gt; 0, openLoopMode and closedLoopModes with known feedback parameters</source>
        <translation>%1：定義檔的調諧區段需要 periodMs ≥ 1、outputFullScale &gt; 0、openLoopMode，以及回授參數已知的 closedLoopModes</translation>
    </message>
</context>
<context>
    <name>opentop::TuningStatusRow</name>
    <message>
        <location filename="../ui/tuning/TuningStatusRow.cpp" line="12"/>
        <source>STOP</source>
        <translation>停止</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningStatusRow.cpp" line="17"/>
        <source>Cancels the running test: the motor is stopped and the stop confirmed</source>
        <translation>取消進行中的測試：停止馬達並確認已停止</translation>
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
        <translation>記錄時間內未安定</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningVerdict.cpp" line="20"/>
        <source>no step was measured to its end with these gains: %1</source>
        <translation>未能以此增益將步階量測完畢：%1</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningVerdict.cpp" line="46"/>
        <source>the speed did not settle within %1 ms (±2 % of the step)</source>
        <translation>速度未在 %1 ms 內安定 (步階的 ±2 %)</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningVerdict.cpp" line="49"/>
        <source>it overshot by %1 % where %2 % was predicted (at most %3 points more are accepted)</source>
        <translation>超調為 %1 %，預測為 %2 % (最多只接受多出 %3 個百分點)</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningVerdict.cpp" line="60"/>
        <source>Measured: overshoot %1 % (predicted %2 %), settling time %3 (predicted %4), peak current %5 A.</source>
        <translation>實測：超調 %1 % (預測 %2 %)，安定時間 %3 (預測 %4)，峰值電流 %5 A。</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningVerdict.cpp" line="70"/>
        <source>Check failed: %1.</source>
        <translation>檢查未通過：%1。</translation>
    </message>
</context>
<context>
    <name>opentop::UnitLog</name>
    <message>
        <location filename="../ui/eol/UnitLog.cpp" line="19"/>
        <source>Time</source>
        <translation>時間</translation>
    </message>
    <message>
        <location filename="../ui/eol/UnitLog.cpp" line="19"/>
        <source>Serial</source>
        <translation>序號</translation>
    </message>
    <message>
        <location filename="../ui/eol/UnitLog.cpp" line="19"/>
        <source>Verdict</source>
        <translation>判定</translation>
    </message>
    <message>
        <location filename="../ui/eol/UnitLog.cpp" line="19"/>
        <source>Reason</source>
        <translation>原因</translation>
    </message>
    <message>
        <location filename="../ui/eol/UnitLog.cpp" line="32"/>
        <source>%1, NOT RECORDED</source>
        <translation>%1，未記錄</translation>
    </message>
    <message>
        <location filename="../ui/eol/UnitLog.cpp" line="34"/>
        <source>%1 (kept on this station)</source>
        <translation>%1（保存在本工作站）</translation>
    </message>
</context>
<context>
    <name>opentop::UnitRecordJson</name>
    <message>
        <location filename="../model/eol/UnitRecordJson.cpp" line="115"/>
        <source>not a unit record (format is not &quot;%1&quot;)</source>
        <translation>不是產品記錄 (format 不是 &quot;%1&quot;)</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitRecordJson.cpp" line="118"/>
        <source>unit record version %1 is not known to this program (it reads up to %2)</source>
        <translation>本程式不認得產品記錄版本 %1 (最多可讀取 %2)</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitRecordJson.cpp" line="125"/>
        <source>the unit record has no serial number</source>
        <translation>產品記錄沒有序號</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitRecordJson.cpp" line="139"/>
        <source>unknown unit status &quot;%1&quot;</source>
        <translation>未知的產品狀態 &quot;%1&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitRecordJson.cpp" line="153"/>
        <source>unknown variant source &quot;%1&quot;</source>
        <translation>未知的機型來源「%1」</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitRecordJson.cpp" line="192"/>
        <source>not JSON: %1</source>
        <translation>不是 JSON：%1</translation>
    </message>
</context>
<context>
    <name>opentop::UnitStartGate</name>
    <message>
        <location filename="../model/station/UnitStartGate.cpp" line="45"/>
        <source>cancelled before it started</source>
        <translation>開始前已取消</translation>
    </message>
    <message>
        <location filename="../model/station/UnitStartGate.cpp" line="80"/>
        <source>not connected to a bus</source>
        <translation>未連線至匯流排</translation>
    </message>
    <message>
        <location filename="../model/station/UnitStartGate.cpp" line="85"/>
        <source>a drive of the station is not safe: %1</source>
        <translation>工作站有驅動器不安全：%1</translation>
    </message>
</context>
<context>
    <name>opentop::UnitValuesCsv</name>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="74"/>
        <source>the CSV file is larger than %1 MB</source>
        <translation>CSV 檔大於 %1 MB</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="76"/>
        <source>not a CSV text file (it holds NUL bytes)</source>
        <translation>不是 CSV 文字檔 (含有 NUL 位元組)</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="97"/>
        <source>line %1: a quoted field is not closed properly</source>
        <translation>第 %1 行：引號欄位未正確結束</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="101"/>
        <source>line %1: the header must start with &quot;serial&quot;, not &quot;%2&quot;</source>
        <translation>第 %1 行：標題列必須以 &quot;serial&quot; 開頭，而非 &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="105"/>
        <source>line %1: the header names no per-unit value</source>
        <translation>第 %1 行：標題列中沒有任何單台數值</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="107"/>
        <source>line %1: more than %2 columns</source>
        <translation>第 %1 行：超過 %2 欄</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="111"/>
        <source>line %1: column %2 has no name</source>
        <translation>第 %1 行：第 %2 欄沒有名稱</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="113"/>
        <source>line %1: column &quot;%2&quot; appears twice</source>
        <translation>第 %1 行：欄位 &quot;%2&quot; 出現兩次</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="122"/>
        <source>line %1: %2 fields, but the header has %3</source>
        <translation>第 %1 行：有 %2 個欄位，但標題列有 %3 個</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="128"/>
        <source>line %1: no serial number</source>
        <translation>第 %1 行：沒有序號</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="130"/>
        <source>line %1: serial number &quot;%2&quot; is already on line %3</source>
        <translation>第 %1 行：序號 &quot;%2&quot; 已出現在第 %3 行</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="137"/>
        <source>the CSV file is empty; it needs a header &quot;serial,&lt;parameter&gt;,...&quot;</source>
        <translation>CSV 檔為空；需要標題列 &quot;serial,&lt;parameter&gt;,...&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="151"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="193"/>
        <source>serial number &quot;%1&quot; is not in the CSV file</source>
        <translation>序號 &quot;%1&quot; 不在 CSV 檔中</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="206"/>
        <source>%1: column &quot;%2&quot; is ambiguous, several positions have this per-unit value; name the column &quot;%3:%2&quot;</source>
        <translation>%1：欄位 &quot;%2&quot; 不明確，多個位置都有此單台數值；請將欄位命名為 &quot;%3:%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="210"/>
        <source>%1: the CSV file has no column &quot;%2&quot; (or &quot;%3:%2&quot;) for this per-unit value</source>
        <translation>%1：CSV 檔中沒有此單台數值的欄位 &quot;%2&quot; (或 &quot;%3:%2&quot;)</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="215"/>
        <source>line %1, column &quot;%2&quot;: no value for serial number &quot;%3&quot;</source>
        <translation>第 %1 行，欄位 &quot;%2&quot;：序號 &quot;%3&quot; 沒有值</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="225"/>
        <source>line %1, column &quot;%2&quot;: &quot;%3&quot; is not a number</source>
        <translation>第 %1 行，欄位 &quot;%2&quot;：&quot;%3&quot; 不是數字</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="231"/>
        <source>line %1: %2</source>
        <translation>第 %1 行：%2</translation>
    </message>
</context>
<context>
    <name>opentop::UserGuideDialog</name>
    <message>
        <location filename="../ui/help/UserGuideDialog.cpp" line="26"/>
        <source>OpenTOP user guide</source>
        <translation>OpenTOP 使用手冊</translation>
    </message>
    <message>
        <location filename="../ui/help/UserGuideDialog.cpp" line="28"/>
        <source> or </source>
        <translation> 或 </translation>
    </message>
    <message>
        <location filename="../ui/help/UserGuideDialog.cpp" line="31"/>
        <source>&lt;h2&gt;Commissioning a drive with OpenTOP&lt;/h2&gt;&lt;ol&gt;&lt;li&gt;&lt;b&gt;Connect.&lt;/b&gt; Bus ▸ Connect… chooses the serial port (or USB to RS-485 adapter), a Modbus TCP gateway or a simulated bus, with the bus&apos;s baud rate, parity and stop bits. The status bar says what the program is connected to; a simulated bus is marked as such.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Find the drives.&lt;/b&gt; Bus ▸ Scan bus (F5) asks every machine number 1–247; the drives that answer are identified and listed on the left with their state and control priority.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Select a drive.&lt;/b&gt; Its pages open on the right: Monitor (live values), the parameter pages of its profile, Test run and Alarms.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Edit settings.&lt;/b&gt; An edited field is marked as pending until it is written. Write page (or Drive ▸ Write all pending, Ctrl+W) writes and reads every value back to verify it; Revert drops the edits; Re-read (Ctrl+R) reads the drive again. A value the drive would refuse is never sent: the field says why.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Test-run the motor.&lt;/b&gt; The Test run page starts, stops and reverses the drive in communication priority and asks before the first start of each drive. Return the drive to I/O priority when done, so that the machine&apos;s own inputs control it again.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Stop.&lt;/b&gt; STOP ALL on the toolbar, or %1, stops every drive on the bus at once, from any window of the program.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Watch.&lt;/b&gt; View ▸ Trends (Ctrl+G) charts speeds and loads; View ▸ Bus overview shows every drive at a glance; View ▸ Traffic log (Ctrl+T) shows each frame on the bus with its meaning.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Keep the settings.&lt;/b&gt; Files ▸ Back up saves the settings of one drive or the whole bus to a file; Files ▸ Compare shows differences between drives, files and factory defaults; Files ▸ Restore writes a backup back after a preview.&lt;/li&gt;&lt;/ol&gt;&lt;p&gt;Every keyboard shortcut is listed in Help ▸ Keyboard shortcuts.&lt;/p&gt;&lt;h3&gt;More documentation&lt;/h3&gt;&lt;p&gt;The command line and the simulator: &lt;code&gt;man opentop&lt;/code&gt;, &lt;code&gt;man opentop-cli&lt;/code&gt;, &lt;code&gt;man opentop-sim&lt;/code&gt;.&lt;/p&gt;</source>
        <translation>&lt;h2&gt;使用 OpenTOP 試車調機驅動器&lt;/h2&gt;&lt;ol&gt;&lt;li&gt;&lt;b&gt;連線。&lt;/b&gt;匯流排 ▸ 連線… 可選擇序列埠 (或 USB 轉 RS-485 轉接器)、Modbus TCP 閘道器或模擬匯流排，並設定匯流排的鮑率、同位元與停止位元。狀態列會顯示程式目前的連線對象；模擬匯流排會特別標示。&lt;/li&gt;&lt;li&gt;&lt;b&gt;尋找驅動器。&lt;/b&gt;匯流排 ▸ 掃描匯流排 (F5) 會詢問每個機號 1–247；有回應的驅動器會被識別，並連同其狀態與控制優先權列在左側。&lt;/li&gt;&lt;li&gt;&lt;b&gt;選擇驅動器。&lt;/b&gt;其頁面會在右側開啟：監視 (即時值)、依定義檔的參數頁、試運轉與警報。&lt;/li&gt;&lt;li&gt;&lt;b&gt;編輯設定。&lt;/b&gt;已編輯的欄位在寫入前會標示為待寫入。寫入本頁 (或 驅動器 ▸ 寫入所有待寫入項目，Ctrl+W) 會寫入每個值並回讀驗證；復原會捨棄變更；重新讀取 (Ctrl+R) 會重新讀取驅動器。驅動器會拒絕的值絕不會送出：欄位會說明原因。&lt;/li&gt;&lt;li&gt;&lt;b&gt;試運轉馬達。&lt;/b&gt;試運轉頁面會在通訊優先下啟動、停止及反轉驅動器，每台驅動器第一次啟動前會先詢問。完成後請將驅動器恢復為 I/O 優先，讓機台本身的輸入端子再次控制。&lt;/li&gt;&lt;li&gt;&lt;b&gt;停止。&lt;/b&gt;工具列上的「全部停止」或 %1，可從程式的任何視窗立即停止匯流排上的所有驅動器。&lt;/li&gt;&lt;li&gt;&lt;b&gt;監看。&lt;/b&gt;檢視 ▸ 趨勢圖 (Ctrl+G) 繪製速度與負載曲線；檢視 ▸ 匯流排總覽 可一覽所有驅動器；檢視 ▸ 通訊記錄 (Ctrl+T) 顯示匯流排上的每個訊框及其意義。&lt;/li&gt;&lt;li&gt;&lt;b&gt;保留設定。&lt;/b&gt;檔案 ▸ 備份 將單台驅動器或整個匯流排的設定儲存至檔案；檔案 ▸ 比較 顯示驅動器、檔案與出廠預設值之間的差異；檔案 ▸ 還原 會在預覽後將備份寫回。&lt;/li&gt;&lt;/ol&gt;&lt;p&gt;所有鍵盤快速鍵均列於 說明 ▸ 鍵盤快速鍵。&lt;/p&gt;&lt;h3&gt;更多文件&lt;/h3&gt;&lt;p&gt;命令列與模擬器：&lt;code&gt;man opentop&lt;/code&gt;、&lt;code&gt;man opentop-cli&lt;/code&gt;、&lt;code&gt;man opentop-sim&lt;/code&gt;。&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../ui/help/UserGuideDialog.cpp" line="66"/>
        <source>&lt;h3&gt;Leaving a bus, and coming back after the link drops&lt;/h3&gt;&lt;p&gt;&lt;b&gt;Leaving.&lt;/b&gt; Quitting, Bus ▸ Disconnect or connecting elsewhere while drives run or are in communication priority names each of them and what will happen to it. The default stops every running drive, reads it back to confirm the stop, and then gives each drive back to its own inputs (I/O priority, read back), so that the machine works without OpenTOP. You may instead give control back only, leave the drives as they are, or stay.&lt;/p&gt;&lt;p&gt;&lt;b&gt;A lost link.&lt;/b&gt; When the adapter is pulled out or the gateway goes, every live value turns grey and a message says which drives were running or in communication priority when the link dropped, with the age of what is known. OpenTOP cannot stop them over a lost link: check the drive&apos;s STOP input, the emergency stop and the power on the machine. Bus ▸ Reconnect (Ctrl+R, also in the message and in the red bar) opens the same port again with the same drives, selected drive and page, reads every drive again and says at once if one is running. While connected, Ctrl+R re-reads the drive&apos;s pages.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;離開匯流排，以及連線中斷後重新連線&lt;/h3&gt;&lt;p&gt;&lt;b&gt;離開。&lt;/b&gt;在驅動器運轉中或處於通訊優先時結束程式、執行 匯流排 ▸ 中斷連線 或連線至其他位置，會列出每台驅動器及將對它執行的動作。預設會停止每台運轉中的驅動器、回讀以確認已停止，然後將每台驅動器交還給其本身的輸入端子 (I/O 優先，回讀確認)，讓機台不需 OpenTOP 也能運作。您也可以選擇僅交還控制權、維持驅動器現狀，或留下。&lt;/p&gt;&lt;p&gt;&lt;b&gt;連線中斷。&lt;/b&gt;當轉接器被拔出或閘道器消失時，所有即時數值會變成灰色，並以訊息說明連線中斷時哪些驅動器正在運轉或處於通訊優先，以及已知資料的時間。OpenTOP 無法透過中斷的連線停止它們：請在機台上確認驅動器的停止輸入端子、緊急停止與電源。匯流排 ▸ 重新連線 (Ctrl+R，訊息與紅色提示列中也有) 會以相同的驅動器、所選驅動器與頁面重新開啟同一個連接埠，重新讀取所有驅動器，並立即告知是否有驅動器正在運轉。連線中時，Ctrl+R 會重新讀取驅動器的頁面。&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../ui/help/UserGuideDialog.cpp" line="86"/>
        <source>&lt;p&gt;The full description of the program: &lt;a href=&quot;%1&quot;&gt;%2&lt;/a&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;程式的完整說明：&lt;a href=&quot;%1&quot;&gt;%2&lt;/a&gt;&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>opentop::UserStore</name>
    <message>
        <location filename="../model/access/UserStore.cpp" line="43"/>
        <source>a user name is 1 to 64 letters, digits or . _ @ - (no spaces): &quot;%1&quot;</source>
        <translation>使用者名稱為 1 至 64 個字母、數字或 . _ @ -（不可有空格）：「%1」</translation>
    </message>
</context>
<context>
    <name>opentop::ValueCodec</name>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="63"/>
        <source>%1: %2 is outside the recommended range %3; it is allowed and will be written</source>
        <translation>%1：%2 超出建議範圍 %3；此值仍允許，將會寫入</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="80"/>
        <source> (the variant is not known, so the value must suit %1; name the variant to use its own range)</source>
        <translation> (機型未知，因此值必須適用於 %1；指定機型即可使用其範圍)</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="90"/>
        <source>%1: the allowed values depend on %2, which has not been read</source>
        <translation>%1：允許值取決於尚未讀取的 %2</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="95"/>
        <source>%1: value out of the register&apos;s range; allowed: %2</source>
        <translation>%1：值超出暫存器範圍；允許：%2</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="107"/>
        <source>%1: %2 is not allowed; allowed: %3</source>
        <translation>%1：不允許 %2；允許：%3</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="119"/>
        <source>%1: expected %2 registers, got %3</source>
        <translation>%1：預期 %2 個暫存器，收到 %3 個</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="149"/>
        <source>%1 is text, not a number</source>
        <translation>%1 是文字，不是數字</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="162"/>
        <source>%1: %2 is finer than the step of %3 %4; allowed: %5</source>
        <translation>%1：%2 比最小單位 %3 %4 更細；允許：%5</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="195"/>
        <source>%1: at most %2 characters</source>
        <translation>%1：最多 %2 個字元</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="200"/>
        <source>%1: only printable ASCII characters are allowed</source>
        <translation>%1：只允許可列印的 ASCII 字元</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="210"/>
        <source>%1: no value given; allowed: %2</source>
        <translation>%1：未指定值；允許：%2</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="250"/>
        <source>%1: &quot;%2&quot; is only available when %3 is %4; allowed now: %5</source>
        <translation>%1：&quot;%2&quot; 僅在 %3 為 %4 時可用；目前允許：%5</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="263"/>
        <location filename="../model/profile/ValueCodec.cpp" line="283"/>
        <source>%1: &quot;%2&quot; is not a valid value; allowed: %3</source>
        <translation>%1：&quot;%2&quot; 不是有效值；允許：%3</translation>
    </message>
</context>
<context>
    <name>opentop::ValueFormat</name>
    <message>
        <location filename="../model/profile/ValueFormat.cpp" line="45"/>
        <source> or </source>
        <translation> 或 </translation>
    </message>
    <message>
        <location filename="../model/profile/ValueFormat.cpp" line="65"/>
        <source>depends on %1, which is not known yet</source>
        <translation>取決於尚未得知的 %1</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueFormat.cpp" line="67"/>
        <source>text of up to %1 characters</source>
        <translation>最多 %1 個字元的文字</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueFormat.cpp" line="73"/>
        <source>, or </source>
        <translation>，或 </translation>
    </message>
    <message>
        <location filename="../model/profile/ValueFormat.cpp" line="74"/>
        <source>any value</source>
        <translation>任意值</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueFormat.cpp" line="81"/>
        <source>(invalid)</source>
        <translation>(無效)</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueFormat.cpp" line="92"/>
        <source>unknown code %1</source>
        <translation>未知代碼 %1</translation>
    </message>
</context>
<context>
    <name>opentop::VariantCheck</name>
    <message>
        <location filename="../model/eol/VariantCheck.cpp" line="23"/>
        <source>proving the variant (%1)</source>
        <translation>證實機型中（%1）</translation>
    </message>
</context>
<context>
    <name>opentop::VariantDecision</name>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="39"/>
        <source>the variant probe left the drive changed: %1</source>
        <translation>機型探測使驅動器留下變更：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="44"/>
        <source>reported by the drive</source>
        <translation>由驅動器回報</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="53"/>
        <source>%1; named by %2</source>
        <translation>%1；由 %2 指定</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="57"/>
        <source>given for the unit by %1 (eol run --variant)</source>
        <translation>由 %1 為此機台指定（eol run --variant）</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="62"/>
        <source>confirmed by the operator %1 (the recipe asks the operator)</source>
        <translation>由作業員 %1 確認（配方要求作業員確認）</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="67"/>
        <source>the recipe&apos;s only variant, not proven on the bus</source>
        <translation>配方唯一的機型，未在匯流排上證實</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="74"/>
        <source>the family has no variant probe</source>
        <translation>此系列沒有機型探測</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="76"/>
        <source>the probe leaves %1 (%2)</source>
        <translation>探測結果仍為 %1（%2）</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="81"/>
        <source>the drive does not report its variant and it was not proven (%1)</source>
        <translation>驅動器不回報機型，也未能證實（%1）</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="82"/>
        <source>the drive does not report its variant and it was not proven (%1); the recipe allows %2 and needs proof</source>
        <translation>驅動器不回報機型，也未能證實（%1）；配方允許 %2，且需要證實</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="90"/>
        <source>the drive is a %1 (%2), but %3 was given for it</source>
        <translation>驅動器是 %1（%2），但指定的是 %3</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="93"/>
        <source>a %1 (%2), the recipe allows %3</source>
        <translation>是 %1（%2），配方允許 %3</translation>
    </message>
</context>
<context>
    <name>opentop::VariantNeed</name>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="19"/>
        <source>%1 and %2 more</source>
        <translation>%1 及另外 %2 項</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="69"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="77"/>
        <source>Allowed %1 — %2</source>
        <translation>允許值 %1 — %2</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="94"/>
        <source>The allowed values of the settings you are changing depend on it.</source>
        <translation>您正在變更的設定，其允許值取決於機型。</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="97"/>
        <source>The backup file records it, and a restore checks the values against it.</source>
        <translation>備份檔會記錄機型，還原時會依機型檢查數值。</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="100"/>
        <source>The speeds the motor may run at depend on it.</source>
        <translation>馬達允許的運轉速度取決於機型。</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="104"/>
        <source>Which drive is %1? It reports only &quot;%2&quot;, not whether it is a %3.</source>
        <translation>%1 是哪一種驅動器？它只回報「%2」，不會回報是否為 %3。</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="105"/>
        <source> or </source>
        <translation> 或 </translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="108"/>
        <source>Read it on the drive&apos;s rating plate. It is kept for this bus and asked once; without it every value must suit all of them.</source>
        <translation>請查看驅動器的銘牌。此設定會保存於此匯流排，只詢問一次；若不指定，每個值都必須符合所有機型。</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="112"/>
        <source>Last time on this bus it was set as %1.</source>
        <translation>上次在此匯流排上設為 %1。</translation>
    </message>
</context>
<context>
    <name>opentop::VariantProbe</name>
    <message>
        <location filename="../model/profile/VariantProbe.cpp" line="51"/>
        <source>unknown key &quot;%1&quot;</source>
        <translation>未知的鍵「%1」</translation>
    </message>
    <message>
        <location filename="../model/profile/VariantProbe.cpp" line="58"/>
        <source>needs &quot;parameter&quot;, a number &quot;value&quot; and &quot;refusedCode&quot;</source>
        <translation>需要 &quot;parameter&quot;、數值 &quot;value&quot; 與 &quot;refusedCode&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/VariantProbe.cpp" line="63"/>
        <source>no parameter &quot;%1&quot;</source>
        <translation>沒有參數「%1」</translation>
    </message>
    <message>
        <location filename="../model/profile/VariantProbe.cpp" line="67"/>
        <source>%1 must be a readable, writable setting that no role names (never a command or a motion register)</source>
        <translation>%1 必須是可讀寫、且未被任何角色使用的設定（絕不可是命令或運轉暫存器）</translation>
    </message>
    <message>
        <location filename="../model/profile/VariantProbe.cpp" line="77"/>
        <source>%1 = %2 must be allowed on some variants and refused on others</source>
        <translation>%1 = %2 必須在部分機型允許、在其他機型拒絕</translation>
    </message>
</context>
<context>
    <name>opentop::VariantProber</name>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="47"/>
        <location filename="../model/session/VariantProber.cpp" line="85"/>
        <source>%1 cannot be read: %2</source>
        <translation>無法讀取 %1：%2</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="63"/>
        <source>%1 still holds %2 from a variant probe that was interrupted, and cannot be set back to %3 (%4): set it to %3 before this drive is used</source>
        <translation>%1 仍保留中斷的機型探測所寫入的 %2，且無法改回 %3 (%4)：使用此驅動器前請將其設為 %3</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="71"/>
        <source>%1 set back from %2 to %3, left by a variant probe that was interrupted</source>
        <translation>%1 已由 %2 改回 %3 (先前中斷的機型探測所留下)</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="102"/>
        <source>not probed: the original value cannot be kept while it is (%1)</source>
        <translation>未探測：探測期間無法保存原值 (%1)</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="123"/>
        <source>the probe %1 was not answered as the manual says: %2</source>
        <translation>機型探測 %1 的回應與手冊所述不符：%2</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="147"/>
        <source>%1 could not be set back to %2 after the variant probe (%3): set it to %2 before this drive is used</source>
        <translation>機型探測後無法將 %1 改回 %2（%3）：使用此驅動器前請將它設為 %2</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="152"/>
        <source>%1 accepted, %2 written back</source>
        <translation>%1 被接受，已寫回 %2</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="160"/>
        <source>%1 refused (%2)</source>
        <translation>%1 被拒絕（%2）</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="171"/>
        <source>%1 does not read back as %2 after the variant probe (%3): set it to %2 before this drive is used</source>
        <translation>機型探測後 %1 讀回不是 %2（%3）：使用此驅動器前請將它設為 %2</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="181"/>
        <source>the probe did not decide</source>
        <translation>探測無法判定</translation>
    </message>
</context>
<context>
    <name>opentop::VariantQuestion</name>
    <message>
        <location filename="../ui/bus/VariantQuestion.cpp" line="29"/>
        <source>Which drive is it?</source>
        <translation>這是哪一種驅動器？</translation>
    </message>
    <message>
        <location filename="../ui/bus/VariantQuestion.cpp" line="42"/>
        <source>Not known: check against every variant</source>
        <translation>不確定：依所有機型檢查</translation>
    </message>
    <message>
        <location filename="../ui/bus/VariantQuestion.cpp" line="65"/>
        <source>the variant of %1 was not given</source>
        <translation>未指定 %1 的機型</translation>
    </message>
</context>
<context>
    <name>opentop::VerdictLook</name>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="16"/>
        <source>READY</source>
        <translation>就緒</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="17"/>
        <source>TESTING</source>
        <translation>測試中</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="18"/>
        <source>NOT STARTED</source>
        <translation>未開始</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="20"/>
        <source>PASS</source>
        <translation>合格</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="21"/>
        <source>FAIL</source>
        <translation>不合格</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="22"/>
        <source>STATION ERROR</source>
        <translation>工站錯誤</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="24"/>
        <source>ABORTED</source>
        <translation>已中止</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="25"/>
        <source>NOT RECORDED</source>
        <translation>未記錄</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="66"/>
        <source>Unit %1</source>
        <translation>產品 %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="69"/>
        <source>%1
Not a verdict on the unit: fix the cause and test it again.</source>
        <translation>%1
此結果並非產品判定：請排除原因後重新測試。</translation>
    </message>
</context>
<context>
    <name>opentop::YieldReport</name>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="100"/>
        <source>%1 rev. %2</source>
        <translation>%1 版次 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="105"/>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="111"/>
        <source>first-pass yield – (no serial tested yet)</source>
        <translation>一次良率 –（尚未測試任何序號）</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="112"/>
        <source>first-pass yield %1 (%2 of %3 serials) · second-pass %4 · last-pass %5</source>
        <translation>一次良率 %1（%3 個序號中 %2 個）· 二次良率 %4 · 最終良率 %5</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="125"/>
        <source>still running (or its station has not restarted since it stopped)</source>
        <translation>仍在執行中 (或其工站停止後尚未重新啟動)</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="127"/>
        <source>interrupted</source>
        <translation>已中斷</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="129"/>
        <source>aborted</source>
        <translation>已中止</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="131"/>
        <source>station error, no reason recorded</source>
        <translation>工站錯誤，未記錄原因</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="133"/>
        <source>failed, no reason recorded</source>
        <translation>不合格，未記錄原因</translation>
    </message>
</context>
</TS>
