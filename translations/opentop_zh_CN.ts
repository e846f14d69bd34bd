<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
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
        <translation>从未读取</translation>
    </message>
    <message>
        <location filename="../model/session/Freshness.cpp" line="41"/>
        <source>last answer %1 (%2)</source>
        <translation>最后应答 %1（%2）</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/main.cpp" line="60"/>
        <source>Commissioning tool for RS-485 Modbus-RTU motor drives.</source>
        <translation>RS-485 Modbus-RTU 电机驱动器调试工具。</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="64"/>
        <source>Language of the program: %1 (default: the language menu&apos;s choice, else the system&apos;s).</source>
        <translation>程序的语言：%1（默认：语言菜单的选择，否则为系统语言）。</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="79"/>
        <source>Open the bus overview and the trends of every drive.</source>
        <translation>打开总线总览和所有驱动器的趋势。</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="80"/>
        <source>Monitoring poll interval in milliseconds.</source>
        <translation>监视轮询周期（毫秒）。</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="83"/>
        <source>Quit after this many seconds and print the monitoring statistics (for measurements).</source>
        <translation>运行指定秒数后退出并输出监视统计（用于测量）。</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="87"/>
        <source>Print the monitoring totals every this many seconds (for measurements).</source>
        <translation>每隔指定秒数输出一次监视统计汇总（用于测量）。</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="97"/>
        <source>--poll-ms needs a number of milliseconds</source>
        <translation>--poll-ms 需要一个毫秒数</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="102"/>
        <source>--quit-after needs a number of seconds</source>
        <translation>--quit-after 需要一个秒数</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="107"/>
        <source>--stats-every needs a number of seconds</source>
        <translation>--stats-every 需要一个秒数</translation>
    </message>
    <message>
        <location filename="../app/gui/StartupProbe.cpp" line="23"/>
        <source>Print how long the start took once the window shows the bus&apos;s drives, then quit (for measurements).</source>
        <translation>在窗口显示总线上的驱动器后，输出启动所用的时间，然后退出（用于测量）。</translation>
    </message>
</context>
<context>
    <name>opentop</name>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="71"/>
        <source>not read</source>
        <translation>未读取</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="91"/>
        <source>No alarm is active.</source>
        <translation>当前无报警。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="93"/>
        <source>Alarm active: %1 %2.</source>
        <translation>报警中：%1 %2。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="96"/>
        <source>An alarm is active.</source>
        <translation>有报警发生。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="99"/>
        <source>This drive is set to clear alarms by a power restart only (%1): Alarm-Reset clears none of them.</source>
        <translation>该驱动器设定为仅通过重新上电清除报警（%1）：报警复位无法清除任何报警。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="106"/>
        <source>%1: could not be read: %2</source>
        <translation>%1：无法读取：%2</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="110"/>
        <source>%1: no records.</source>
        <translation>%1：无记录。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="113"/>
        <source>%1: %2 of %3 records, newest first</source>
        <translation>%1：%3 条记录中的 %2 条，最新在前</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="118"/>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="118"/>
        <source>Code</source>
        <translation>代码</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="118"/>
        <source>Panel</source>
        <translation>面板</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="118"/>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="118"/>
        <source>Cleared by</source>
        <translation>清除方式</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="125"/>
        <source>unknown code</source>
        <translation>未知代码</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="132"/>
        <source>Cause: %1</source>
        <translation>原因：%1</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="134"/>
        <source>Remedy: %1</source>
        <translation>处理方法：%1</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="136"/>
        <source>To clear: %1</source>
        <translation>清除方法：%1</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="142"/>
        <source>Communication error register (%1): could not be read.</source>
        <translation>通信错误寄存器（%1）：无法读取。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="146"/>
        <source>Communication error register (%1): none (0).</source>
        <translation>通信错误寄存器（%1）：无（0）。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="149"/>
        <source>Communication error register (%1): %2, not a known code.</source>
        <translation>通信错误寄存器（%1）：%2，不是已知代码。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="153"/>
        <source>Communication error register (%1): %2 %3
  Cause: %4
  Remedy: %5</source>
        <translation>通信错误寄存器（%1）：%2 %3
  原因：%4
  处理方法：%5</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="27"/>
        <source>Machine-readable JSON on standard output.</source>
        <translation>在标准输出上输出机器可读的 JSON。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="28"/>
        <source>Print every frame sent and received on standard error.</source>
        <translation>在标准错误上输出每一帧收发报文。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="30"/>
        <source>Drive variant where the drive does not report it: VARIANT, or ID=VARIANT,... (e.g. dbu400, 150=dbu400).</source>
        <translation>驱动器未报告机型时指定机型：VARIANT，或 ID=VARIANT,…（例如 dbu400, 150=dbu400）。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="32"/>
        <source>VARIANT</source>
        <translation>VARIANT</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="34"/>
        <source>The drives on the bus, e.g. 1,3,5-7 (default: OPENTOP_BUS_DRIVES, else the drives the last scan of this connection found): before a write or command, their communication group is read to name every drive it also reaches.</source>
        <translation>总线上的驱动器，例如 1,3,5-7（默认：OPENTOP_BUS_DRIVES，否则为此连接上次扫描找到的驱动器）：写入或执行命令前读取其通信组，以列出命令同时到达的每台驱动器。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="37"/>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="39"/>
        <source>Write or command a drive that can be a communication group parent although the drives on the bus are not known (no --bus-drives and no scan of this connection): drives in its group execute it too, unnamed.</source>
        <translation>即使不知道总线上有哪些驱动器（没有 --bus-drives，此连接也未扫描过），仍向可能是通信组主站的驱动器写入或执行命令：组内的驱动器也会执行，且不会列出。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="43"/>
        <source>Show this help, or a command&apos;s help after the command.</source>
        <translation>显示本帮助；放在命令之后则显示该命令的帮助。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="44"/>
        <source>Show the version.</source>
        <translation>显示版本。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="48"/>
        <source>Language of the human output: en, zh_TW, zh_CN, ko, ja (default: the system&apos;s). --json output is the same in every language.</source>
        <translation>供人阅读的输出的语言：en、zh_TW、zh_CN、ko、ja（默认：系统语言）。--json 输出在各语言中都相同。</translation>
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
        <translation>仍在运行</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="32"/>
        <source>no answer</source>
        <translation>无应答</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="38"/>
        <source>top level</source>
        <translation>顶层</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="41"/>
        <source>&quot;schema&quot; must be 1</source>
        <translation>&quot;schema&quot; 必须为 1</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="52"/>
        <source>&quot;family&quot; must be a lower-case id</source>
        <translation>&quot;family&quot; 必须是小写 id</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="60"/>
        <source>serial.parity must be N, E or O</source>
        <translation>serial.parity 必须为 N、E 或 O</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="64"/>
        <source>serial: baud must be 1200–115200 and stopBits 1 or 2</source>
        <translation>serial：baud 必须为 1200–115200，stopBits 必须为 1 或 2</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="76"/>
        <source>serial.formats: &quot;%1&quot; is not a format such as 8N1 or 8E1</source>
        <translation>serial.formats：“%1”不是 8N1 或 8E1 这样的格式</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="80"/>
        <source>serial.formats must hold the default format %1</source>
        <translation>serial.formats 必须包含默认格式 %1</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="84"/>
        <source>serial.powerOnDelayMs must be 0–60000</source>
        <translation>serial.powerOnDelayMs 必须为 0–60000</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="97"/>
        <source>limits: maxReadRegisters 1–125, maxWriteRegisters 1–123</source>
        <translation>limits：maxReadRegisters 1–125，maxWriteRegisters 1–123</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="99"/>
        <source>limits: slaves must lie in 1–247</source>
        <translation>limits：slaves 必须在 1–247 范围内</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="114"/>
        <source>variants[%1] needs id, model and label</source>
        <translation>variants[%1] 需要 id、model 和 label</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="116"/>
        <source>variants[%1]: id &quot;%2&quot; repeated</source>
        <translation>variants[%1]：id &quot;%2&quot; 重复</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="127"/>
        <source>groups[%1] needs a unique id and a label</source>
        <translation>groups[%1] 需要唯一的 id 和 label</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="138"/>
        <source>readBlocks[%1] needs function 3 or 4 and first ≤ last</source>
        <translation>readBlocks[%1] 需要功能码 3 或 4，且 first ≤ last</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="182"/>
        <source>%1 has no name</source>
        <translation>%1 没有名称</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="184"/>
        <source>%1: reset must be one of %2</source>
        <translation>%1：reset 必须是 %2 之一</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="187"/>
        <source>%1: code %2 repeated</source>
        <translation>%1：代码 %2 重复</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="203"/>
        <source>%1: unknown parameter &quot;%2&quot;</source>
        <translation>%1：未知参数 &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="231"/>
        <source>%1 must be a parameter name, a list of names or an object</source>
        <translation>%1 必须是参数名、参数名列表或对象</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="240"/>
        <source>%1: &quot;%2&quot; has no bit field &quot;%3&quot;</source>
        <translation>%1：&quot;%2&quot; 没有位域 &quot;%3&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="246"/>
        <source>%1: %2 is not a value &quot;%3&quot; can be written with</source>
        <translation>%1：%2 不是可用于写入 &quot;%3&quot; 的值</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="264"/>
        <source>decelerationKnobs need the &quot;selected&quot; role</source>
        <translation>decelerationKnobs 需要 &quot;selected&quot; 角色</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="280"/>
        <source>%1 needs &quot;selected&quot; and &quot;maxSeconds&quot;</source>
        <translation>%1 需要 &quot;selected&quot; 和 &quot;maxSeconds&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="283"/>
        <source>%1: &quot;selected&quot; %2 is not a value of the &quot;selected&quot; role, or repeated</source>
        <translation>%1：&quot;selected&quot; %2 不是 &quot;selected&quot; 角色的值，或重复出现</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="288"/>
        <source>%1: &quot;maxSeconds&quot; must be more than 0 and at most 600</source>
        <translation>%1：&quot;maxSeconds&quot; 必须大于 0 且不超过 600</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="320"/>
        <source>%1: &quot;light&quot; must be one of %2, each once</source>
        <translation>%1：&quot;light&quot; 必须是 %2 之一，且每个只能出现一次</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="323"/>
        <source>%1: &quot;colour&quot; must be #rrggbb</source>
        <translation>%1：&quot;colour&quot; 必须为 #rrggbb</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="325"/>
        <source>%1: &quot;label&quot; and &quot;meaning&quot; must not be empty</source>
        <translation>%1：&quot;label&quot; 和 &quot;meaning&quot; 不能为空</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="57"/>
        <source> and %1 more</source>
        <translation> 及另外 %1 个</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="28"/>
        <source>not reached</source>
        <translation>未达到</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="35"/>
        <source>error: %1</source>
        <translation>错误：%1</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="36"/>
        <source>nothing was written</source>
        <translation>未写入任何内容</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="60"/>
        <source>NOT RECORDED (%1)</source>
        <translation>未记录（%1）</translation>
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
        <translation>关于 OpenTOP</translation>
    </message>
    <message>
        <location filename="../ui/help/AboutDialog.cpp" line="22"/>
        <source>&lt;h2&gt;OpenTOP %1&lt;/h2&gt;&lt;p&gt;Commissioning tool for RS-485 Modbus-RTU motor drives: TROY DBU brushless drives and a DC motor PID controller.&lt;/p&gt;&lt;p&gt;Copyright © the OpenTOP developers.&lt;br&gt;Licence: GNU General Public License, version 3 or any later version (GPL-3.0-or-later). This program comes with ABSOLUTELY NO WARRANTY; it is free software, and you are welcome to redistribute it under the terms of that licence.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Built with&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;Qt %2 (run time; built with %3): GNU Lesser General Public License, version 3 (LGPL-3.0-only); Qt Charts: GNU General Public License, version 3 (GPL-3.0-only)&lt;/li&gt;&lt;li&gt;libmodbus %4: GNU Lesser General Public License, version 2.1 or later (LGPL-2.1-or-later)&lt;/li&gt;&lt;li&gt;GoogleTest (tests only): BSD 3-Clause licence&lt;/li&gt;&lt;/ul&gt;</source>
        <translation>&lt;h2&gt;OpenTOP %1&lt;/h2&gt;&lt;p&gt;RS-485 Modbus-RTU 电机驱动器调试工具：TROY DBU 无刷驱动器和直流电机 PID 控制器。&lt;/p&gt;&lt;p&gt;Copyright © the OpenTOP developers.&lt;br&gt;许可证：GNU 通用公共许可证第 3 版或任何更高版本（GPL-3.0-or-later）。本程序不提供任何担保；它是自由软件，欢迎在该许可证条款下再发布。&lt;/p&gt;&lt;p&gt;&lt;b&gt;构建组件&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;Qt %2（运行时；构建时 %3）：GNU 宽通用公共许可证第 3 版（LGPL-3.0-only）；Qt Charts：GNU 通用公共许可证第 3 版（GPL-3.0-only）&lt;/li&gt;&lt;li&gt;libmodbus %4：GNU 宽通用公共许可证 2.1 版或更高版本（LGPL-2.1-or-later）&lt;/li&gt;&lt;li&gt;GoogleTest（仅用于测试）：BSD 3-Clause 许可证&lt;/li&gt;&lt;/ul&gt;</translation>
    </message>
    <message>
        <location filename="../ui/help/AboutDialog.cpp" line="45"/>
        <source>About &amp;Qt</source>
        <translation>关于 Qt(&amp;Q)</translation>
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
        <translation>无法从结果数据库读取用户：%1</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="54"/>
        <source>wrong user name or password</source>
        <translation>用户名或密码错误</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="56"/>
        <source>user &quot;%1&quot;: wrong user name or password</source>
        <translation>用户“%1”：用户名或密码错误</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="60"/>
        <source>user %1 is disabled</source>
        <translation>用户 %1 已停用</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="98"/>
        <source>logged in as %1</source>
        <translation>以%1身份登录</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="123"/>
        <source>user %1 is not an active user</source>
        <translation>用户 %1 不是启用的用户</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="136"/>
        <source>recipe %1 rev. %2, checksum %3</source>
        <translation>配方 %1 版本 %2，校验和 %3</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="142"/>
        <source>this station has no users yet: an approval names its approver, so add users first (opentop-cli eol user add)</source>
        <translation>此工位还没有用户：批准须记录批准人，请先添加用户（opentop-cli eol user add）</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="151"/>
        <source>the approval was not recorded: %1</source>
        <translation>批准未被记录：%1</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="155"/>
        <source>%1; approval %2</source>
        <translation>%1；批准 %2</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="184"/>
        <source>the first user must be an administrator (--role administrator): they add everyone else</source>
        <translation>第一个用户必须是管理员（--role administrator）：由其添加其他所有人</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="189"/>
        <source>add user %1</source>
        <translation>添加用户 %1</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="196"/>
        <source>user %1 exists already</source>
        <translation>用户 %1 已存在</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="202"/>
        <source>user %1 (%2) added as %3</source>
        <translation>已添加用户 %1（%2），角色 %3</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="214"/>
        <source>enable user %1</source>
        <translation>启用用户 %1</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="214"/>
        <source>disable user %1</source>
        <translation>停用用户 %1</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="216"/>
        <location filename="../model/access/AccessCheck.cpp" line="256"/>
        <source>there are no users yet</source>
        <translation>还没有任何用户</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="223"/>
        <location filename="../model/access/AccessCheck.cpp" line="262"/>
        <source>no user %1</source>
        <translation>没有用户 %1</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="228"/>
        <source>%1 is the last active administrator: add another first</source>
        <translation>%1 是最后一位启用的管理员：请先添加另一位</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="254"/>
        <source>set the password of %1</source>
        <translation>设置 %1 的密码</translation>
    </message>
</context>
<context>
    <name>opentop::AccessPolicy</name>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="76"/>
        <source>operator</source>
        <translation>操作员</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="78"/>
        <source>technician</source>
        <translation>技术员</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="80"/>
        <source>engineer</source>
        <translation>工程师</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="84"/>
        <source>administrator</source>
        <translation>管理员</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="96"/>
        <source>test units</source>
        <translation>测试产品</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="98"/>
        <source>reset an alarm and retry</source>
        <translation>复位报警并重试</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="100"/>
        <source>override a retest limit</source>
        <translation>解除复测次数上限</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="102"/>
        <source>leave production mode</source>
        <translation>退出生产模式</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="104"/>
        <source>open or edit a recipe</source>
        <translation>打开或编辑配方</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="106"/>
        <source>approve a recipe</source>
        <translation>批准配方</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="110"/>
        <source>manage users</source>
        <translation>管理用户</translation>
    </message>
</context>
<context>
    <name>opentop::AddressSwitches</name>
    <message>
        <location filename="../model/profile/AddressSwitches.cpp" line="66"/>
        <source>address.names: every switch needs a name</source>
        <translation>address.names：每个开关都需要名称</translation>
    </message>
    <message>
        <location filename="../model/profile/AddressSwitches.cpp" line="74"/>
        <source>address.switches must be &quot;hex-rotary&quot; or &quot;binary-dip&quot;</source>
        <translation>address.switches 必须为 &quot;hex-rotary&quot; 或 &quot;binary-dip&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/AddressSwitches.cpp" line="78"/>
        <source>address.names: 1–%1 switches for this notation</source>
        <translation>address.names：此表示法需要 1–%1 个开关</translation>
    </message>
    <message>
        <location filename="../model/profile/AddressSwitches.cpp" line="81"/>
        <source>address: the switches (%1) cannot set machine number %2</source>
        <translation>address：这些开关（%1）无法设定站号 %2</translation>
    </message>
</context>
<context>
    <name>opentop::AlarmBanner</name>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="16"/>
        <source>Show</source>
        <translation>显示</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="17"/>
        <source>Dismiss</source>
        <translation>忽略</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="24"/>
        <source>Open the drive&apos;s alarm history</source>
        <translation>打开该驱动器的报警履历</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="25"/>
        <source>Hide this alarm until it is cleared; a new alarm shows again</source>
        <translation>在该报警清除前不再显示；新报警会重新显示</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="85"/>
        <source>Machine %1: %2 %3 — %4</source>
        <translation>站号 %1：%2 %3 — %4</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="89"/>
        <source>Machine %1: %2 %3</source>
        <translation>站号 %1：%2 %3</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="91"/>
        <source>Machine %1: alarm %2h (not in the alarm table)</source>
        <translation>站号 %1：报警 %2h（不在报警表中）</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="95"/>
        <source>Machine %1: an alarm is active</source>
        <translation>站号 %1：有报警发生</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/alarms/AlarmBanner.cpp" line="98"/>
        <source>(%n more drive(s) with an alarm)</source>
        <translation>
            <numerusform>（另有 %n 台驱动器报警）</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::AlarmExport</name>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="50"/>
        <source>Machine</source>
        <translation>站号</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="50"/>
        <source>Model</source>
        <translation>型号</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="50"/>
        <source>Kind</source>
        <translation>类型</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="50"/>
        <source>Record</source>
        <translation>记录</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="50"/>
        <source>Code</source>
        <translation>代码</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="50"/>
        <source>Machine name</source>
        <translation>机器名称</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="51"/>
        <source>Panel code</source>
        <translation>面板代码</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="51"/>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="51"/>
        <source>Cleared by</source>
        <translation>清除方式</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="51"/>
        <source>Cause</source>
        <translation>原因</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="51"/>
        <source>Remedy</source>
        <translation>处理方法</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="54"/>
        <source>alarm</source>
        <translation>报警</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="55"/>
        <source>warning</source>
        <translation>警告</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="63"/>
        <source>unknown code</source>
        <translation>未知代码</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="109"/>
        <source>machine %1: %2</source>
        <translation>站号 %1：%2</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/alarms/AlarmExport.cpp" line="132"/>
        <source>%n record(s) of %1 drive(s) written to %2.</source>
        <translation>
            <numerusform>已将 %1 台驱动器的 %n 条记录写入 %2。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="137"/>
        <source>Not everything could be read: %1</source>
        <translation>部分内容无法读取：%1</translation>
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
        <translation>%1 驱动器没有报警复位命令</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="182"/>
        <source>The alarm</source>
        <translation>该报警</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="184"/>
        <source>%1 is cleared.</source>
        <translation>%1 已清除。</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="185"/>
        <source>No alarm was active; nothing to clear.</source>
        <translation>当前无报警，无需清除。</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="188"/>
        <source>%1 is still active: only a power cycle clears it. %2</source>
        <translation>%1 仍未清除：只能通过重新上电清除。%2</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="193"/>
        <source>%1 is still active: the drive is set to clear alarms by a power restart only (%2). Remove the cause, turn the power off, wait 5 s and turn it on again; or change that setting to allow the reset command.</source>
        <translation>%1 仍未清除：该驱动器设定为仅通过重新上电清除报警（%2）。请排除原因，关闭电源，等待 5 s 后再接通；或修改该设定以允许复位命令。</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="199"/>
        <source>%1 is still active: its cause is still present%2. Remove the cause and turn off the start signal, then reset again.</source>
        <translation>%1 仍未清除：原因仍然存在%2。请排除原因并关闭启动信号，然后再次复位。</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="205"/>
        <source>The reset was accepted; whether an alarm is still active could not be read.</source>
        <translation>复位已被接受；但无法读取报警是否仍然存在。</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="207"/>
        <source>The reset failed: %1</source>
        <translation>复位失败：%1</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="210"/>
        <source>(The drive refused the reset: %1)</source>
        <translation>（驱动器拒绝复位：%1）</translation>
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
        <translation>代码</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="50"/>
        <source>Panel</source>
        <translation>面板</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="50"/>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="50"/>
        <source>Cleared by</source>
        <translation>清除方式</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="67"/>
        <source>Cause and remedy</source>
        <translation>原因和处理方法</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="68"/>
        <source>Communication error register</source>
        <translation>通信错误寄存器</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="75"/>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="115"/>
        <source>Select a record to see its cause and remedy.</source>
        <translation>选择一条记录查看其原因和处理方法。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="76"/>
        <source>Not read yet.</source>
        <translation>尚未读取。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="126"/>
        <source>This drive has no communication error register.</source>
        <translation>该驱动器没有通信错误寄存器。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="128"/>
        <source>%1: could not be read.</source>
        <translation>%1：无法读取。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="130"/>
        <source>%1: no error (0).</source>
        <translation>%1：无错误（0）。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="133"/>
        <source>%1: %2, not a known code.</source>
        <translation>%1：%2，不是已知代码。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="135"/>
        <source>%1: %2 %3
Cause: %4
Remedy: %5</source>
        <translation>%1：%2 %3
原因：%4
处理方法：%5</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="147"/>
        <source>No alarm records</source>
        <translation>无报警记录</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="147"/>
        <source>No warning records</source>
        <translation>无警告记录</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="153"/>
        <source>%1: could not be read: %2</source>
        <translation>%1：无法读取：%2</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="156"/>
        <source>%1: %2 of %3 records, newest first</source>
        <translation>%1：%3 条记录中的 %2 条，最新在前</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="167"/>
        <source>unknown code</source>
        <translation>未知代码</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="196"/>
        <source>Record %1: code %2 is not in the %3 table.</source>
        <translation>记录 %1：代码 %2 不在 %3 表中。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="201"/>
        <source>%1 %2 (record %3)</source>
        <translation>%1 %2（记录 %3）</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="203"/>
        <source>Cause: %1</source>
        <translation>原因：%1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="205"/>
        <source>Remedy: %1</source>
        <translation>处理方法：%1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="207"/>
        <source>To clear: %1</source>
        <translation>清除方法：%1</translation>
    </message>
</context>
<context>
    <name>opentop::AlarmsCommand</name>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="165"/>
        <source>Show alarm and warning histories with causes and remedies; reset, erase</source>
        <translation>显示报警和警告履历及原因与处理方法；复位、清除记录</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="172"/>
        <source>Send the alarm reset command, then tell whether the alarm is cleared or needs a power cycle (needs --yes; exit 4 when it stays active).</source>
        <translation>发送报警复位命令，然后显示报警是否已清除或需要重新上电（需要 --yes；报警仍存在时退出码为 4）。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="174"/>
        <source>Erase the alarm and warning records (needs --yes).</source>
        <translation>清除报警和警告记录（需要 --yes）。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="175"/>
        <source>Confirm --reset and --clear-records.</source>
        <translation>确认 --reset 和 --clear-records。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="186"/>
        <source>error: usage: %1 (one machine number)</source>
        <translation>错误：用法：%1（一个站号）</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="194"/>
        <source>error: %1</source>
        <translation>错误：%1</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="200"/>
        <source>error: machine number %1 (%2) keeps no alarm or warning records</source>
        <translation>错误：站号 %1（%2）不保存报警或警告记录</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="207"/>
        <source>error: %1 drives have no %2 command</source>
        <translation>错误：%1 驱动器没有 %2 命令</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="209"/>
        <source>alarm reset</source>
        <translation>报警复位</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="209"/>
        <source>record erase</source>
        <translation>清除记录</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="220"/>
        <source>These change machine number %1; add --yes to send them:</source>
        <translation>以下操作将修改站号 %1；加上 --yes 才会发送：</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="224"/>
        <source>— clears the active alarm if its cause is gone and it is not one that only a power cycle clears</source>
        <translation>— 若原因已排除且该报警并非只能重新上电清除，则清除当前报警</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="249"/>
        <source>Machine number %1 (%2)</source>
        <translation>站号 %1（%2）</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="277"/>
        <source>Alarm reset: %1</source>
        <translation>报警复位：%1</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="300"/>
        <source>Erased: %1 (%2 records); %3</source>
        <translation>已清除：%1（%2 条记录）；%3</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="303"/>
        <source>read back empty.</source>
        <translation>回读为空。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="304"/>
        <source>NOT empty when read back.</source>
        <translation>回读时不为空。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="307"/>
        <source>Erasing failed: %1</source>
        <translation>清除失败：%1</translation>
    </message>
</context>
<context>
    <name>opentop::AlarmsPage</name>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="35"/>
        <source>&amp;Re-read</source>
        <translation>重新读取(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="36"/>
        <source>Reset &amp;alarm…</source>
        <translation>报警复位(&amp;A)…</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="37"/>
        <source>&amp;Clear records…</source>
        <translation>清除记录(&amp;C)…</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="41"/>
        <source>Alarms and warnings of machine %1 (%2)</source>
        <translation>站号 %1（%2）的报警和警告</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="67"/>
        <source>Send the alarm reset command; tells whether the alarm is cleared or only a power cycle clears it</source>
        <translation>发送报警复位命令；显示报警是否已清除或只能重新上电清除</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="69"/>
        <source>Erase the alarm and warning records kept by the drive</source>
        <translation>清除驱动器保存的报警和警告记录</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="75"/>
        <source>This drive keeps no alarm or warning records.</source>
        <translation>该驱动器不保存报警或警告记录。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="105"/>
        <source>Alarm state: %1</source>
        <translation>报警状态：%1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="187"/>
        <source>Reading the records…</source>
        <translation>正在读取记录…</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="203"/>
        <source>No alarm is active.</source>
        <translation>当前无报警。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="205"/>
        <source>Alarm active: %1 %2.</source>
        <translation>报警中：%1 %2。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="207"/>
        <source>An alarm is active.</source>
        <translation>有报警发生。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="210"/>
        <source>This drive is set to clear alarms by a power restart only (%1): Alarm-Reset clears none of them.</source>
        <translation>该驱动器设定为仅通过重新上电清除报警（%1）：报警复位无法清除任何报警。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="214"/>
        <source>Could not be read: %1</source>
        <translation>无法读取：%1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="252"/>
        <source>Writes: %1</source>
        <translation>写入：%1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="253"/>
        <source>This clears the active alarm if its cause is gone. Some alarms are cleared only by a power cycle; the result tells.</source>
        <translation>若原因已排除，将清除当前报警。部分报警只能通过重新上电清除；结果会给出提示。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="256"/>
        <source>This drive is set to clear alarms by a power restart only (%1).</source>
        <translation>该驱动器设定为仅通过重新上电清除报警（%1）。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="258"/>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="260"/>
        <source>Reset alarm</source>
        <translation>报警复位</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="259"/>
        <source>Send the alarm reset command to machine %1?</source>
        <translation>向站号 %1 发送报警复位命令？</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="267"/>
        <source>Sending the alarm reset…</source>
        <translation>正在发送报警复位…</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="273"/>
        <source>Alarm reset: %1</source>
        <translation>报警复位：%1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="276"/>
        <source>Turn the drive&apos;s power off, wait 5 s and turn it on again.</source>
        <translation>请关闭驱动器电源，等待 5 s 后再接通。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="287"/>
        <source>%1 (%2 records)</source>
        <translation>%1（%2 条记录）</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="289"/>
        <source>the alarm and warning records</source>
        <translation>报警和警告记录</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="291"/>
        <source>Clear records</source>
        <translation>清除记录</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="292"/>
        <source>Erase %1 of machine %2?</source>
        <translation>清除站号 %2 的%1？</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="292"/>
        <source> and </source>
        <translation> 和 </translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="293"/>
        <source>The records cannot be restored. Writes: %1</source>
        <translation>记录清除后无法恢复。写入：%1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="295"/>
        <source>Erase</source>
        <translation>清除</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="302"/>
        <source>Erasing the records…</source>
        <translation>正在清除记录…</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="310"/>
        <source>Erased: %1 (%2 records); %3</source>
        <translation>已清除：%1（%2 条记录）；%3</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="313"/>
        <source>read back empty.</source>
        <translation>回读为空。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="314"/>
        <source>NOT empty when read back.</source>
        <translation>回读时不为空。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="316"/>
        <source>Erasing failed: %1</source>
        <translation>清除失败：%1</translation>
    </message>
</context>
<context>
    <name>opentop::AutotunePanel</name>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="24"/>
        <source>Autotune…</source>
        <translation>自整定…</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="28"/>
        <source>Accept</source>
        <translation>接受</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="29"/>
        <source>Reject</source>
        <translation>拒绝</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="30"/>
        <source>Store in the drive</source>
        <translation>保存到驱动器</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="48"/>
        <source>Writes the proposed gains to the drive (temporary until stored) and offers a step test to compare with the prediction</source>
        <translation>将建议增益写入驱动器（保存前仅临时有效），并提供阶跃测试以与预测结果比较</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="50"/>
        <source>Writes back the gains the drive had before</source>
        <translation>将驱动器原来的增益写回</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="51"/>
        <source>Stores the gains in the drive so that they survive a power cycle; asks first unless the step after Accept passed the check</source>
        <translation>将增益保存到驱动器，重新上电后仍保留；接受后的阶跃未通过检查时，会先询问</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="57"/>
        <source>Operating speed:</source>
        <translation>运行速度：</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="58"/>
        <source>Relay amplitude:</source>
        <translation>继电器幅值：</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="59"/>
        <source>%</source>
        <translation>%</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="60"/>
        <source>Rule:</source>
        <translation>整定规则：</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="64"/>
        <source>Present</source>
        <translation>当前</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="65"/>
        <source>Proposed</source>
        <translation>建议</translation>
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
        <translation>D 周期</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="113"/>
        <source>Enter an operating speed above 0 %1.</source>
        <translation>请输入大于 0 %1 的运行速度。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="117"/>
        <source>Enter a relay amplitude of 1–50 %.</source>
        <translation>请输入 1–50 % 的继电器幅值。</translation>
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
        <translation>尚无自整定结果。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="153"/>
        <source>Autotune failed: %1</source>
        <translation>自整定失败：%1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="155"/>
        <source>What to change: %1</source>
        <translation>应更改的项目：%1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="165"/>
        <source>Relay: Ku %1 %/%2, Tu %3 ms measured, %4 readings per period (one every %5 ms)</source>
        <translation>继电器：Ku %1 %/%2，实测 Tu %3 ms，每周期读取 %4 次（每 %5 ms 一次）</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="175"/>
        <source>The drive&apos;s own loop (model): Ku %1 %/%2, Tu %3 ms</source>
        <translation>驱动器自身的环路（模型）：Ku %1 %/%2，Tu %3 ms</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="180"/>
        <source>Proposal: the rule&apos;s P × %1, Ti × %2; predicted overshoot %3 %, settling %4</source>
        <translation>建议值：规则的 P × %1，Ti × %2；预测超调 %3 %，调节 %4</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="184"/>
        <source>not within the record</source>
        <translation>记录时间内未稳定</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="208"/>
        <source>Check after Accept: passed.</source>
        <translation>接受后的检查：通过。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="209"/>
        <source>Check after Accept: FAILED. Reject writes back the gains the drive had.</source>
        <translation>接受后的检查：未通过。按“拒绝”会写回驱动器原来的增益。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="171"/>
        <source>Model: K %1 %2/%, τ %3 ms, dead time %4 ms</source>
        <translation>模型：K %1 %2/%，τ %3 ms，纯滞后时间 %4 ms</translation>
    </message>
</context>
<context>
    <name>opentop::BackupCommand</name>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="37"/>
        <source>Save every setting of drives to a backup file (written only when all were read)</source>
        <translation>将驱动器的全部设定保存到备份文件（仅在全部读取成功后写入）</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="43"/>
        <source>The backup file to write (replaced atomically).</source>
        <translation>要写入的备份文件（原子替换）。</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="44"/>
        <source>FILE</source>
        <translation>FILE</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="46"/>
        <source>Every drive the connection knows (a simulated bus), or every drive a scan finds.</source>
        <translation>连接已知的所有驱动器（模拟总线），或扫描找到的所有驱动器。</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="54"/>
        <source>error: name the machine numbers, or give --all: backup ID... -o FILE</source>
        <translation>错误：请指定站号，或使用 --all：backup ID... -o FILE</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="63"/>
        <location filename="../cli/BackupCommand.cpp" line="245"/>
        <location filename="../cli/BackupCommand.cpp" line="251"/>
        <source>error: %1</source>
        <translation>错误：%1</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="72"/>
        <source>scanning the bus for drives…</source>
        <translation>正在扫描总线上的驱动器…</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="87"/>
        <source>warning: machine number %1 answered, but its identification failed: it is not backed up; name it to try again (backup %1 -o FILE).</source>
        <translation>警告：站号 %1 有应答，但识别失败：未备份它；请指定这个站号再试一次（backup %1 -o FILE）。</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="108"/>
        <source>error: the port %1 was lost while reading %2 (%3)</source>
        <translation>错误：读取 %2 时端口 %1 丢失（%3）</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="112"/>
        <location filename="../cli/BackupCommand.cpp" line="247"/>
        <source>nothing written to %1</source>
        <translation>未写入 %1</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="120"/>
        <source>error: give the file to write: backup ID... -o FILE</source>
        <translation>错误：请指定要写入的文件：backup ID... -o FILE</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="124"/>
        <source>error: %1; nothing read</source>
        <translation>错误：%1；未读取任何内容</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="136"/>
        <source>interrupted: nothing written</source>
        <translation>已中断：未写入任何内容</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="140"/>
        <source>error: no drive answers on %1; nothing written</source>
        <translation>错误：%1 上没有驱动器应答；未写入任何内容</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="166"/>
        <source>machine number %1</source>
        <translation>站号 %1</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="226"/>
        <source>interrupted while reading machine number %1: nothing written</source>
        <translation>读取站号 %1 时中断：未写入任何内容</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="188"/>
        <source>%1: %2 settings read in %3 requests, %4 ms</source>
        <translation>%1：%3 次请求读取 %2 项设定，%4 ms</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="196"/>
        <source>%1: reading failed, %2 of %3 settings read (%4 requests, %5 ms)</source>
        <translation>%1：读取失败，已读取 %3 项设定中的 %2 项（%4 次请求，%5 ms）</translation>
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
        <translation>保存已读取的驱动器(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="31"/>
        <source>C&amp;lose</source>
        <translation>关闭(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="44"/>
        <source>Back up drives</source>
        <translation>备份驱动器</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="46"/>
        <source>Machine number</source>
        <translation>站号</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="46"/>
        <source>Model</source>
        <translation>型号</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="46"/>
        <source>Progress</source>
        <translation>进度</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="46"/>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="54"/>
        <source>Save only the drives that were read; the others are left out</source>
        <translation>仅保存已读取的驱动器；其余的不保存</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="56"/>
        <source>Stop after the drive being read</source>
        <translation>读完当前驱动器后停止</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="84"/>
        <source>Nothing was read: %1.</source>
        <translation>未读取任何数据：%1。</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="107"/>
        <source>Waiting</source>
        <translation>等待中</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="111"/>
        <source>%v of %m drives</source>
        <translation>%v / %m 台驱动器</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/BackupDialog.cpp" line="112"/>
        <source>Reading the settings of %n drive(s)…</source>
        <translation>
            <numerusform>正在读取 %n 台驱动器的设定…</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="123"/>
        <source>Stopping after the drive being read…</source>
        <translation>读完当前驱动器后停止…</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="161"/>
        <source>Not read (cancelled)</source>
        <translation>未读取（已取消）</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="37"/>
        <source>drive %1: not identified, nothing read</source>
        <translation>驱动器 %1：未识别，未读取任何内容</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="166"/>
        <source>Not identified</source>
        <translation>未识别</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="139"/>
        <source>Reading…</source>
        <translation>正在读取…</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/BackupDialog.cpp" line="153"/>
        <source>%n setting(s) read in %1 ms</source>
        <translation>
            <numerusform>%1 ms 内读取了 %n 项设定</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="167"/>
        <source>Value not allowed</source>
        <translation>值不允许</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="168"/>
        <source>Read failed</source>
        <translation>读取失败</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="184"/>
        <source>Not read: drive(s) %1. Nothing has been saved yet.</source>
        <translation>未读取：驱动器 %1。尚未保存任何内容。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/BackupDialog.cpp" line="190"/>
        <source>Save the %n drive(s) that were read?</source>
        <translation>
            <numerusform>保存已读取的 %n 台驱动器？</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/BackupDialog.cpp" line="214"/>
        <source>Saved %n drive(s) to %1.</source>
        <translation>
            <numerusform>已将 %n 台驱动器保存到 %1。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="220"/>
        <source>Left out (not read): drive(s) %1.</source>
        <translation>未保存（未读取）：驱动器 %1。</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="224"/>
        <source>Could not save %1: %2</source>
        <translation>无法保存 %1：%2</translation>
    </message>
</context>
<context>
    <name>opentop::BackupFile</name>
    <message>
        <location filename="../model/files/BackupFile.cpp" line="309"/>
        <source>%1 is larger than %2 MB, the most a backup file may hold (a backup of 247 drives is far smaller); not a backup file</source>
        <translation>%1 大于 %2 MB，超过备份文件的上限（247 台驱动器的备份也远小于此）；不是备份文件</translation>
    </message>
</context>
<context>
    <name>opentop::BackupFileParser</name>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="49"/>
        <source>not a JSON file: %1 at byte %2</source>
        <translation>不是 JSON 文件：%1，位于字节 %2</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="53"/>
        <source>not an OpenTOP backup file: the JSON is not an object</source>
        <translation>不是 OpenTOP 备份文件：JSON 不是对象</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="63"/>
        <source>&quot;created&quot; is not an ISO 8601 date and time</source>
        <translation>&quot;created&quot; 不是 ISO 8601 日期时间</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="75"/>
        <source>the file holds no drives (&quot;devices&quot; must be a non-empty list)</source>
        <translation>文件中没有驱动器（&quot;devices&quot; 必须是非空列表）</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="82"/>
        <source>%1: not a drive</source>
        <translation>%1：不是驱动器</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="84"/>
        <source>machine number %1 appears twice</source>
        <translation>站号 %1 出现了两次</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="98"/>
        <source>not an OpenTOP backup file (&quot;format&quot; is &quot;%1&quot;, not &quot;%2&quot;)</source>
        <translation>不是 OpenTOP 备份文件（&quot;format&quot; 为 &quot;%1&quot;，而非 &quot;%2&quot;）</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="100"/>
        <source>not an OpenTOP backup file (no &quot;format&quot;: &quot;%1&quot;)</source>
        <translation>不是 OpenTOP 备份文件（没有 &quot;format&quot;: &quot;%1&quot;）</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="105"/>
        <source>&quot;formatVersion&quot; must be a whole number from 1</source>
        <translation>&quot;formatVersion&quot; 必须是从 1 起的整数</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="107"/>
        <source>written by a newer OpenTOP (format version %1); this version reads format version %2</source>
        <translation>由更新版本的 OpenTOP 写入（格式版本 %1）；本版本读取格式版本 %2</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="113"/>
        <source>the file has no checksum (&quot;checksum&quot;: &quot;sha256:…&quot;); it was not written by OpenTOP or was changed afterwards</source>
        <translation>文件没有校验和（&quot;checksum&quot;: &quot;sha256:…&quot;）；它不是由 OpenTOP 写入的，或写入后被修改过</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="118"/>
        <source>the file was changed after it was written (checksum mismatch)</source>
        <translation>文件在写入后被修改过（校验和不一致）</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="128"/>
        <source>%1: &quot;slave&quot; must be a machine number 1–247</source>
        <translation>%1：&quot;slave&quot; 必须是站号 1–247</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="129"/>
        <source>%1 (machine number %2)</source>
        <translation>%1（站号 %2）</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="133"/>
        <source>%1: unknown family &quot;%2&quot;; known: %3</source>
        <translation>%1：未知系列 &quot;%2&quot;；已知：%3</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="138"/>
        <source>%1: &quot;variant&quot; must be text or null</source>
        <translation>%1：&quot;variant&quot; 必须是文本或 null</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="143"/>
        <source>%1: unknown variant &quot;%2&quot; of family %3; known: %4</source>
        <translation>%1：系列 %3 的未知机型 &quot;%2&quot;；已知：%4</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="145"/>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="153"/>
        <source>%1: &quot;machineName&quot; must be text</source>
        <translation>%1：&quot;machineName&quot; 必须是文本</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="155"/>
        <source>%1: &quot;machineName&quot;: %2</source>
        <translation>%1：&quot;machineName&quot;：%2</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="160"/>
        <source>%1: &quot;parameters&quot; must be a list</source>
        <translation>%1：&quot;parameters&quot; 必须是列表</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="180"/>
        <source>%1: no &quot;name&quot;</source>
        <translation>%1：没有 &quot;name&quot;</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="183"/>
        <source>%1 %2: &quot;registers&quot; must be a list</source>
        <translation>%1 %2：&quot;registers&quot; 必须是列表</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="187"/>
        <source>%1 %2: registers must be numbers 0–65535</source>
        <translation>%1 %2：寄存器必须是 0–65535 的数字</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="193"/>
        <source>%1 %2: address &quot;%3&quot;, but the %4 profile has it at %5</source>
        <translation>%1 %2：地址为 &quot;%3&quot;，但 %4 设备描述中其地址为 %5</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="218"/>
        <source>%1: %2: &quot;value&quot; %3 does not match its registers (%4)</source>
        <translation>%1：%2：&quot;value&quot; %3 与其寄存器不一致（%4）</translation>
    </message>
</context>
<context>
    <name>opentop::BackupValidator</name>
    <message>
        <location filename="../model/files/BackupValidator.cpp" line="16"/>
        <source>unknown parameter &quot;%1&quot;: the %2 profile has no such setting</source>
        <translation>未知参数 &quot;%1&quot;：%2 设备描述中没有该设定</translation>
    </message>
    <message>
        <location filename="../model/files/BackupValidator.cpp" line="21"/>
        <source>&quot;%1&quot; is not a setting that backups hold</source>
        <translation>&quot;%1&quot; 不是备份所保存的设定</translation>
    </message>
    <message>
        <location filename="../model/files/BackupValidator.cpp" line="25"/>
        <source>&quot;%1&quot; appears twice</source>
        <translation>&quot;%1&quot; 出现了两次</translation>
    </message>
    <message>
        <location filename="../model/files/BackupValidator.cpp" line="28"/>
        <source>%1: %2 registers, but the parameter has %3</source>
        <translation>%1：%2 个寄存器，但该参数有 %3 个</translation>
    </message>
    <message>
        <location filename="../model/files/BackupValidator.cpp" line="53"/>
        <source>%1: its allowed values depend on %2, which the file does not hold</source>
        <translation>%1：其允许值取决于 %2，但文件中没有该项</translation>
    </message>
</context>
<context>
    <name>opentop::BackupViewer</name>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="24"/>
        <source>Backup file</source>
        <translation>备份文件</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="35"/>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="35"/>
        <source>Label</source>
        <translation>标签</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="35"/>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="35"/>
        <source>Registers</source>
        <translation>寄存器</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="39"/>
        <source>&amp;Open…</source>
        <translation>打开(&amp;O)…</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="40"/>
        <source>Open another backup file</source>
        <translation>打开另一个备份文件</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="41"/>
        <source>C&amp;lose</source>
        <translation>关闭(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="62"/>
        <source>%1: no such file</source>
        <translation>%1：文件不存在</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="68"/>
        <source>the file could not be read</source>
        <translation>无法读取该文件</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="69"/>
        <source>Backup file %1</source>
        <translation>备份文件 %1</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="77"/>
        <source>Open backup file</source>
        <translation>打开备份文件</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="78"/>
        <source>OpenTOP backups (*.json);;All files (*)</source>
        <translation>OpenTOP 备份 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="100"/>
        <source>File: %1</source>
        <translation>文件：%1</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="101"/>
        <source>Refused: %1</source>
        <translation>已拒绝：%1</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="116"/>
        <source>, %1 bit/s, parity %2, %3 stop bit(s)</source>
        <translation>，%1 bit/s，校验位 %2，停止位 %3</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="118"/>
        <source>File: %1
Written by %2 on %3 (UTC)
Read from: %4
Drives: %5</source>
        <translation>文件：%1
由 %2 于 %3（UTC）写入
读取自：%4
驱动器：%5</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="127"/>
        <source>%1 %2, firmware %3</source>
        <translation>%1 %2，固件 %3</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="130"/>
        <source>(variant unknown)</source>
        <translation>（机型未知）</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/BackupViewer.cpp" line="133"/>
        <source>%n setting(s)</source>
        <translation>
            <numerusform>%n 项设定</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::BarHideButton</name>
    <message>
        <location filename="../ui/widgets/BarHideButton.cpp" line="9"/>
        <source>Hide this bar</source>
        <translation>隐藏此栏</translation>
    </message>
    <message>
        <location filename="../ui/widgets/BarHideButton.cpp" line="10"/>
        <source>Hide</source>
        <translation>隐藏</translation>
    </message>
</context>
<context>
    <name>opentop::BusDocks</name>
    <message>
        <location filename="../ui/main/BusDocks.cpp" line="28"/>
        <source>Traffic log</source>
        <translation>报文日志</translation>
    </message>
    <message>
        <location filename="../ui/main/BusDocks.cpp" line="35"/>
        <source>Bus overview</source>
        <translation>总线总览</translation>
    </message>
    <message>
        <location filename="../ui/main/BusDocks.cpp" line="36"/>
        <source>Trends</source>
        <translation>趋势</translation>
    </message>
    <message>
        <location filename="../ui/main/BusDocks.cpp" line="37"/>
        <source>Communication groups</source>
        <translation>通信组</translation>
    </message>
    <message>
        <location filename="../ui/main/BusDocks.cpp" line="40"/>
        <location filename="../ui/main/BusDocks.cpp" line="110"/>
        <source>Not connected</source>
        <translation>未连接</translation>
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
        <translation>%1 分钟前</translation>
    </message>
    <message>
        <location filename="../cli/BusDriveList.cpp" line="15"/>
        <source>%1 h ago</source>
        <translation>%1 小时前</translation>
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
        <translation>模拟总线的驱动器</translation>
    </message>
    <message>
        <location filename="../cli/BusDriveList.cpp" line="30"/>
        <source>the drives last seen on %1</source>
        <translation>上次在 %1 看到的驱动器</translation>
    </message>
    <message>
        <location filename="../cli/BusDriveList.cpp" line="31"/>
        <source>the drives the last scan of %1 found (%2, %3)</source>
        <translation>上次扫描 %1 找到的驱动器（%2，%3）</translation>
    </message>
    <message>
        <location filename="../cli/BusDriveList.cpp" line="38"/>
        <source>no list of the drives on the bus</source>
        <translation>没有总线上驱动器的列表</translation>
    </message>
</context>
<context>
    <name>opentop::BusGroups</name>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="109"/>
        <source>machine number %1 is the parent of communication group %1: what is sent to it is also executed by %2 (children do not reply)</source>
        <translation>站号 %1 是通信组 %1 的组父站：发送给它的内容也会由 %2 执行（组子站不应答）</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="127"/>
        <location filename="../model/bus/BusGroups.cpp" line="136"/>
        <source>%1 and %2</source>
        <translation>%1 和 %2</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="145"/>
        <source>This also reaches machine number %1 (the child of communication group %2; it executes it without replying).</source>
        <translation>该操作也会作用于站号 %1（通信组 %2 的组子站；执行但不应答）。</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="149"/>
        <source>This also reaches machine numbers %1 (the children of communication group %2; they execute it without replying).</source>
        <translation>该操作也会作用于站号 %1（通信组 %2 的组子站；执行但不应答）。</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="159"/>
        <source>child of %1</source>
        <translation>%1 的组子站</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="162"/>
        <source>parent of %1</source>
        <translation>%1 的组父站</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="170"/>
        <source>machine number %1 is a child of %2 and itself a parent: a child must not be a group parent</source>
        <translation>站号 %1 是 %2 的组子站，本身又是组父站：组子站不能同时是组父站</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="175"/>
        <source>machine number %1 is in communication group %2, but no drive %2 is known: frames to %2 reach %1 although nothing answers</source>
        <translation>站号 %1 属于通信组 %2，但没有已知的驱动器 %2：发往 %2 的报文会作用于 %1，但无任何应答</translation>
    </message>
</context>
<context>
    <name>opentop::BusLeaving</name>
    <message>
        <location filename="../ui/main/BusLeaving.cpp" line="68"/>
        <location filename="../ui/main/BusLeaving.cpp" line="88"/>
        <source>quit</source>
        <translation>退出</translation>
    </message>
    <message>
        <location filename="../ui/main/BusLeaving.cpp" line="77"/>
        <source>Unwritten changes</source>
        <translation>未写入的修改</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/main/BusLeaving.cpp" line="78"/>
        <source>%n edit(s) have not been written to the drives. Quit and discard them?</source>
        <translation>
            <numerusform>有 %n 项修改尚未写入驱动器。退出并放弃这些修改？</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::BusListMenu</name>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="30"/>
        <source>&amp;Name this machine…</source>
        <translation>为此机器命名(&amp;N)…</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="36"/>
        <source>&amp;Identify again</source>
        <translation>重新识别(&amp;I)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="47"/>
        <source>&amp;Remove from list</source>
        <translation>从列表中移除(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="62"/>
        <source>Name of %1 (up to %2 characters; empty removes the name):</source>
        <translation>%1 的名称（最多 %2 个字符；留空即删除名称）：</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="69"/>
        <source>Name this machine</source>
        <translation>为此机器命名</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="76"/>
        <source>Machine number %1 has no name now.</source>
        <translation>站号 %1 现在没有名称。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="77"/>
        <source>Machine number %1 is now named %2.</source>
        <translation>站号 %1 现在名为 %2。</translation>
    </message>
</context>
<context>
    <name>opentop::BusListModel</name>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="76"/>
        <source>Machine number: the drive&apos;s address on the bus (1–247)</source>
        <translation>站号：驱动器在总线上的地址（1–247）</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="78"/>
        <source>The drive&apos;s MONITOR LED: red alarm, green ready, orange CW, sky blue CCW, purple external interrupt, blue memory or communication error, grey no answer</source>
        <translation>驱动器的 MONITOR 指示灯：红色报警，绿色就绪，橙色 CW，天蓝色 CCW，紫色外部中断，蓝色存储器或通信错误，灰色无应答</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="85"/>
        <source>LED</source>
        <translation>LED</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="87"/>
        <source>No.</source>
        <translation>站号</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="91"/>
        <source>Family</source>
        <translation>系列</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="93"/>
        <source>Model</source>
        <translation>型号</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="95"/>
        <source>Firmware</source>
        <translation>固件</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="97"/>
        <source>State</source>
        <translation>状态</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="99"/>
        <source>Control priority</source>
        <translation>控制优先级</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="73"/>
        <source>How each drive&apos;s machine number is set on its switches:
%1</source>
        <translation>各驱动器的站号在其开关上的设定方式：
%1</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="89"/>
        <source>Switches</source>
        <translation>开关</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="101"/>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="113"/>
        <source>Two drives may share machine number %1 (%2): check the address switches of every drive on the line, give each drive its own number and restart its power; a bad termination or a swapped A/B pair also corrupts replies.</source>
        <translation>可能有两台驱动器共用站号 %1（%2）：请检查线路上每台驱动器的地址开关，为每台驱动器设定各自的站号并重新上电；终端电阻不良或 A/B 接反也会使应答损坏。</translation>
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
        <translation>%1 — 机型未知</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="142"/>
        <source>V%1</source>
        <translation>V%1</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="171"/>
        <source>Status light %1: %2 (%3)</source>
        <translation>状态灯 %1：%2（%3）</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="175"/>
        <source>The drive&apos;s manual: %1</source>
        <translation>驱动器手册：%1</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="178"/>
        <source>Status light grey: not live — %1</source>
        <translation>状态灯灰色：非实时 — %1</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="186"/>
        <source>No name yet: Name… in the context menu (F2) names this machine</source>
        <translation>尚无名称：在右键菜单中选择“命名…”（F2）为此机器命名</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="187"/>
        <source>%1: the name given to this machine (F2 changes it)</source>
        <translation>%1：此机器的名称（F2 可更改）</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="190"/>
        <source>Requests to this drive go out at %1, its own line format, not the port&apos;s: the line is switched to it and back between transactions. Change it with Line format… in the context menu.</source>
        <translation>发往该驱动器的请求以它自己的通信格式 %1 发送，而不是端口的格式：线路在两次通信之间切换过去再切换回来。可在右键菜单的“通信格式…”中更改。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="197"/>
        <source>The drive does not report its variant. Choose it from the context menu (Variant) so that values are checked against the right limits.</source>
        <translation>该驱动器未报告其机型。请在右键菜单（机型）中选择，以便按正确的限值检查数值。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="206"/>
        <source>The drive takes run commands from its I/O terminals; test runs over the bus need communication priority.</source>
        <translation>该驱动器通过 I/O 端子接收运行命令；通过总线试运行需要通信优先级。</translation>
    </message>
</context>
<context>
    <name>opentop::BusMemory</name>
    <message>
        <location filename="../model/bus/BusMemory.cpp" line="79"/>
        <source>the simulated bus</source>
        <translation>模拟总线</translation>
    </message>
</context>
<context>
    <name>opentop::BusOverview</name>
    <message>
        <location filename="../ui/bus/BusOverview.cpp" line="37"/>
        <source>Double-click a drive to open its pages.</source>
        <translation>双击驱动器打开其页面。</translation>
    </message>
</context>
<context>
    <name>opentop::BusOverviewModel</name>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="133"/>
        <source>Drive</source>
        <translation>驱动器</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="135"/>
        <source>State</source>
        <translation>状态</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="137"/>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="139"/>
        <source>Display</source>
        <translation>显示</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="141"/>
        <source>Target</source>
        <translation>目标</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="143"/>
        <source>Load</source>
        <translation>负载</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="145"/>
        <source>Alarm</source>
        <translation>报警</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="147"/>
        <source>Last answer</source>
        <translation>最后应答</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="174"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="164"/>
        <source>connection lost; %1</source>
        <translation>连接丢失；%1</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="166"/>
        <source>no answer: %1; %2</source>
        <translation>无应答：%1；%2</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="203"/>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="206"/>
        <source>active</source>
        <translation>发生中</translation>
    </message>
</context>
<context>
    <name>opentop::BusPanel</name>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="35"/>
        <source>&amp;Scan</source>
        <translation>扫描(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="38"/>
        <source>A&amp;dd drive…</source>
        <translation>添加驱动器(&amp;D)…</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="40"/>
        <source>Ca&amp;ncel</source>
        <translation>取消(&amp;N)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="50"/>
        <source>Ask every machine number of the range who answers</source>
        <translation>逐个询问范围内的每个站号是否应答</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="52"/>
        <source>&amp;from</source>
        <translation>从(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="54"/>
        <source>&amp;to</source>
        <translation>到(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="77"/>
        <source>Identify one machine number and add it to the list</source>
        <translation>识别一个站号并将其添加到列表</translation>
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
        <translation>扫描进度</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="85"/>
        <source>Stop the scan after the request on the wire</source>
        <translation>在当前线路上的请求完成后停止扫描</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="95"/>
        <source>Rescan at %1</source>
        <translation>以 %1 重新扫描</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="135"/>
        <source>Drives on the bus</source>
        <translation>总线上的驱动器</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="151"/>
        <source>Name this machine…</source>
        <translation>为此机器命名…</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="207"/>
        <source>%v of %m (machine number %1)</source>
        <translation>%v / %m（站号 %1）</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="211"/>
        <source>Machine number %1 answered, identification failed: retrying (%2 of %3)… Polling waits until the scan is over.</source>
        <translation>站号 %1 有应答，但识别失败：正在重试（第 %2 次，共 %3 次）… 轮询将等到扫描结束。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="223"/>
        <source>Scanning machine numbers %1–%2 on %3, %4 ms each… Polling waits until the scan is over.</source>
        <translation>正在扫描 %3 上的站号 %1–%2，每个 %4 ms… 轮询将等到扫描结束。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="295"/>
        <source>If one is on this bus, add it with Add drive and its line format.</source>
        <translation>如果总线上有这种驱动器，请用“添加驱动器”连同它的通信格式添加。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="300"/>
        <source>Machine number %1 answered, but its identification failed, also when asked again: add it by hand with Add drive…, or check its line settings and scan again.</source>
        <translation>站号 %1 有应答，但识别失败，重新询问也一样：请用“添加驱动器…”手动添加，或检查它的通信设定后重新扫描。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="243"/>
        <source>Cancelling after the request on the wire…</source>
        <translation>正在等待线路上的请求完成后取消…</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="59"/>
        <source>Machine numbers 1–247, as set on each drive&apos;s switches:
%1</source>
        <translation>站号 1–247，按各驱动器开关的设定：
%1</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="261"/>
        <source>Did not answer the last scan.</source>
        <translation>上次扫描未应答。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="267"/>
        <source>The scan stopped at machine number %1: %2</source>
        <translation>扫描在站号 %1 处停止：%2</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/bus/BusPanel.cpp" line="272"/>
        <source>Scan cancelled after machine numbers %1–%2 (%3 of %4): %n drive(s) found.</source>
        <translation>
            <numerusform>在站号 %1–%2 后取消扫描（%4 个中的 %3 个）：找到 %n 台驱动器。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/bus/BusPanel.cpp" line="280"/>
        <source>%n drive(s) found on machine numbers %1–%2 in %3 s.</source>
        <translation>
            <numerusform>在 %3 s 内于站号 %1–%2 上找到 %n 台驱动器。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="321"/>
        <source>Asking machine number %1…</source>
        <translation>正在询问站号 %1…</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="326"/>
        <source>Machine number %1: %2 added.</source>
        <translation>站号 %1：已添加 %2。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="328"/>
        <source>Machine number %1: %2 %3</source>
        <translation>站号 %1：%2 %3</translation>
    </message>
    <message>
        <location filename="../ui/bus/VariantMenu.cpp" line="26"/>
        <source>&amp;Variant</source>
        <translation>机型(&amp;V)</translation>
    </message>
</context>
<context>
    <name>opentop::BusRecallBar</name>
    <message>
        <location filename="../ui/bus/BusRecallBar.cpp" line="21"/>
        <source>&amp;Scan the bus</source>
        <translation>扫描总线(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusRecallBar.cpp" line="44"/>
        <source>Last time on %1: %2.</source>
        <translation>上次在 %1 上：%2。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusRecallBar.cpp" line="46"/>
        <source>&amp;Restore the drive last seen</source>
        <translation>恢复上次识别到的驱动器(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusRecallBar.cpp" line="47"/>
        <source>&amp;Restore the %1 drives last seen</source>
        <translation>恢复上次识别到的 %1 台驱动器(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusRecallBar.cpp" line="48"/>
        <source>Identify the drives at these machine numbers again, with the variants set last time</source>
        <translation>按上次设定的机型，重新识别这些站号上的驱动器</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusRecallBar.cpp" line="62"/>
        <source>No drive is known on %1 yet. Scan the bus to find the drives.</source>
        <translation>%1 上尚无已知的驱动器。请扫描总线查找驱动器。</translation>
    </message>
</context>
<context>
    <name>opentop::BusRestore</name>
    <message>
        <location filename="../model/files/BusRestore.cpp" line="26"/>
        <source>machine number %1 is not a drive on the bus</source>
        <translation>站号 %1 不是总线上的驱动器</translation>
    </message>
    <message>
        <location filename="../model/files/BusRestore.cpp" line="97"/>
        <source>not attempted</source>
        <translation>未尝试</translation>
    </message>
</context>
<context>
    <name>opentop::BusScanner</name>
    <message>
        <location filename="../model/bus/BusScanner.cpp" line="152"/>
        <source>garbled replies twice (%1): two drives probably share machine number %2; check their address switches (%3)</source>
        <translation>两次收到损坏的应答（%1）：可能有两台驱动器共用站号 %2；请检查其地址开关（%3）</translation>
    </message>
    <message>
        <location filename="../model/bus/BusScanner.cpp" line="158"/>
        <source>answers, but none of the device profiles matches (%1)</source>
        <translation>有应答，但没有匹配的设备描述（%1）</translation>
    </message>
    <message>
        <location filename="../model/bus/BusScanner.cpp" line="171"/>
        <source>answered, but its identification read got no reply (%1), also when asked %2 more times: add it by hand, or scan with a longer wait</source>
        <translation>有应答，但识别读取没有回复（%1），再询问 %2 次仍然如此：请手动添加，或用更长的等待时间重新扫描</translation>
    </message>
    <message>
        <location filename="../model/bus/BusScanner.cpp" line="243"/>
        <source>answered late at first (after the %1 ms wait); a longer wait makes scans of this bus reliable</source>
        <translation>首次应答较迟（超过 %1 ms 等待时间）；加长等待时间可使该总线的扫描更可靠</translation>
    </message>
</context>
<context>
    <name>opentop::BusSpec</name>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="57"/>
        <source>&quot;%1&quot;: the braces do not pair; a drive&apos;s defects are written in braces after its number, e.g. dbu200@3{firmware=1.4,stall}</source>
        <translation>&quot;%1&quot;：花括号不成对；驱动器的缺陷写在其编号后的花括号中，例如 dbu200@3{firmware=1.4,stall}</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="62"/>
        <source>empty device list; write TYPE@ID[,TYPE@ID...], e.g. dbu200@1,dcpid@7 (types: %1)</source>
        <translation>设备列表为空；请写成 TYPE@ID[,TYPE@ID...]，例如 dbu200@1,dcpid@7（类型：%1）</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="70"/>
        <source>&quot;%1&quot;: the defects in braces end the item, e.g. dbu200@3{stall}</source>
        <translation>&quot;%1&quot;：花括号中的缺陷必须位于该项末尾，例如 dbu200@3{stall}</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="78"/>
        <source>&quot;%1&quot;: write TYPE@ID or TYPE@FIRST-LAST, e.g. dbu200@1</source>
        <translation>&quot;%1&quot;：请写成 TYPE@ID 或 TYPE@FIRST-LAST，例如 dbu200@1</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="83"/>
        <source>&quot;%1&quot;: unknown device type &quot;%2&quot;; known types: %3</source>
        <translation>&quot;%1&quot;：未知设备类型 &quot;%2&quot;；已知类型：%3</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="90"/>
        <source>&quot;%1&quot;: the machine number must be a number or a range such as 1-16</source>
        <translation>&quot;%1&quot;：站号必须是数字或范围，例如 1-16</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="94"/>
        <source>&quot;%1&quot;: machine number %2 is outside %3–%4 for %5</source>
        <translation>&quot;%1&quot;：站号 %2 超出 %5 的范围 %3–%4</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="101"/>
        <source>machine number %1 is given twice</source>
        <translation>站号 %1 重复指定</translation>
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
        <translation>工位错误</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="56"/>
        <source>INTERRUPTED</source>
        <translation>已中断</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="58"/>
        <source>NOT FINISHED</source>
        <translation>未完成</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="71"/>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="78"/>
        <source>End-of-line test certificate</source>
        <translation>下线检测检验证书</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="81"/>
        <source>Serial number</source>
        <translation>序列号</translation>
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
        <translation>%1，版本 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="83"/>
        <source>Recipe checksum</source>
        <translation>配方校验和</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="84"/>
        <source>Recipe approved by</source>
        <translation>配方批准人</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="85"/>
        <source>not approved (station without users)</source>
        <translation>未批准（工位无用户）</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="86"/>
        <source>%1 (approval %2)</source>
        <translation>%1（批准 %2）</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="87"/>
        <source>Station</source>
        <translation>工位</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="88"/>
        <source>Operator</source>
        <translation>操作员</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="89"/>
        <location filename="../model/eol/CertificateHtml.cpp" line="148"/>
        <source>Attempt</source>
        <translation>测试次数</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="90"/>
        <source>%1 (tests of this serial under this recipe)</source>
        <translation>第 %1 次（该序列号在此配方下的测试）</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="91"/>
        <source>not counted (recorded before attempts were)</source>
        <translation>未计次（记录时尚未统计测试次数）</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="92"/>
        <location filename="../model/eol/CertificateHtml.cpp" line="148"/>
        <source>Started</source>
        <translation>开始时间</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="93"/>
        <source>Ended</source>
        <translation>结束时间</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="94"/>
        <source>Record</source>
        <translation>记录</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="103"/>
        <source>First failure:</source>
        <translation>首个不合格项：</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/eol/CertificateHtml.cpp" line="121"/>
        <source>This serial failed %n earlier test(s); they are listed below.</source>
        <translation>
            <numerusform>该序列号此前有 %n 次测试不合格，列于下方。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="124"/>
        <source>Drives</source>
        <translation>驱动器</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="125"/>
        <source>Machine number</source>
        <translation>站号</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="125"/>
        <source>Model</source>
        <translation>型号</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="125"/>
        <source>Variant</source>
        <translation>机型</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="125"/>
        <source>Firmware</source>
        <translation>固件</translation>
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
        <translation>设定</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="133"/>
        <location filename="../model/eol/CertificateHtml.cpp" line="141"/>
        <source>Drive</source>
        <translation>驱动器</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="133"/>
        <source>Setting</source>
        <translation>设定</translation>
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
        <translation>已写入</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="134"/>
        <source>Read back</source>
        <translation>回读</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="134"/>
        <source>Verified</source>
        <translation>已校验</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="137"/>
        <source>written</source>
        <translation>已写入</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="137"/>
        <source>already set</source>
        <translation>已是该值</translation>
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
        <translation>测量值</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="141"/>
        <source>Step</source>
        <translation>步骤</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="141"/>
        <source>Quantity</source>
        <translation>测量项</translation>
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
        <translation>该序列号此前的测试</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="148"/>
        <source>Reason</source>
        <translation>原因</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="150"/>
        <source>%1 rev. %2</source>
        <translation>%1 版本 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="151"/>
        <source>–</source>
        <translation>–</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="161"/>
        <source>Bus traffic around the failure</source>
        <translation>不合格前后的总线报文</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="176"/>
        <source>read from the drive</source>
        <translation>从驱动器读取</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="178"/>
        <source>proven by the variant probe</source>
        <translation>由机型探测证实</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="180"/>
        <source>confirmed by a person</source>
        <translation>由人员确认</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="182"/>
        <source>ASSUMED, not proven</source>
        <translation>推定，未证实</translation>
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
        <translation>下线检测证书 %1</translation>
    </message>
    <message>
        <location filename="../report/CertificatePdf.cpp" line="57"/>
        <source>%1 · %2 · page %3 of %4</source>
        <translation>%1 · %2 · 第 %3 页，共 %4 页</translation>
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
        <translation>用法：%1 [选项] COMMAND [参数]

RS-485 Modbus-RTU 电机驱动器调试工具。

命令：
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
连接（所有与驱动器通信的命令）：
  --port PATH | --tcp HOST:PORT | --sim SPEC
  --family F  --baud N  --parity N|E|O  --stop-bits N  --timeout MS  --retries N
  默认值随系列而定：dbu 19200 8N1，dcpid 9600 8E1；--timeout 200，
  --retries 3（线路有干扰时再加 2 次：即最近有请求需要重试）。
  仅限串口：--rs485 off|auto|kernel|rts（由谁切换 RS-485
  收发方向；off：适配器），--rts-polarity high|low，--rts-delay US，
  --low-latency on|off（默认 on）。scan 会显示驱动程序接受的设置。
输出：--json  --trace  --variant VARIANT  --lang CODE
通信组：写入或执行命令前，读取总线上驱动器的通信组：--bus-drives LIST
（或 OPENTOP_BUS_DRIVES），否则为此连接上次扫描找到的驱动器（在此处或在窗口中）；
两者都没有时，写入可能是组主站的驱动器会被拒绝，除非加上 --no-group-check

退出码：0 成功，1 通信失败，2 用法错误，3 值或文件无效
（未写入任何内容），4 校验不一致或驱动器未停止，
5 eol run 不合格，6 eol run 工位错误（未对产品作出判定），
130 被 Ctrl-C、SIGTERM 或 SIGHUP 中断（会报告已完成的操作）。

&quot;%1 help COMMAND&quot; 显示命令的选项。
</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="125"/>
        <source>note: standard output could not be written (closed early, or the disk is full): what the command printed there is lost; the work itself ran to its end and exit status %1 says how it ended</source>
        <translation>注意：无法写入标准输出（提前关闭或磁盘已满）：命令在该处输出的内容已丢失；工作本身已执行完毕，退出状态 %1 表示其结果</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="190"/>
        <location filename="../cli/CliApp.cpp" line="245"/>
        <source>Try &quot;%1 --help&quot;.</source>
        <translation>请尝试 &quot;%1 --help&quot;。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="210"/>
        <source>%1: unknown command &quot;%2&quot;; commands: </source>
        <translation>%1：未知命令 &quot;%2&quot;；可用命令： </translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="219"/>
        <source>Usage: %1 [options] %2
%3
</source>
        <translation>用法：%1 [选项] %2
%3
</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="233"/>
        <source>%1 %2: --%3 is not an option of this command; see &quot;%1 help %2&quot;</source>
        <translation>%1 %2：--%3 不是该命令的选项；请参阅 &quot;%1 help %2&quot;</translation>
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
        <translation>错误：%1</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="154"/>
        <source>serial line: %1</source>
        <translation>串行线路：%1</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="177"/>
        <source>%1 &quot;%2&quot;: %3</source>
        <translation>%1 &quot;%2&quot;：%3</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="289"/>
        <source>machine number %1: no connection</source>
        <translation>站号 %1：无连接</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="294"/>
        <source>machine number %1: %2%3</source>
        <translation>站号 %1：%2%3</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="352"/>
        <source>--variant %1: &quot;%2&quot; is not a machine number 1–247</source>
        <translation>--variant %1：&quot;%2&quot; 不是站号 1–247</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="356"/>
        <source>--variant %1: &quot;%2&quot; is not a drive variant; use one of %3</source>
        <translation>--variant %1：&quot;%2&quot; 不是驱动器机型；请使用 %3 之一</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="374"/>
        <source>&quot;%1&quot; is not a machine number 1–247 or a range such as 3-8</source>
        <translation>&quot;%1&quot; 不是站号 1–247，也不是 3-8 这样的范围</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="384"/>
        <source>no machine number given</source>
        <translation>未指定站号</translation>
    </message>
</context>
<context>
    <name>opentop::CliIdentity</name>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="73"/>
        <source>Who does it (a user of the results database); the password comes from OPENTOP_PASSWORD or is asked on the terminal.</source>
        <translation>执行者（结果数据库的用户）；密码取自 OPENTOP_PASSWORD，否则在终端上询问。</translation>
    </message>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="75"/>
        <source>NAME</source>
        <translation>名称</translation>
    </message>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="86"/>
        <source>error: no password: set %1 or run on a terminal</source>
        <translation>错误：没有密码：请设置 %1 或在终端上运行</translation>
    </message>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="91"/>
        <source>Again: </source>
        <translation>再输入一次：</translation>
    </message>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="93"/>
        <source>error: the passwords differ; nothing was changed</source>
        <translation>错误：两次密码不同；未做任何更改</translation>
    </message>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="104"/>
        <source>error: name who does it with --user NAME</source>
        <translation>错误：请用 --user NAME 指定执行者</translation>
    </message>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="108"/>
        <source>Password for %1: </source>
        <translation>%1 的密码：</translation>
    </message>
</context>
<context>
    <name>opentop::CodeEntry</name>
    <message>
        <location filename="../model/profile/CodeTable.cpp" line="10"/>
        <source>Alarm-Reset</source>
        <translation>报警复位</translation>
    </message>
    <message>
        <location filename="../model/profile/CodeTable.cpp" line="12"/>
        <source>power cycle</source>
        <translation>重新上电</translation>
    </message>
    <message>
        <location filename="../model/profile/CodeTable.cpp" line="14"/>
        <source>by itself</source>
        <translation>自动</translation>
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
        <translation>处理方法：%1</translation>
    </message>
</context>
<context>
    <name>opentop::CommLossArm</name>
    <message>
        <location filename="../model/eol/CommLossArm.cpp" line="29"/>
        <source>cannot read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/CommLossArm.cpp" line="40"/>
        <source>the communication-loss stop cannot be armed (%1 = %2 s): %3; the motor is not started without it</source>
        <translation>无法启用通信中断停止（%1 = %2 s）：%3；没有它不会启动电机</translation>
    </message>
</context>
<context>
    <name>opentop::CommandReadBack</name>
    <message>
        <location filename="../ui/run/CommandReadBack.cpp" line="43"/>
        <source>Read back after the command at %1:</source>
        <translation>%1 发送命令后回读：</translation>
    </message>
    <message>
        <location filename="../ui/run/CommandReadBack.cpp" line="46"/>
        <source>The motor is running.</source>
        <translation>电机正在运行。</translation>
    </message>
    <message>
        <location filename="../ui/run/CommandReadBack.cpp" line="46"/>
        <source>The motor is stopped.</source>
        <translation>电机已停止。</translation>
    </message>
    <message>
        <location filename="../ui/run/CommandReadBack.cpp" line="48"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../ui/run/CommandReadBack.cpp" line="50"/>
        <source>(not read: %1)</source>
        <translation>（未读取：%1）</translation>
    </message>
    <message>
        <location filename="../ui/run/CommandReadBack.cpp" line="57"/>
        <source>The drives of its communication group, read after the command:</source>
        <translation>命令后读取的通信组驱动器：</translation>
    </message>
</context>
<context>
    <name>opentop::CompareCommand</name>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="36"/>
        <source>Show the settings that differ; A, B: a machine number, FILE or FILE:ID (exit 0 whether or not they differ)</source>
        <translation>显示不同的设定；A、B：站号、FILE 或 FILE:ID（无论是否有差异，退出码均为 0）</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="43"/>
        <source>Compare A with the profile&apos;s factory defaults; settings the manual gives no default for are listed, never counted as differences.</source>
        <translation>将 A 与设备描述中的出厂默认值比较；手册未给出默认值的设定会列出，但不计为差异。</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="70"/>
        <location filename="../cli/CompareCommand.cpp" line="87"/>
        <location filename="../cli/CompareCommand.cpp" line="146"/>
        <source>error: %1</source>
        <translation>错误：%1</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="64"/>
        <source>interrupted</source>
        <translation>已中断</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="74"/>
        <source>drive %1</source>
        <translation>驱动器 %1</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="106"/>
        <source>error: %1 holds several drives (%2): name one as %1:ID</source>
        <translation>错误：%1 包含多台驱动器（%2）：请用 %1:ID 指定其中一台</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="110"/>
        <source>error: %1 holds no drive with machine number %2; it holds %3</source>
        <translation>错误：%1 中没有站号为 %2 的驱动器；其中有 %3</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="126"/>
        <source>error: compare A B, or compare A --defaults (A, B: a machine number, FILE or FILE:ID)</source>
        <translation>错误：compare A B 或 compare A --defaults（A、B：站号、FILE 或 FILE:ID）</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="144"/>
        <source>factory defaults</source>
        <translation>出厂默认值</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="172"/>
        <source>A: %1 (%2)</source>
        <translation>A：%1（%2）</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="175"/>
        <source>B: %1</source>
        <translation>B：%1</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="180"/>
        <source>parameter</source>
        <translation>参数</translation>
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
        <translation>（无此项）</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="186"/>
        <source> in %1 settings compared</source>
        <translation> （共比较 %1 项设定）</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="188"/>
        <source>no differences (%1 settings compared)</source>
        <translation>无差异（共比较 %1 项设定）</translation>
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
        <translation>仅显示差异(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="37"/>
        <source>Co&amp;mpare</source>
        <translation>比较(&amp;M)</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="39"/>
        <source>Compare settings</source>
        <translation>比较设定</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="40"/>
        <source>Side A</source>
        <translation>A 侧</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="41"/>
        <source>Side B</source>
        <translation>B 侧</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="57"/>
        <location filename="../ui/files/CompareDialog.cpp" line="227"/>
        <source>Setting</source>
        <translation>设定</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="57"/>
        <location filename="../ui/files/CompareDialog.cpp" line="227"/>
        <source>Parameter</source>
        <translation>参数</translation>
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
        <translation>按设定名或参数名筛选</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="65"/>
        <source>Read the chosen sides and compare them (drives are read fresh)</source>
        <translation>读取所选两侧并进行比较（驱动器会重新读取）</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="78"/>
        <source>C&amp;lose</source>
        <translation>关闭(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="111"/>
        <source>%1 refused: %2</source>
        <translation>%1 已拒绝：%2</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="125"/>
        <source>Reading…</source>
        <translation>正在读取…</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="150"/>
        <source>side A</source>
        <translation>A 侧</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="150"/>
        <source>side B</source>
        <translation>B 侧</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="154"/>
        <source>Factory defaults</source>
        <translation>出厂默认值</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="161"/>
        <source>Choose a backup file and a drive in it for %1.</source>
        <translation>请为%1选择一个备份文件及其中的一台驱动器。</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="165"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="175"/>
        <source>Choose an identified drive on the bus for %1.</source>
        <translation>请为%1选择总线上一台已识别的驱动器。</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="183"/>
        <source>%1: cannot read %2</source>
        <translation>%1：无法读取 %2</translation>
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
        <translation>出厂默认值（%1）</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="239"/>
        <source>(no documented default)</source>
        <translation>（无文档默认值）</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="240"/>
        <location filename="../ui/files/CompareDialog.cpp" line="242"/>
        <source>(not held)</source>
        <translation>（无此项）</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/CompareDialog.cpp" line="258"/>
        <source>%n difference(s)</source>
        <translation>
            <numerusform>%n 处差异</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="259"/>
        <source> in %1 settings compared</source>
        <translation> （共比较 %1 项设定）</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="262"/>
        <source>Note: %1</source>
        <translation>注意：%1</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="269"/>
        <source>No factory default documented (never counted as a difference): %1</source>
        <translation>无文档出厂默认值（不计为差异）：%1</translation>
    </message>
</context>
<context>
    <name>opentop::CompareSide</name>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="23"/>
        <source>Browse…</source>
        <translation>浏览…</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="27"/>
        <source>Drive on the bus</source>
        <translation>总线上的驱动器</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="28"/>
        <source>Drive in a backup file</source>
        <translation>备份文件中的驱动器</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="30"/>
        <source>Factory defaults</source>
        <translation>出厂默认值</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="34"/>
        <source>Drive %1 (%2)</source>
        <translation>驱动器 %1（%2）</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="41"/>
        <source>Backup file</source>
        <translation>备份文件</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="46"/>
        <source>Source:</source>
        <translation>来源：</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="47"/>
        <source>Drive:</source>
        <translation>驱动器：</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="48"/>
        <source>File:</source>
        <translation>文件：</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="49"/>
        <source>Drive in file:</source>
        <translation>文件中的驱动器：</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="170"/>
        <source>Open backup file</source>
        <translation>打开备份文件</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="171"/>
        <source>OpenTOP backups (*.json);;All files (*)</source>
        <translation>OpenTOP 备份 (*.json);;所有文件 (*)</translation>
    </message>
</context>
<context>
    <name>opentop::Comparer</name>
    <message>
        <location filename="../model/files/Comparer.cpp" line="15"/>
        <source>nothing to compare: %1 is a %2 drive, %3 a %4 drive</source>
        <translation>无法比较：%1 是 %2 驱动器，%3 是 %4 驱动器</translation>
    </message>
    <message>
        <location filename="../model/files/Comparer.cpp" line="20"/>
        <source>the variants differ: %1 and %2</source>
        <translation>机型不同：%1 和 %2</translation>
    </message>
    <message>
        <location filename="../model/files/Comparer.cpp" line="55"/>
        <source>factory defaults</source>
        <translation>出厂默认值</translation>
    </message>
</context>
<context>
    <name>opentop::ConnectionDialog</name>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="63"/>
        <source>Connect to a bus</source>
        <translation>连接总线</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="68"/>
        <source>&amp;Serial port</source>
        <translation>串口(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="68"/>
        <source>Modbus &amp;TCP gateway</source>
        <translation>Modbus TCP 网关(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="69"/>
        <source>Si&amp;mulated bus</source>
        <translation>模拟总线(&amp;M)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="85"/>
        <source>&amp;Advanced</source>
        <translation>高级(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="108"/>
        <source>&amp;Connect</source>
        <translation>连接(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="129"/>
        <source>&amp;Refresh</source>
        <translation>刷新(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="130"/>
        <source>List the serial ports again (after plugging in an adapter)</source>
        <translation>重新列出串口（插入适配器后）</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="135"/>
        <source>&amp;Port:</source>
        <translation>端口(&amp;P)：</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="144"/>
        <source>Custom</source>
        <translation>自定义</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="146"/>
        <source>%1 (%2 %3%4%5)</source>
        <translation>%1（%2 %3%4%5）</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="153"/>
        <source>Fills in the factory line settings of a drive family</source>
        <translation>填入该驱动器系列的出厂通信设定</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="156"/>
        <source>&amp;Family defaults:</source>
        <translation>系列默认值(&amp;F)：</translation>
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
        <translation>波特率(&amp;B)：</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="163"/>
        <source>None (N)</source>
        <translation>无 (N)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="164"/>
        <source>Even (E)</source>
        <translation>偶校验 (E)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="165"/>
        <source>Odd (O)</source>
        <translation>奇校验 (O)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="166"/>
        <source>P&amp;arity:</source>
        <translation>校验位(&amp;A)：</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="168"/>
        <source>1 bit</source>
        <translation>1 位</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="169"/>
        <source>2 bits</source>
        <translation>2 位</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="170"/>
        <source>S&amp;top bits:</source>
        <translation>停止位(&amp;T)：</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="186"/>
        <source>e.g. 192.168.1.10</source>
        <translation>例如 192.168.1.10</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="187"/>
        <source>&amp;Host:</source>
        <translation>主机(&amp;H)：</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="190"/>
        <source>Modbus TCP uses port 502</source>
        <translation>Modbus TCP 使用端口 502</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="191"/>
        <source>TCP p&amp;ort:</source>
        <translation>TCP 端口(&amp;O)：</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="203"/>
        <source>Device types and machine numbers: TYPE@NUMBER, comma separated. Types: %1</source>
        <translation>设备类型和站号：TYPE@NUMBER，以逗号分隔。类型：%1</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="206"/>
        <source>&amp;Devices:</source>
        <translation>设备(&amp;D)：</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="220"/>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="221"/>
        <source>How long to wait for each reply</source>
        <translation>等待每个应答的时间</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="222"/>
        <source>Response &amp;timeout:</source>
        <translation>应答超时(&amp;T)：</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="225"/>
        <source>Extra attempts after a request got no valid reply</source>
        <translation>请求未获得有效应答后的额外尝试次数</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="226"/>
        <source>R&amp;etries:</source>
        <translation>重试次数(&amp;E)：</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="333"/>
        <source>The device list is not valid.</source>
        <translation>设备列表无效。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="26"/>
        <source>The port is in use by another program (named above where the system tells it): a terminal program, ModemManager, another OpenTOP window or an opentop-cli command. Close it, or disconnect the other window, and connect again. Nothing was sent on the port.</source>
        <translation>该端口正被其他程序占用（系统能给出名称时已显示在上方）：终端程序、ModemManager、另一个 OpenTOP 窗口或 opentop-cli 命令。请关闭该程序，或断开另一个窗口的连接，然后重新连接。端口上未发送任何内容。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="33"/>
        <source>Your user may not open serial ports: add it to the dialout group with the command above, then log out and in again.</source>
        <translation>当前用户无权打开串口：请用上面的命令将其加入 dialout 组，然后注销并重新登录。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="36"/>
        <source>Your user may not open serial ports. Add it to the dialout group:
    sudo usermod -aG dialout $USER
then log out and in again (the group applies to new sessions only).</source>
        <translation>当前用户无权打开串口。请将其加入 dialout 组：
    sudo usermod -aG dialout $USER
然后注销并重新登录（该组仅对新会话生效）。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="41"/>
        <source>The port %1 does not exist: the USB adapter may be unplugged or have come back under another name, or the path is mistyped. Plug it in, press Refresh and pick it from the list; for a pseudo-terminal check that the program serving it (opentop-sim, socat) still runs.</source>
        <translation>端口 %1 不存在：USB 适配器可能已拔出或以其他名称重新出现，或路径输入有误。请插入适配器，按“刷新”并从列表中选择；如果是伪终端，请检查提供它的程序（opentop-sim、socat）是否仍在运行。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="48"/>
        <source>The connection opened but no drive answered. Check that the baud rate, parity and stop bits (%1) match the drives&apos; settings (DBU: 19200 8N1, DC controller: 9600 8E1) — a framing mismatch looks like silence — that the machine number is right, and that the A and B (D+ and D−) wires are not swapped.</source>
        <translation>连接已打开，但没有驱动器应答。请检查波特率、校验位和停止位（%1）是否与驱动器的设定一致（DBU：19200 8N1，直流控制器：9600 8E1）——帧格式不一致时看起来就像无应答——站号是否正确，以及 A 和 B（D+ 和 D−）线是否接反。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="56"/>
        <source>The gateway %1:%2 did not accept the connection: check the address and port (Modbus TCP uses 502), that the gateway is powered and on this network, and that no firewall blocks it.</source>
        <translation>网关 %1:%2 未接受连接：请检查地址和端口（Modbus TCP 使用 502），网关是否已通电并在本网络中，以及是否有防火墙阻挡。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="63"/>
        <source>Check that the adapter is plugged in, that %1 is the right port, and that no other program uses it.</source>
        <translation>请检查适配器是否已插入，%1 是否为正确的端口，以及是否有其他程序正在使用它。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="66"/>
        <source>Check the connection settings and try again.</source>
        <translation>请检查连接设定后重试。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="68"/>
        <source>Could not use %1: %2</source>
        <translation>无法使用 %1：%2</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="69"/>
        <source>What to check:</source>
        <translation>检查事项：</translation>
    </message>
</context>
<context>
    <name>opentop::ConnectionOptions</name>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="30"/>
        <source>--rs485 %1: use off (the adapter switches direction itself), auto, kernel or rts</source>
        <translation>--rs485 %1：请使用 off（由适配器自行切换方向）、auto、kernel 或 rts</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="36"/>
        <source>--rts-polarity %1: use high or low (the RTS level while sending)</source>
        <translation>--rts-polarity %1：请使用 high 或 low（发送时的 RTS 电平）</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="44"/>
        <source>--rts-delay %1: use 0–%2 µs (0: the driver&apos;s or libmodbus&apos; own delay)</source>
        <translation>--rts-delay %1：请使用 0–%2 µs（0：使用驱动程序或 libmodbus 自身的延时）</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="51"/>
        <source>--low-latency %1: use on or off</source>
        <translation>--low-latency %1：请使用 on 或 off</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="61"/>
        <source>--%1 applies to a serial port (--port), not to a Modbus TCP gateway (--tcp)</source>
        <translation>--%1 适用于串口（--port），不适用于 Modbus TCP 网关（--tcp）</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="65"/>
        <source>--%1 applies to a serial port (--port), not to a simulated bus</source>
        <translation>--%1 适用于串口（--port），不适用于模拟总线</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="66"/>
        <source>--%1 applies to a serial port only: give it with --port PATH</source>
        <translation>--%1 仅适用于串口：请与 --port PATH 一起指定</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="74"/>
        <source>Serial device (e.g. /dev/ttyUSB0 or a pty path).</source>
        <translation>串口设备（例如 /dev/ttyUSB0 或 pty 路径）。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="75"/>
        <source>PATH</source>
        <translation>PATH</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="76"/>
        <source>Modbus TCP gateway, HOST:PORT (port defaults to 502).</source>
        <translation>Modbus TCP 网关，HOST:PORT（端口默认为 502）。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="77"/>
        <source>HOST:PORT</source>
        <translation>HOST:PORT</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="78"/>
        <source>In-process simulated bus, e.g. dbu200@1,dbu400@150,dcpid@7.</source>
        <translation>进程内模拟总线，例如 dbu200@1,dbu400@150,dcpid@7。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="79"/>
        <source>SPEC</source>
        <translation>SPEC</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="81"/>
        <source>Device family whose serial defaults apply (dbu: 19200 8N1, dcpid: 9600 8E1).</source>
        <translation>采用其串口默认值的设备系列（dbu：19200 8N1，dcpid：9600 8E1）。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="82"/>
        <source>FAMILY</source>
        <translation>FAMILY</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="83"/>
        <source>Baud rate, 1200–115200.</source>
        <translation>波特率，1200–115200。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="83"/>
        <source>BAUD</source>
        <translation>BAUD</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="84"/>
        <source>Parity: N, E or O.</source>
        <translation>校验位：N、E 或 O。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="84"/>
        <source>N|E|O</source>
        <translation>N|E|O</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="85"/>
        <source>Stop bits: 1 or 2.</source>
        <translation>停止位：1 或 2。</translation>
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
        <translation>使用与端口不同通信格式的驱动器，在两次通信之间切换：ID=[BAUD:]FORMAT,...，例如 7=9600:8E1 或 7=8N2（BAUD 默认为端口的波特率）。DBU 只能用 8N1；DC 控制器用 8E1、8O1 或 8N2。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="90"/>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="92"/>
        <source>Response timeout per attempt in ms, 10–10000 (default 200).</source>
        <translation>每次尝试的应答超时（ms），10–10000（默认 200）。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="92"/>
        <source>MS</source>
        <translation>MS</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="94"/>
        <source>Extra attempts after no reply or a garbled one, 0–10 (default 3; 2 more while the line is noisy).</source>
        <translation>无应答或应答损坏后的额外尝试次数，0–10（默认 3；线路有干扰时再加 2 次）。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="98"/>
        <source>Who switches the RS-485 direction (serial port only): off (default: the adapter itself, as USB–RS-485 adapters do), kernel (the driver&apos;s RS-485 mode), rts (RTS from the program) or auto (kernel where the driver has it, else rts).</source>
        <translation>由谁切换 RS-485 收发方向（仅限串口）：off（默认：由适配器自行切换，USB–RS-485 适配器即如此）、kernel（驱动程序的 RS-485 模式）、rts（由程序控制 RTS）或 auto（驱动程序支持时用 kernel，否则用 rts）。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="101"/>
        <source>MODE</source>
        <translation>MODE</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="103"/>
        <source>RTS level while sending with --rs485 kernel, rts or auto: high (default) or low.</source>
        <translation>使用 --rs485 kernel、rts 或 auto 时发送期间的 RTS 电平：high（默认）或 low。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="104"/>
        <source>high|low</source>
        <translation>high|low</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="106"/>
        <source>RTS delay before and after sending in µs, 0–100000 (default 0: the driver&apos;s, or libmodbus&apos; one character time; the kernel rounds up to whole ms).</source>
        <translation>发送前后的 RTS 延时（µs），0–100000（默认 0：使用驱动程序的延时，或 libmodbus 的 1 个字符时间；内核会向上取整到整 ms）。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="108"/>
        <source>US</source>
        <translation>US</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="110"/>
        <source>Ask the serial driver to pass received bytes on at once (USB adapters otherwise hold them up to 16 ms): on (default) or off.</source>
        <translation>要求串口驱动程序立即转交收到的字节（否则 USB 适配器最多会缓存 16 ms）：on（默认）或 off。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="112"/>
        <source>on|off</source>
        <translation>on|off</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="157"/>
        <source>give only one of --port, --tcp and --sim</source>
        <translation>--port、--tcp 和 --sim 只能指定其中一个</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="159"/>
        <source>no bus given: use --port PATH, --tcp HOST:PORT or --sim SPEC</source>
        <translation>未指定总线：请使用 --port PATH、--tcp HOST:PORT 或 --sim SPEC</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="168"/>
        <source>--family %1: unknown family; use one of %2</source>
        <translation>--family %1：未知系列；请使用 %2 之一</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="187"/>
        <source>--tcp: &quot;%1&quot; is not HOST:PORT</source>
        <translation>--tcp：&quot;%1&quot; 不是 HOST:PORT</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="196"/>
        <source>--sim: %1</source>
        <translation>--sim：%1</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="209"/>
        <source>--baud %1: use a baud rate 1200–115200 (e.g. 9600, 19200, 38400)</source>
        <translation>--baud %1：请使用 1200–115200 的波特率（例如 9600、19200、38400）</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="213"/>
        <source>--stop-bits %1: use 1 or 2</source>
        <translation>--stop-bits %1：请使用 1 或 2</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="215"/>
        <source>--timeout %1: use a response timeout of 10–10000 ms</source>
        <translation>--timeout %1：请使用 10–10000 ms 的应答超时</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="218"/>
        <source>--retries %1: use 0–10 extra attempts</source>
        <translation>--retries %1：请使用 0–10 次额外尝试</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="223"/>
        <source>--parity %1: use N (none), E (even) or O (odd)</source>
        <translation>--parity %1：请使用 N（无）、E（偶）或 O（奇）</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="229"/>
        <source>--drive-format applies to a serial port (--port) or a simulated bus, not to a Modbus TCP gateway (--tcp): the gateway sets its line itself</source>
        <translation>--drive-format 适用于串口（--port）或模拟总线，不适用于 Modbus TCP 网关（--tcp）：网关自行设定它的线路</translation>
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
        <translation>模拟总线 — 无硬件</translation>
    </message>
    <message>
        <location filename="../ui/main/ConnectionStatus.cpp" line="22"/>
        <source>These drives exist only in this program; nothing moves.</source>
        <translation>这些驱动器仅存在于本程序中；不会有任何动作。</translation>
    </message>
    <message>
        <location filename="../ui/main/ConnectionStatus.cpp" line="27"/>
        <location filename="../ui/main/ConnectionStatus.cpp" line="76"/>
        <source>Not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <location filename="../ui/main/ConnectionStatus.cpp" line="54"/>
        <source>Connected: %1</source>
        <translation>已连接：%1</translation>
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
        <translation>通信组：%1（总线 › 通信组）</translation>
    </message>
</context>
<context>
    <name>opentop::DbuSimDevice</name>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="340"/>
        <source>alarm 0x%1</source>
        <translation>报警 0x%1</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="341"/>
        <source>running</source>
        <translation>运行中</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="342"/>
        <source>stopped</source>
        <translation>已停止</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="343"/>
        <source>%1 %2 r/min (target %3) SPno%4 load %5 % %6, %7 priority, %8%9</source>
        <translation>%1 %2 r/min（目标 %3）SPno%4 负载 %5 % %6，%7优先级，%8%9</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="347"/>
        <source>communication</source>
        <translation>通信</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="347"/>
        <source>I/O</source>
        <translation>I/O</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="348"/>
        <source>offline</source>
        <translation>离线</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="348"/>
        <source>online</source>
        <translation>在线</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="349"/>
        <source>, ignoring stop</source>
        <translation>，忽略停止</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="357"/>
        <source>usage: %1 ID CODE</source>
        <translation>用法：%1 ID CODE</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="360"/>
        <source>warning cleared</source>
        <translation>警告已清除</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="365"/>
        <source>unknown %1 code %2; allowed: %3</source>
        <translation>未知%1代码 %2；允许：%3</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="373"/>
        <source>%1 0x%2 raised</source>
        <translation>已触发%1 0x%2</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="384"/>
        <source>usage: ignore-stop ID on|off</source>
        <translation>用法：ignore-stop ID on|off</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="386"/>
        <source>stop commands are acknowledged and ignored</source>
        <translation>停止命令会被应答但被忽略</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="387"/>
        <source>stop commands are obeyed</source>
        <translation>停止命令会被执行</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="403"/>
        <source>usage: %1 ID VALUE with VALUE %2..%3</source>
        <translation>用法：%1 ID VALUE，VALUE 范围 %2..%3</translation>
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
        <translation>直流控制器</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="46"/>
        <source>Re&amp;load stored configuration</source>
        <translation>重新载入已保存的配置(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="68"/>
        <source>Store &amp;configuration</source>
        <translation>保存配置(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="69"/>
        <source>Store P&amp;ID</source>
        <translation>保存 PID(&amp;I)</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="70"/>
        <source>Store pre&amp;set</source>
        <translation>保存预设(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="73"/>
        <source>Writes %1 = 1: %2</source>
        <translation>写入 %1 = 1：%2</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="78"/>
        <source>Writes store.config = 0: the controller reloads the stored configuration; unstored configuration changes are discarded</source>
        <translation>写入 store.config = 0：控制器重新载入已保存的配置；未保存的配置修改将被丢弃</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="85"/>
        <source>Speed mode and motor currents</source>
        <translation>速度模式和电机电流</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="86"/>
        <source>Speed &amp;mode:</source>
        <translation>速度模式(&amp;M)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="87"/>
        <source>Rated current:</source>
        <translation>额定电流：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="88"/>
        <source>Maximum start/load current:</source>
        <translation>最大启动/负载电流：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="89"/>
        <source>Brake current:</source>
        <translation>制动电流：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="91"/>
        <source>Limit switches</source>
        <translation>限位开关</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="92"/>
        <source>Limits:</source>
        <translation>限位：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="93"/>
        <source>SQ1 active level (forward):</source>
        <translation>SQ1 有效电平（正转）：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="94"/>
        <source>SQ2 active level (reverse):</source>
        <translation>SQ2 有效电平（反转）：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="96"/>
        <source>Protective stops (0 = off)</source>
        <translation>保护停止（0 = 关闭）</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="97"/>
        <source>S&amp;tall stop time:</source>
        <translation>堵转停止时间(&amp;T)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="98"/>
        <source>Communication loss stop time:</source>
        <translation>通信中断停止时间：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="106"/>
        <source>Serial port (used from the next power-up)</source>
        <translation>串口（从下次上电起生效）</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="111"/>
        <source>Baud rate and parity are written as one 15-register block from 0x0080 that also stores the configuration; the controller uses them from the next power-up on: switch it off and on, then reconnect with them. The lock is lost at power-off until stored (Store configuration).</source>
        <translation>波特率和校验位以从 0x0080 起的一个 15 寄存器块写入，该写入同时保存配置；控制器从下次上电起使用新设定：请将其断电再上电，然后用新设定重新连接。串口配置锁定在保存（保存配置）前断电即丢失。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="133"/>
        <source>Takes effect now and is kept over power-off: each change is written as one 5-register block from 0x0050 that also stores the port states.</source>
        <translation>立即生效，断电后保留：每次修改都以从 0x0050 起的一个 5 寄存器块写入，该写入同时保存端口状态。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="175"/>
        <source>The communication loss stop time is 0 s (%1): the manual does not say what 0 does, and OpenTOP assumes the stop is then off: if the connection is lost while the motor runs, the controller keeps it running at the last speed command. Set a time so that it brakes when the bus goes quiet.</source>
        <translation>通信中断停止时间为 0 s（%1）：手册没有说明 0 的作用，OpenTOP 假定此时该停止功能关闭：如果电机运行时连接中断，控制器会按最后的速度命令继续运行。请设定一个时间，使总线无通信时电机制动。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="107"/>
        <source>Baud rate:</source>
        <translation>波特率：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="108"/>
        <source>Parity and stop bits:</source>
        <translation>校验位和停止位：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="109"/>
        <source>Configuration over serial:</source>
        <translation>通过串口配置：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="115"/>
        <source>Speed loop PID</source>
        <translation>速度环 PID</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="116"/>
        <source>&amp;P coefficient:</source>
        <translation>P 系数(&amp;P)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="117"/>
        <source>I coefficient:</source>
        <translation>I 系数：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="118"/>
        <source>&amp;D coefficient:</source>
        <translation>D 系数(&amp;D)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="119"/>
        <source>D period:</source>
        <translation>D 周期：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="121"/>
        <source>Preset speed (potentiometer/analog control)</source>
        <translation>预设速度（电位器/模拟量控制）</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="122"/>
        <source>Preset speed mo&amp;de:</source>
        <translation>预设速度模式(&amp;D)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="123"/>
        <source>Trigger:</source>
        <translation>触发：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="124"/>
        <source>&amp;Forward speed:</source>
        <translation>正转速度(&amp;F)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="125"/>
        <source>Reverse speed:</source>
        <translation>反转速度：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="127"/>
        <source>AI1/AI2 as digital ports</source>
        <translation>AI1/AI2 用作数字端口</translation>
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
        <translation>AI1 电平：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="131"/>
        <source>AI2 level:</source>
        <translation>AI2 电平：</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="191"/>
        <source>Takes effect now, lost at power-off until stored (%1).</source>
        <translation>立即生效，保存（%1）前断电即丢失。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="252"/>
        <source>Set it anyway?</source>
        <translation>仍要设定吗？</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="268"/>
        <source>Forward and reverse speed in this mode (%1): %2</source>
        <translation>该模式下的正转和反转速度（%1）：%2</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="270"/>
        <source>The unit and range of the speeds follow the preset speed mode (not read yet).</source>
        <translation>速度的单位和范围取决于预设速度模式（尚未读取）。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="294"/>
        <source>&lt;b&gt;Written but not stored:&lt;/b&gt; %1. These values act now and are lost when the controller is switched off.</source>
        <translation>&lt;b&gt;已写入但未保存：&lt;/b&gt;%1。这些值立即生效，控制器断电后丢失。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="316"/>
        <source>%1: the controller writes the values now in effect to its memory and uses them from the next power-up on.

Stored: %2.</source>
        <translation>%1：控制器将当前生效的值写入其存储器，并从下次上电起使用。

已保存：%2。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="327"/>
        <source>Not written yet, so not stored: %1.</source>
        <translation>尚未写入，因此未保存：%1。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="330"/>
        <source>%1: done, kept over power-off.</source>
        <translation>%1：完成，断电后保留。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="338"/>
        <source>The controller replaces its configuration (%1) with the one stored in its memory.

Configuration changes written but not stored are discarded.</source>
        <translation>控制器将用其存储器中保存的配置替换当前配置（%1）。

已写入但未保存的配置修改将被丢弃。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="344"/>
        <source>Stored configuration reloaded.</source>
        <translation>已重新载入保存的配置。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="352"/>
        <source>Writing %1 = %2…</source>
        <translation>正在写入 %1 = %2…</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="362"/>
        <source>%1 = %2 failed: %3</source>
        <translation>%1 = %2 失败：%3</translation>
    </message>
</context>
<context>
    <name>opentop::DcMotor</name>
    <message>
        <location filename="../sim/DcMotor.cpp" line="64"/>
        <source>unknown motor setting &apos;%1&apos;; settings: %2</source>
        <translation>未知的电机设定 &apos;%1&apos;；可用设定：%2</translation>
    </message>
    <message>
        <location filename="../sim/DcMotor.cpp" line="71"/>
        <source>motor setting %1 must be a number %2..%3, got &apos;%4&apos;</source>
        <translation>电机设定 %1 必须是 %2..%3 的数，实际为 &apos;%4&apos;</translation>
    </message>
</context>
<context>
    <name>opentop::DcPidSimDevice</name>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="366"/>
        <source>%1 %2%3, output %4 %, command %5, line %6 %7</source>
        <translation>%1 %2%3，输出 %4 %，命令 %5，线路 %6 %7</translation>
    </message>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="368"/>
        <source> (stall stop)</source>
        <translation> （堵转停止）</translation>
    </message>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="384"/>
        <source>usage: %1 ID VALUE with VALUE %2..%3 %4</source>
        <translation>用法：%1 ID VALUE，VALUE 范围 %2..%3 %4</translation>
    </message>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="388"/>
        <source>(bit0 SQ1, bit1 SQ2, bit2 DE)</source>
        <translation>（bit0 SQ1，bit1 SQ2，bit2 DE）</translation>
    </message>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="388"/>
        <source>(% current)</source>
        <translation>（% 电流）</translation>
    </message>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="390"/>
        <source>%1 = %2</source>
        <translation>%1 = %2</translation>
    </message>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="407"/>
        <source>motor %1, speed %2 1/s, current %3 A</source>
        <translation>电机 %1，速度 %2 1/s，电流 %3 A</translation>
    </message>
</context>
<context>
    <name>opentop::DcRunCommands</name>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="26"/>
        <source>Set s&amp;peed</source>
        <translation>设定速度(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="31"/>
        <source>set point, e.g. 50 or -20</source>
        <translation>设定值，例如 50 或 -20</translation>
    </message>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="39"/>
        <source>Speed command:</source>
        <translation>速度命令：</translation>
    </message>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="54"/>
        <source>&amp;Brake (speed 0)</source>
        <translation>制动(&amp;B)（速度 0）</translation>
    </message>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="56"/>
        <source>&amp;Natural stop</source>
        <translation>自然停止(&amp;N)</translation>
    </message>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="90"/>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="91"/>
        <source>(reading %1…)</source>
        <translation>（正在读取 %1…）</translation>
    </message>
</context>
<context>
    <name>opentop::DependentValues</name>
    <message>
        <location filename="../model/session/DependentValues.cpp" line="45"/>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location filename="../model/session/DependentValues.cpp" line="53"/>
        <source>%1 = %2 would leave %3 without a valid value, because what they allow depends on it. Choose new values for them and write them together with it.</source>
        <translation>%1 = %2 会使 %3 失去有效值，因为它们的允许值取决于该项。请为它们选择新值，并与该项一起写入。</translation>
    </message>
    <message>
        <location filename="../model/session/DependentValues.cpp" line="57"/>
        <source>%1 cannot be checked: the values of %2 depend on it and could not be read</source>
        <translation>无法检查 %1：%2 的值取决于该项，但无法读取</translation>
    </message>
</context>
<context>
    <name>opentop::DeviceIdentifier</name>
    <message>
        <location filename="../model/session/DeviceIdentifier.cpp" line="31"/>
        <source>answers, but none of the device profiles matches</source>
        <translation>有应答，但没有匹配的设备描述</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceIdentifier.cpp" line="96"/>
        <source>device name &quot;%1&quot; is not a %2</source>
        <translation>设备名 &quot;%1&quot; 不是 %2</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceIdentifier.cpp" line="116"/>
        <source>the variant cannot be read from the device; choose it</source>
        <translation>无法从设备读取机型；请选择</translation>
    </message>
</context>
<context>
    <name>opentop::DeviceInfo</name>
    <message>
        <location filename="../model/session/DeviceInfo.cpp" line="59"/>
        <source>not checked</source>
        <translation>未检查</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceInfo.cpp" line="61"/>
        <source>online</source>
        <translation>在线</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceInfo.cpp" line="63"/>
        <source>no answer</source>
        <translation>无应答</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceInfo.cpp" line="65"/>
        <source>garbled replies (duplicate machine number?)</source>
        <translation>应答报文损坏（站号重复？）</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceInfo.cpp" line="68"/>
        <source>unknown device</source>
        <translation>未知设备</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceInfo.cpp" line="70"/>
        <source>answered, identification failed</source>
        <translation>有应答，识别失败</translation>
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
        <translation>运行中</translation>
    </message>
    <message>
        <location filename="../model/monitor/DeviceMonitor.cpp" line="69"/>
        <source>Running CCW</source>
        <translation>CCW 运行中</translation>
    </message>
    <message>
        <location filename="../model/monitor/DeviceMonitor.cpp" line="69"/>
        <source>Running CW</source>
        <translation>CW 运行中</translation>
    </message>
    <message>
        <location filename="../model/monitor/DeviceMonitor.cpp" line="212"/>
        <source>machine number %1: %2</source>
        <translation>站号 %1：%2</translation>
    </message>
</context>
<context>
    <name>opentop::DeviceParameters</name>
    <message>
        <location filename="../model/session/DeviceParameters.cpp" line="92"/>
        <source>%1 has no parameter &quot;%2&quot;</source>
        <translation>%1 没有参数 &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceParameters.cpp" line="94"/>
        <source>%1 is read-only</source>
        <translation>%1 为只读</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceParameters.cpp" line="96"/>
        <source>%1 is a command, not a setting; commands are sent one by one on request</source>
        <translation>%1 是命令，不是设定；命令仅在请求时逐条发送</translation>
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
            <numerusform>%n 个写入失败：%1</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/session/DeviceParameters.cpp" line="289"/>
        <source>Written, but not verified on every drive it reached: %1</source>
        <translation>已写入，但未能在所有收到的驱动器上确认：%1</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/session/DeviceParameters.cpp" line="292"/>
        <source>%n value(s) written and verified</source>
        <translation>
            <numerusform>%n 个值已写入并校验</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::DeviceSession</name>
    <message>
        <location filename="../model/session/DeviceSession.cpp" line="83"/>
        <source>%1 has no parameter &quot;%2&quot;</source>
        <translation>%1 没有参数 &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/session/BlockReader.cpp" line="50"/>
        <location filename="../model/session/DeviceSession.cpp" line="92"/>
        <source>%1 cannot be read (it is a write-only command)</source>
        <translation>无法读取 %1（它是只写命令）</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceSession.cpp" line="137"/>
        <source>%1 is read-only</source>
        <translation>%1 为只读</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceSession.cpp" line="143"/>
        <source>%1 is a %2 command; it is only sent when explicitly requested</source>
        <translation>%1 是%2命令；仅在明确请求时才发送</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceSession.cpp" line="173"/>
        <source>%1 cannot be checked: %2</source>
        <translation>无法检查 %1：%2</translation>
    </message>
    <message>
        <location filename="../model/session/BlockWriter.cpp" line="28"/>
        <source>not written: %1 is written together with 0x%2–0x%3, and reading those first failed: %4</source>
        <translation>未写入：%1 需与 0x%2–0x%3 一起写入，而预先读取这些寄存器失败：%4</translation>
    </message>
    <message>
        <location filename="../model/session/BlockWriter.cpp" line="33"/>
        <source>short reply</source>
        <translation>应答过短</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceSession.cpp" line="254"/>
        <source>written, but reading it back failed: %1</source>
        <translation>已写入，但回读失败：%1</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceSession.cpp" line="263"/>
        <source>verification failed: wrote %1, the device holds %2</source>
        <translation>校验失败：写入 %1，设备中为 %2</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceRefusal.cpp" line="67"/>
        <source>error code %1</source>
        <translation>错误代码 %1</translation>
    </message>
</context>
<context>
    <name>opentop::DriveBatchReader</name>
    <message>
        <location filename="../model/files/DriveBatchReader.cpp" line="13"/>
        <source>machine number %1: not read</source>
        <translation>站号 %1：未读取</translation>
    </message>
    <message>
        <location filename="../model/files/DriveBatchReader.cpp" line="22"/>
        <source>%1: cannot read %2</source>
        <translation>%1：无法读取 %2</translation>
    </message>
    <message>
        <location filename="../model/files/DriveBatchReader.cpp" line="24"/>
        <source>%1 holds a value its profile does not allow, so the backup could not be restored: %2</source>
        <translation>%1 含有其设备描述不允许的值，因此该备份无法恢复：%2</translation>
    </message>
    <message>
        <location filename="../model/files/DriveBatchReader.cpp" line="89"/>
        <source>machine number %1 is not a drive on the bus</source>
        <translation>站号 %1 不是总线上的驱动器</translation>
    </message>
</context>
<context>
    <name>opentop::DriveFormatsField</name>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="28"/>
        <source>none: every drive at the port&apos;s format</source>
        <translation>无：所有驱动器都用端口的格式</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="30"/>
        <source>Drives set to another line format than the port&apos;s, e.g. 7=9600:8E1 or 7=8N2 (the baud rate may be left out): requests to them switch the line to their format and back between transactions. A DBU works only at 8N1; a DC controller at 8E1, 8O1 or 8N2. The bus list&apos;s context menu sets them too.</source>
        <translation>设为与端口不同通信格式的驱动器，例如 7=9600:8E1 或 7=8N2（波特率可省略）：发往它们的请求会在两次通信之间把线路切换到它们的格式再切换回来。DBU 只能用 8N1；DC 控制器用 8E1、8O1 或 8N2。总线列表的右键菜单也可设定。</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="36"/>
        <source>&amp;Mixed bus…</source>
        <translation>混合总线(&amp;M)…</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="37"/>
        <source>How a drive of another format joins this bus</source>
        <translation>不同格式的驱动器如何加入此总线</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="39"/>
        <source>Drives of different line formats</source>
        <translation>不同通信格式的驱动器</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="47"/>
        <source>Drive f&amp;ormats:</source>
        <translation>驱动器格式(&amp;O)：</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="68"/>
        <source>Drive formats: %1</source>
        <translation>驱动器格式：%1</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="74"/>
        <source>Every drive hears only frames sent in its own line format: a DBU works only at 8N1 (19200 bit/s from the factory), a DC controller at 8E1 (9600 bit/s from the factory), 8O1 or 8N2. OpenTOP can talk to drives of different formats on one port: give each drive that is not at the port&apos;s format its own (Drive formats here, or Line format… in the bus list&apos;s context menu); the port is switched between transactions. To put all drives at one format for good, change the drives:</source>
        <translation>每台驱动器只能收到以它自己的通信格式发送的帧：DBU 只能用 8N1（出厂 19200 bit/s），DC 控制器用 8E1（出厂 9600 bit/s）、8O1 或 8N2。OpenTOP 可以在同一个端口上与不同格式的驱动器通信：为每台不是端口格式的驱动器设定它自己的格式（在这里的“驱动器格式”，或总线列表右键菜单的“通信格式…”）；端口会在两次通信之间切换。若要让所有驱动器长期使用同一种格式，请更改驱动器的设定：</translation>
    </message>
</context>
<context>
    <name>opentop::DriveLineDialog</name>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="29"/>
        <source>Line format of machine number %1</source>
        <translation>站号 %1 的通信格式</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="29"/>
        <source>Add drive</source>
        <translation>添加驱动器</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="37"/>
        <source>&amp;Machine number:</source>
        <translation>站号(&amp;M)：</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="51"/>
        <source>The port&apos;s (%1)</source>
        <translation>端口的格式（%1）</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="63"/>
        <source>The baud rate and format the drive is set to: requests to it switch the port to it and back between transactions. Type another as 38400 8E1.</source>
        <translation>驱动器设定的波特率和格式：发往它的请求会在两次通信之间把端口切换过去再切换回来。其他格式可输入，例如 38400 8E1。</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="66"/>
        <source>&amp;Line format:</source>
        <translation>通信格式(&amp;L)：</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="74"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="147"/>
        <source>Line &amp;format…</source>
        <translation>通信格式(&amp;F)…</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="152"/>
        <source>Machine number %1 talks %2, not the port&apos;s %3</source>
        <translation>站号 %1 使用 %2，而不是端口的 %3</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="155"/>
        <source>Machine number %1 talks the port&apos;s %2</source>
        <translation>站号 %1 使用端口的 %2</translation>
    </message>
</context>
<context>
    <name>opentop::DriveName</name>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="19"/>
        <source>A machine&apos;s name has at most %1 characters; &quot;%2&quot; has %3.</source>
        <translation>机器名称最多 %1 个字符；“%2”有 %3 个。</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="30"/>
        <source>A machine&apos;s name may not hold control characters or line breaks (U+%1).</source>
        <translation>机器名称不能包含控制字符或换行（U+%1）。</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="38"/>
        <source>A machine&apos;s name may not hold %1 (a percent sign directly before a digit).</source>
        <translation>机器名称不能包含 %1（百分号后面紧跟数字）。</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="47"/>
        <source>machine number %1</source>
        <translation>站号 %1</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="48"/>
        <source>machine number %1 (%2)</source>
        <translation>站号 %1（%2）</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="53"/>
        <source>Machine number %1</source>
        <translation>站号 %1</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="54"/>
        <source>Machine number %1 (%2)</source>
        <translation>站号 %1（%2）</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="72"/>
        <source>drive %1 (%2)</source>
        <translation>驱动器 %1（%2）</translation>
    </message>
</context>
<context>
    <name>opentop::DrivePages</name>
    <message>
        <location filename="../ui/main/DrivePages.cpp" line="102"/>
        <source>Monitor</source>
        <translation>监视</translation>
    </message>
    <message>
        <location filename="../ui/main/DrivePages.cpp" line="115"/>
        <source>Test run</source>
        <translation>试运行</translation>
    </message>
    <message>
        <location filename="../ui/main/DrivePages.cpp" line="139"/>
        <source>%1 — %2, firmware V%3, switches %4</source>
        <translation>%1 — %2，固件 V%3，开关 %4</translation>
    </message>
    <message>
        <location filename="../ui/main/DrivePages.cpp" line="123"/>
        <source>Speed loop tuning</source>
        <translation>速度环整定</translation>
    </message>
    <message>
        <location filename="../ui/main/DrivePages.cpp" line="129"/>
        <source>Alarms</source>
        <translation>报警</translation>
    </message>
</context>
<context>
    <name>opentop::DriveStatus</name>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="8"/>
        <source>not polled yet</source>
        <translation>尚未轮询</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="10"/>
        <source>online</source>
        <translation>在线</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/bus/DriveStatus.cpp" line="12"/>
        <source>no answer (%n poll(s) in a row)</source>
        <translation>
            <numerusform>无应答（连续 %n 次轮询）</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../model/bus/DriveStatus.cpp" line="13"/>
        <source>communication error (%n in a row)</source>
        <translation>
            <numerusform>通信错误（连续 %n 次）</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="19"/>
        <location filename="../model/bus/DriveStatus.cpp" line="31"/>
        <source>Status not known yet</source>
        <translation>状态未知</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="21"/>
        <source>No answer: %1</source>
        <translation>无应答：%1</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="24"/>
        <source>Communication error: %1</source>
        <translation>通信错误：%1</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="34"/>
        <source>Alarm %1 %2</source>
        <translation>报警 %1 %2</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="36"/>
        <source>Alarm %1h (not in the alarm table)</source>
        <translation>报警 %1h（不在报警表中）</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="38"/>
        <source>Alarm active</source>
        <translation>报警中</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="42"/>
        <source>Running</source>
        <translation>运行中</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="43"/>
        <source>Running CCW</source>
        <translation>CCW 运行中</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="43"/>
        <source>Running CW</source>
        <translation>CW 运行中</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="45"/>
        <source>Stopped, no alarm</source>
        <translation>已停止，无报警</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="52"/>
        <source>grey</source>
        <translation>灰色</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="54"/>
        <source>green</source>
        <translation>绿色</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="56"/>
        <source>orange</source>
        <translation>橙色</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="58"/>
        <source>sky blue</source>
        <translation>天蓝色</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="60"/>
        <source>red</source>
        <translation>红色</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="62"/>
        <source>purple</source>
        <translation>紫色</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="64"/>
        <source>blue</source>
        <translation>蓝色</translation>
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
        <translation>写入全部待写入项(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="36"/>
        <source>Revert all</source>
        <translation>全部还原</translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="37"/>
        <source>Re-read all</source>
        <translation>全部重新读取</translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="55"/>
        <source>Write every pending edit of this drive, on all pages, and verify</source>
        <translation>写入该驱动器所有页面上的全部待写入修改，并进行校验</translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="88"/>
        <source>Select a drive in the bus list to set it up.</source>
        <translation>在总线列表中选择一台驱动器进行设定。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="152"/>
        <source>Every edit is accepted now. Nothing has been written yet: Write all pending sends %n value(s).</source>
        <translation>
            <numerusform>所有编辑值现已接受。尚未写入任何值：“写入全部待写入值”将发送 %n 个值。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="168"/>
        <source>Write &amp;all pending (%1)</source>
        <translation>写入全部待写入项(&amp;A)（%1）</translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="190"/>
        <source>Reading the drive…</source>
        <translation>正在读取驱动器…</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="192"/>
        <source>%n value(s) could not be read</source>
        <translation>
            <numerusform>%n 个值无法读取</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="147"/>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="210"/>
        <source>Nothing was written: %1</source>
        <translation>未写入任何内容：%1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="144"/>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="224"/>
        <source>%1: %2 Nothing was written.</source>
        <translation>%1：%2 未写入任何内容。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="233"/>
        <source>Write %n pending value(s) to machine number %1</source>
        <translation>
            <numerusform>向站号 %1 写入 %n 个待写入值</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="205"/>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="235"/>
        <source>Nothing was written.</source>
        <translation>未写入任何内容。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="238"/>
        <source>Writing %n value(s)…</source>
        <translation>
            <numerusform>正在写入 %n 个值…</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::EolAuditCommand</name>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="34"/>
        <source>Show the audit trail: who logged in, approved, used or was refused a privilege</source>
        <translation>显示审计记录：谁登录、批准、使用或被拒绝某项权限</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="40"/>
        <source>Results database: an SQLite file or postgresql://user@host/db.</source>
        <translation>结果数据库：SQLite 文件或 postgresql://user@host/db。</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="41"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="42"/>
        <source>audit: at or after T (2026-11-24, 8h, 2d, today).</source>
        <translation>audit：T 当时或之后（2026-11-24、8h、2d、today）。</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="42"/>
        <source>T</source>
        <translation>T</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="43"/>
        <source>audit: only this user.</source>
        <translation>audit：仅此用户。</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="43"/>
        <location filename="../cli/EolAuditCommand.cpp" line="44"/>
        <source>NAME</source>
        <translation>名称</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="44"/>
        <source>audit: only this station.</source>
        <translation>audit：仅此工位。</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="53"/>
        <source>usage: opentop-cli eol %1</source>
        <translation>用法：opentop-cli eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="62"/>
        <source>error: --since: %1</source>
        <translation>错误：--since：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="74"/>
        <source>error: %1</source>
        <translation>错误：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="89"/>
        <source>no audit entry matches</source>
        <translation>没有匹配的审计记录</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="92"/>
        <source>time</source>
        <translation>时间</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="92"/>
        <source>station</source>
        <translation>工位</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="92"/>
        <source>user</source>
        <translation>用户</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="92"/>
        <source>action</source>
        <translation>操作</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="92"/>
        <source>detail</source>
        <translation>详情</translation>
    </message>
</context>
<context>
    <name>opentop::EolCertificateCommand</name>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="31"/>
        <source>A unit&apos;s certificate: its newest record as a PDF, or as JSON with --json</source>
        <translation>产品的检验证书：其最新记录，输出为 PDF，或用 --json 输出为 JSON</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="37"/>
        <source>The results database (see results).</source>
        <translation>结果数据库（参见 results）。</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="37"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="38"/>
        <source>certificate: the record with this id instead of the newest.</source>
        <translation>certificate：使用该 id 的记录，而不是最新记录。</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="39"/>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="59"/>
        <source>error: name one serial number, or a record with --id ID; usage: eol %1</source>
        <translation>错误：请指定一个序列号，或用 --id ID 指定一条记录；用法：eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="67"/>
        <source>error: the serial number is empty</source>
        <translation>错误：序列号为空</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="73"/>
        <location filename="../cli/EolCertificateCommand.cpp" line="138"/>
        <location filename="../cli/EolCertificateCommand.cpp" line="154"/>
        <source>error: %1</source>
        <translation>错误：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="80"/>
        <source>error: this program cannot draw a PDF (no Qt GUI application); use --json</source>
        <translation>错误：本程序无法生成 PDF（没有 Qt GUI 应用程序）；请使用 --json</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="96"/>
        <source>error: no record %1 in %2 (%3)</source>
        <translation>错误：%2 中没有记录 %1（%3）</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="104"/>
        <source>error: record %1 is of serial number %2, not %3</source>
        <translation>错误：记录 %1 属于序列号 %2，而不是 %3</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="114"/>
        <location filename="../cli/EolCertificateCommand.cpp" line="147"/>
        <source>error: %1: %2</source>
        <translation>错误：%1：%2</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="121"/>
        <source>error: no record of serial number %1 in %2</source>
        <translation>错误：%2 中没有序列号 %1 的记录</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="141"/>
        <source>wrote %1</source>
        <translation>已写入 %1</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="157"/>
        <source>wrote %1: serial number %2, %3, recorded %4</source>
        <translation>已写入 %1：序列号 %2，%3，记录于 %4</translation>
    </message>
</context>
<context>
    <name>opentop::EolCommand</name>
    <message>
        <location filename="../cli/EolCommand.cpp" line="36"/>
        <source>End-of-line station: recipes, the results database, unit certificates</source>
        <translation>下线检测工位：配方、结果数据库、产品检验证书</translation>
    </message>
    <message>
        <location filename="../cli/EolCommand.cpp" line="41"/>
        <source>Subcommands:
</source>
        <translation>子命令：
</translation>
    </message>
    <message>
        <location filename="../cli/EolCommand.cpp" line="44"/>
        <source>Results database: --db URL, else OPENTOP_EOL_DB, else the SQLite file
$XDG_DATA_HOME/opentop/results.db (~/.local/share/opentop/results.db).
&quot;opentop-cli help eol&quot; lists every option; each subcommand takes only its own.</source>
        <translation>结果数据库：--db URL，否则为 OPENTOP_EOL_DB，否则为 SQLite 文件
$XDG_DATA_HOME/opentop/results.db（~/.local/share/opentop/results.db）。
&quot;opentop-cli help eol&quot; 列出全部选项；每个子命令只接受自己的选项。</translation>
    </message>
    <message>
        <location filename="../cli/EolCommand.cpp" line="92"/>
        <source>error: name a subcommand: eol %1</source>
        <translation>错误：请指定子命令：eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolCommand.cpp" line="94"/>
        <source>error: unknown subcommand &quot;eol %1&quot;; subcommands: %2</source>
        <translation>错误：未知子命令 &quot;eol %1&quot;；子命令：%2</translation>
    </message>
    <message>
        <location filename="../cli/EolCommand.cpp" line="98"/>
        <source>See &quot;opentop-cli help eol&quot;.</source>
        <translation>请参阅 &quot;opentop-cli help eol&quot;。</translation>
    </message>
    <message>
        <location filename="../cli/EolCommand.cpp" line="114"/>
        <source>error: eol %1: --%2 is not an option of this subcommand; usage: eol %3</source>
        <translation>错误：eol %1：--%2 不是该子命令的选项；用法：eol %3</translation>
    </message>
</context>
<context>
    <name>opentop::EolDriveRun</name>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="56"/>
        <source>identifying</source>
        <translation>正在识别</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="84"/>
        <source>no drive answers at machine number %1</source>
        <translation>站号 %1 上没有驱动器应答</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="85"/>
        <source>the drive at machine number %1 is not identified: %2</source>
        <translation>站号 %1 上的驱动器未识别：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="99"/>
        <source>a %1 drive, the recipe needs a %2 drive</source>
        <translation>是 %1 驱动器，配方需要 %2 驱动器</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="103"/>
        <source>firmware %1, the recipe allows %2</source>
        <translation>固件 %1，配方允许 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="104"/>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="110"/>
        <source>no profile for the family %1</source>
        <translation>没有系列 %1 的设备描述</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="193"/>
        <source>cannot read whether the motor runs or an alarm is active: %1</source>
        <translation>无法读取电机是否在运行或是否有报警：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="194"/>
        <source>no answer</source>
        <translation>无应答</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="201"/>
        <source>its motor was running before the test</source>
        <translation>测试前其电机已在运行</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="202"/>
        <source>the motor is already running before the test (left by an interrupted run?); nothing was written: stop it first (STOP ALL, or at the drive)</source>
        <translation>测试前电机已在运行（上次运行中断遗留？）；未写入任何内容：请先停止（全部停止，或在驱动器上停止）</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="209"/>
        <source>an alarm is active before the test (left by the last unit?); nothing was written: reset the alarm and test again</source>
        <translation>测试前已有报警（上一台产品遗留？）；未写入任何内容：请复位报警后重新测试</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="219"/>
        <source>writing the settings</source>
        <translation>正在写入设定</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="224"/>
        <source>writing the settings: %1</source>
        <translation>正在写入设定：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="233"/>
        <source>reading every setting back</source>
        <translation>正在回读全部设定</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="238"/>
        <source>verifying the settings: %1</source>
        <translation>正在校验设定：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="252"/>
        <source>arming the communication-loss stop</source>
        <translation>启用通信中断停止</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="266"/>
        <source>testing</source>
        <translation>正在测试</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="270"/>
        <source>step %1 of %2: %3</source>
        <translation>步骤 %1/%2：%3</translation>
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
        <translation>配方编辑器(&amp;R)…</translation>
    </message>
    <message>
        <location filename="../ui/eol/EolMenu.cpp" line="51"/>
        <source>the recipe editor</source>
        <translation>配方编辑器</translation>
    </message>
    <message>
        <location filename="../ui/eol/EolMenu.cpp" line="57"/>
        <source>Re&amp;sults…</source>
        <translation>结果(&amp;S)…</translation>
    </message>
</context>
<context>
    <name>opentop::EolRecipeApproveCommand</name>
    <message>
        <location filename="../cli/EolRecipeApproveCommand.cpp" line="35"/>
        <source>Approve a signed recipe for the line (an engineer): stations then run it</source>
        <translation>批准已签名的配方供产线使用（工程师）：之后工位即可运行</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeApproveCommand.cpp" line="41"/>
        <source>Results database: an SQLite file or postgresql://user@host/db.</source>
        <translation>结果数据库：SQLite 文件或 postgresql://user@host/db。</translation>
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
        <translation>%1：配方无效，因此无法批准：</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeApproveCommand.cpp" line="80"/>
        <source>error: %1; the recipe was not approved</source>
        <translation>错误：%1；配方未批准</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeApproveCommand.cpp" line="98"/>
        <source>%1 rev. %2 approved by %3 (approval %4, checksum %5)</source>
        <translation>%1 版本 %2 已由 %3 批准（批准 %4，校验和 %5）</translation>
    </message>
</context>
<context>
    <name>opentop::EolRecipeCheckCommand</name>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="27"/>
        <source>Check a recipe against the drive profiles (and per-unit values of a CSV file)</source>
        <translation>按驱动器设备描述检查配方（以及 CSV 文件中的单台数值）</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="33"/>
        <source>recipe check: also check every unit&apos;s per-unit values in this CSV file.</source>
        <translation>recipe check：同时检查该 CSV 文件中每台产品的单台数值。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="34"/>
        <source>CSV</source>
        <translation>CSV</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="55"/>
        <source>error: %1 refused: %2</source>
        <translation>错误：%1 已拒绝：%2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="65"/>
        <source>%1, serial %2</source>
        <translation>%1，序列号 %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="91"/>
        <source>error: %1</source>
        <translation>错误：%1</translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="93"/>
        <source>%1 is not valid: %n problem(s); nothing may be run with it</source>
        <translation>
            <numerusform>%1 无效：%n 个问题；不得用它运行任何测试</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="102"/>
        <source>valid: %1 revision %2: %3</source>
        <translation>有效：%1 版本 %2：%3</translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="107"/>
        <source>; %n unit(s) of %1 checked</source>
        <translation>
            <numerusform>；已检查 %1 中的 %n 台产品</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::EolRecipeCreateCommand</name>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="39"/>
        <source>Make a recipe from a golden unit: a backup file or drives on the bus</source>
        <translation>从标准样机生成配方：备份文件或总线上的驱动器</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="45"/>
        <source>recipe create: the golden unit&apos;s backup file.</source>
        <translation>recipe create：标准样机的备份文件。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="46"/>
        <source>FILE</source>
        <translation>FILE</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="48"/>
        <source>recipe create: the golden unit&apos;s drives on the bus, e.g. 1,2 (with the connection options).</source>
        <translation>recipe create：标准样机在总线上的驱动器，例如 1,2（配合连接选项）。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="50"/>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="51"/>
        <source>recipe create: the product&apos;s name.</source>
        <translation>recipe create：产品名称。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="51"/>
        <source>NAME</source>
        <translation>NAME</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="52"/>
        <source>recipe create: the recipe&apos;s revision.</source>
        <translation>recipe create：配方版本。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="52"/>
        <source>REV</source>
        <translation>REV</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="54"/>
        <source>recipe create: replace an existing recipe file.</source>
        <translation>recipe create：替换已有的配方文件。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="56"/>
        <source>recipe create --drives: run the golden unit through the recipe&apos;s steps once (its motors turn) and take the hold limits from what it measured.</source>
        <translation>recipe create --drives：让标准样机按配方步骤运行一次（电机会转动），并以测量值确定保持步骤的限值。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="59"/>
        <source>recipe create --measure: the margin around a measured value, in % of it (default 25; at least 5 % of the parameter&apos;s full scale).</source>
        <translation>recipe create --measure：测量值两侧的裕量，以测量值的 % 表示（默认 25；至少为该参数满量程的 5 %）。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="61"/>
        <source>PERCENT</source>
        <translation>百分比</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="62"/>
        <source>recipe create --measure: run the motors.</source>
        <translation>recipe create --measure：确认让电机运转。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="76"/>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="177"/>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="282"/>
        <source>error: %1; nothing written</source>
        <translation>错误：%1；未写入任何内容</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="118"/>
        <source>nothing written</source>
        <translation>未写入任何内容</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="91"/>
        <source>%1: %2 settings read</source>
        <translation>%1：已读取 %2 项设定</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="106"/>
        <source>interrupted while reading the golden unit: nothing written</source>
        <translation>读取标准样机时中断：未写入任何文件</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="112"/>
        <source>note: %1</source>
        <translation>注意：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="117"/>
        <source>give its variant with --variant %1=VARIANT</source>
        <translation>请用 --variant %1=机型 指定其机型</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="133"/>
        <source>Would run the golden unit through the recipe&apos;s steps:</source>
        <translation>将让标准样机按配方步骤运行：</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="136"/>
        <source>This turns motors: add --yes to run them. Nothing was run; nothing written.</source>
        <translation>这会使电机转动：加上 --yes 才会运行。未运行任何电机，也未写入任何文件。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="141"/>
        <source>measuring the golden unit (Ctrl-C stops every motor):</source>
        <translation>正在测量标准样机（按 Ctrl-C 停止所有电机）：</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="150"/>
        <source>drive %1: %2</source>
        <translation>驱动器 %1：%2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="162"/>
        <source>interrupted</source>
        <translation>已中断</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="175"/>
        <source>WARNING: %1 is not confirmed stopped</source>
        <translation>警告：%1 未确认停止</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="185"/>
        <source>limits from the golden unit:</source>
        <translation>由标准样机确定的限值：</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="189"/>
        <source>  drive %1, step %2: %3</source>
        <translation>  驱动器 %1，步骤 %2：%3</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="213"/>
        <source>error: %1; usage: eol %2</source>
        <translation>错误：%1；用法：eol %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="218"/>
        <source>unexpected argument &quot;%1&quot;</source>
        <translation>意外的参数 &quot;%1&quot;</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="222"/>
        <source>give either --from-backup FILE or --drives LIST</source>
        <translation>请指定 --from-backup FILE 或 --drives LIST 之一</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="225"/>
        <source>--measure needs the golden unit on the bus: give --drives LIST</source>
        <translation>--measure 需要总线上的标准样机：请指定 --drives 列表</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="231"/>
        <source>--margin is for --measure</source>
        <translation>--margin 仅用于 --measure</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="233"/>
        <source>--margin %1: give a percentage from 1 to 100</source>
        <translation>--margin %1：请输入 1 到 100 的百分比</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="239"/>
        <source>give the product&apos;s name with --product NAME</source>
        <translation>请用 --product NAME 指定产品名称</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="241"/>
        <source>give the recipe&apos;s revision with --revision REV</source>
        <translation>请用 --revision REV 指定配方版本</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="244"/>
        <source>give the recipe file to write with -o RECIPE</source>
        <translation>请用 -o RECIPE 指定要写入的配方文件</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="248"/>
        <source>error: %1 exists; give --force to replace it</source>
        <translation>错误：%1 已存在；使用 --force 进行替换</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="253"/>
        <source>error: %1; nothing read</source>
        <translation>错误：%1；未读取任何内容</translation>
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
        <translation>错误：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="308"/>
        <source>wrote %1: %2 revision %3, %4</source>
        <translation>已写入 %1：%2 版本 %3，%4</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="316"/>
        <source>error: the recipe does not pass &quot;eol recipe check&quot;: fix it, then sign it with &quot;opentop-cli eol recipe sign %1&quot;</source>
        <translation>错误：配方未通过 &quot;eol recipe check&quot;：请修正，然后用 &quot;opentop-cli eol recipe sign %1&quot; 签名</translation>
    </message>
</context>
<context>
    <name>opentop::EolRecipeShowCommand</name>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="61"/>
        <source>Show a recipe: positions, settings by label with units, steps and limits</source>
        <translation>显示配方：位置、按标签列出的设定（含单位）、步骤和限值</translation>
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
        <translation>  无设定</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="90"/>
        <source>  setting</source>
        <translation>  设定</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="90"/>
        <source>value</source>
        <translation>值</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="90"/>
        <source>unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="100"/>
        <source>  per-unit value</source>
        <translation>  单台数值</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="100"/>
        <source>range</source>
        <translation>范围</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="100"/>
        <source>from</source>
        <translation>来源</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="103"/>
        <source>%1 … %2</source>
        <translation>%1 … %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="106"/>
        <source>CSV file by serial</source>
        <translation>按序列号取自 CSV 文件</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="107"/>
        <source>typed by the operator</source>
        <translation>由操作员输入</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="112"/>
        <source>  no test steps</source>
        <translation>  无测试步骤</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="115"/>
        <source>  steps:</source>
        <translation>  步骤：</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="174"/>
        <source>%1, revision %2</source>
        <translation>%1，版本 %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="180"/>
        <source>serial numbers: %1</source>
        <translation>序列号：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="181"/>
        <source>checksum %1</source>
        <translation>校验和 %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="182"/>
        <source>position</source>
        <translation>位置</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="182"/>
        <source>machine number</source>
        <translation>站号</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="182"/>
        <source>name</source>
        <translation>名称</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="182"/>
        <source>family</source>
        <translation>系列</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="183"/>
        <source>variants</source>
        <translation>机型</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="183"/>
        <source>firmware</source>
        <translation>固件</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="194"/>
        <source>any</source>
        <translation>任意</translation>
    </message>
</context>
<context>
    <name>opentop::EolRecipeSignCommand</name>
    <message>
        <location filename="../cli/EolRecipeSignCommand.cpp" line="27"/>
        <source>Accept a recipe edited by hand: a new checksum, only when it passes check</source>
        <translation>接受手工编辑的配方：仅在通过检查时生成新的校验和</translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolRecipeSignCommand.cpp" line="49"/>
        <source>error: %1 does not pass check (%n problem(s)); not signed</source>
        <translation>
            <numerusform>错误：%1 未通过检查（%n 个问题）；未签名</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeSignCommand.cpp" line="57"/>
        <source>error: %1; not signed</source>
        <translation>错误：%1；未签名</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeSignCommand.cpp" line="70"/>
        <source>%1 is signed already (%2); nothing changed</source>
        <translation>%1 已签名（%2）；未作任何修改</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeSignCommand.cpp" line="74"/>
        <source>signed %1: %2 revision %3, %4</source>
        <translation>已签名 %1：%2 版本 %3，%4</translation>
    </message>
</context>
<context>
    <name>opentop::EolResultsCommand</name>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="74"/>
        <source>List units of the results database, their first-pass yield, or export them as CSV</source>
        <translation>列出结果数据库中的产品及其直通率，或导出为 CSV</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="81"/>
        <source>The results database: a SQLite file, sqlite:PATH or postgresql://user@host/db (default: OPENTOP_EOL_DB, else ~/.local/share/opentop/results.db).</source>
        <translation>结果数据库：SQLite 文件、sqlite:PATH 或 postgresql://user@host/db（默认：OPENTOP_EOL_DB，否则为 ~/.local/share/opentop/results.db）。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="83"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="85"/>
        <source>results: only this serial number; with * or ? a pattern that ignores case (&quot;SN-10*&quot;).</source>
        <translation>results：只列出此序列号；含 * 或 ? 时为不区分大小写的模式（&quot;SN-10*&quot;）。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="87"/>
        <source>S</source>
        <translation>S</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="89"/>
        <source>results: started at or after T (2026-11-24, 2026-11-24T06:00, 8h, 2d, today).</source>
        <translation>results：开始时间不早于 T（2026-11-24、2026-11-24T06:00、8h、2d、today）。</translation>
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
        <translation>results：开始时间早于 T。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="92"/>
        <source>results: only this recipe (product name).</source>
        <translation>results：仅该配方（产品名称）。</translation>
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
        <translation>results：仅该工位。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="101"/>
        <source>results: only the newest N units.</source>
        <translation>results：仅最新的 N 台产品。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="101"/>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="103"/>
        <source>results: CSV (RFC 4180) on standard output or to -o FILE.</source>
        <translation>results：输出 CSV（RFC 4180）到标准输出或 -o FILE。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="108"/>
        <source>results --yield: the shifts&apos; start times in local time (default 06:00,14:00,22:00).</source>
        <translation>results --yield：各班次的开始时间（本地时间，默认 06:00,14:00,22:00）。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="109"/>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="141"/>
        <source>&quot;%1&quot; is not a time; give 2026-11-24, 2026-11-24T06:00 (local, or with Z or +01:00), 8h, 2d, today or yesterday</source>
        <translation>&quot;%1&quot; 不是时间；请使用 2026-11-24、2026-11-24T06:00（本地时间，或带 Z 或 +01:00）、8h、2d、today 或 yesterday</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="151"/>
        <location filename="../cli/EolResultsCommand.cpp" line="297"/>
        <source>error: %1</source>
        <translation>错误：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="167"/>
        <source>--%1: %2</source>
        <translation>--%1：%2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="172"/>
        <source>--since %1 is not before --until %2</source>
        <translation>--since %1 不早于 --until %2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="94"/>
        <source>results: only this version of a recipe (its checksum, as eol recipe check prints it).</source>
        <translation>results：仅该版本的配方（以校验和指定，即 eol recipe check 输出的值）。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="96"/>
        <source>SUM</source>
        <translation>SUM</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="98"/>
        <source>results: pass, fail, error (station error), interrupted, aborted or running.</source>
        <translation>results：pass、fail、error（工位错误）、interrupted、aborted 或 running。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="105"/>
        <source>results: first-, second- and last-pass yield and failure reasons per recipe version and per shift; station errors and aborts are kept out of yield.</source>
        <translation>results：按配方版本和班次列出直通率、二次合格率、最终合格率及不合格原因；工位错误和中止不计入合格率。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="178"/>
        <source>--verdict &quot;%1&quot;: give pass, fail, error, interrupted, aborted or running</source>
        <translation>--verdict &quot;%1&quot;：请指定 pass、fail、error、interrupted、aborted 或 running</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="186"/>
        <source>--limit &quot;%1&quot;: give a number of units from 1</source>
        <translation>--limit &quot;%1&quot;：请给出从 1 起的产品台数</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="196"/>
        <location filename="../cli/EolResultsCommand.cpp" line="226"/>
        <source>no unit matches</source>
        <translation>没有匹配的产品</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="199"/>
        <source>started</source>
        <translation>开始时间</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="199"/>
        <source>serial</source>
        <translation>序列号</translation>
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
        <translation>工位</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="199"/>
        <source>approved by</source>
        <translation>批准人</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="200"/>
        <source>operator</source>
        <translation>操作员</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="200"/>
        <source>verdict</source>
        <translation>判定</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="200"/>
        <source>time</source>
        <translation>时间</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="200"/>
        <source>reason</source>
        <translation>原因</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="200"/>
        <source>drives</source>
        <translation>驱动器</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="209"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="211"/>
        <source>%1 rev. %2</source>
        <translation>%1 版本 %2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="232"/>
        <source>shift</source>
        <translation>班次</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="233"/>
        <source>serials</source>
        <translation>序列号数</translation>
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
        <translation>最终合格</translation>
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
        <translation>工位错误</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="254"/>
        <source>Yield per recipe version (station errors and aborts are not counted)</source>
        <translation>各配方版本的合格率（不计入工位错误和中止）</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="263"/>
        <source>%1: checksum %2</source>
        <translation>%1：校验和 %2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="234"/>
        <source>not finished</source>
        <translation>未完成</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="266"/>
        <source>Per shift</source>
        <translation>各班次</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="282"/>
        <source>Failure reasons</source>
        <translation>不合格原因</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="283"/>
        <source>Station errors (not counted in yield)</source>
        <translation>工位错误（不计入合格率）</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="300"/>
        <source>wrote %1</source>
        <translation>已写入 %1</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="308"/>
        <source>error: unexpected argument &quot;%1&quot;; usage: eol %2</source>
        <translation>错误：意外的参数 &quot;%1&quot;；用法：eol %2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="315"/>
        <source>error: give --csv or --json, not both</source>
        <translation>错误：--csv 和 --json 只能指定其一</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="319"/>
        <source>error: -o names the CSV file: give --csv too</source>
        <translation>错误：-o 指定的是 CSV 文件：请同时指定 --csv</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="324"/>
        <source>error: --shifts is for --yield</source>
        <translation>错误：--shifts 仅用于 --yield</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="333"/>
        <source>error: --shifts %1: %2</source>
        <translation>错误：--shifts %1：%2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="352"/>
        <location filename="../cli/EolResultsCommand.cpp" line="382"/>
        <location filename="../cli/EolResultsCommand.cpp" line="393"/>
        <source>error: %1: %2</source>
        <translation>错误：%1：%2</translation>
    </message>
</context>
<context>
    <name>opentop::EolRun</name>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="59"/>
        <source>recording the unit before anything is sent</source>
        <translation>发送任何内容前正在记录产品</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="65"/>
        <source>the results database cannot record the unit: %1</source>
        <translation>结果数据库无法记录该产品：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="98"/>
        <source>the recipe has no drives</source>
        <translation>配方中没有驱动器</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="111"/>
        <source>the recipe is not valid: %1</source>
        <translation>配方无效：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="116"/>
        <source>%1: no value for %2 for this unit</source>
        <translation>%1：该产品没有 %2 的值</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="134"/>
        <source>cancelled by the operator</source>
        <translation>已被操作员取消</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="145"/>
        <source>the connection was lost: %1</source>
        <translation>连接丢失：%1</translation>
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
        <translation>%1 失败</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="198"/>
        <source>NOT CONFIRMED STOPPED: %1</source>
        <translation>未确认已停止：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="207"/>
        <source>recording the result</source>
        <translation>正在记录结果</translation>
    </message>
</context>
<context>
    <name>opentop::EolRunCommand</name>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="59"/>
        <source>Set up and test one unit at the end of the line; record the result</source>
        <translation>在下线工位设定并测试一台产品；记录结果</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="65"/>
        <source>The unit&apos;s serial number (as its barcode reads).</source>
        <translation>产品序列号（按条码读取）。</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="65"/>
        <source>S</source>
        <translation>S</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="66"/>
        <source>Who tests it, on a station without users (default: the login name).</source>
        <translation>无用户的工位上的测试者（默认：登录名）。</translation>
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
        <translation>本工位名称（默认：主机名）。</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="70"/>
        <source>Results database: an SQLite file or postgresql://user@host/db.</source>
        <translation>结果数据库：SQLite 文件或 postgresql://user@host/db。</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="70"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="71"/>
        <source>CSV file with the per-unit values, by serial number.</source>
        <translation>含单台数值的 CSV 文件，按序列号对应。</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="71"/>
        <source>CSV</source>
        <translation>CSV</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="72"/>
        <source>A per-unit value typed by the operator, e.g. 1:spno3.speed=1500.</source>
        <translation>由操作员输入的单台数值，例如 1:spno3.speed=1500。</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="73"/>
        <source>ID:NAME=VALUE</source>
        <translation>ID:NAME=VALUE</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="75"/>
        <source>A technician allows a retest the recipe&apos;s rules hold back (a serial that passed already, or its attempts used up).</source>
        <translation>由技术员许可配方规则不允许的重新测试（已合格的序列号，或测试次数已用完）。</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="109"/>
        <source>--value %1: write it as MACHINE:NAME=VALUE, e.g. 1:spno3.speed=1500</source>
        <translation>--value %1：请写成 MACHINE:NAME=VALUE，例如 1:spno3.speed=1500</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="114"/>
        <source>--value %1: %2</source>
        <translation>--value %1：%2</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="137"/>
        <source>--variant %1: %2 allows %3; nothing was sent</source>
        <translation>--variant %1：%2 允许 %3；未发送任何内容</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="139"/>
        <source>any %1 variant</source>
        <translation>任何 %1 机型</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="148"/>
        <source>--variant %1: the recipe has no position at machine number %2; nothing was sent</source>
        <translation>--variant %1：配方在站号 %2 没有位置；未发送任何内容</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="162"/>
        <source>usage: opentop-cli eol %1</source>
        <translation>用法：opentop-cli eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="178"/>
        <source>%1: the recipe is not valid; nothing was sent:</source>
        <translation>%1：配方无效；未发送任何内容：</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="188"/>
        <source>--serial: %1; nothing was sent</source>
        <translation>--serial：%1；未发送任何内容</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="217"/>
        <source>results database: %1; nothing was sent</source>
        <translation>结果数据库：%1；未发送任何内容</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="223"/>
        <source>note: unit %1 (begun %2) was left unfinished by a station process that is gone; it is now recorded as interrupted. Check that its motor is stopped.</source>
        <translation>注意：单元 %1（开始于 %2）因工作站进程已结束而未完成，现已记录为“中断”。请确认其电机已停止。</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="228"/>
        <source>note: %1 result(s) kept on this station could not be sent to the results database yet</source>
        <translation>注意：本工作站保存的 %1 条结果尚未能发送到结果数据库</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="317"/>
        <source>error: %1; nothing was sent</source>
        <translation>错误：%1；未发送任何内容</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="320"/>
        <source>a technician allows it with --retest</source>
        <translation>技术员可用 --retest 许可重新测试</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="269"/>
        <source>note: %1; tested again as --retest allows</source>
        <translation>注意：%1；按 --retest 的许可重新测试</translation>
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
        <translation>工作站有驱动器未确认停止；未进行任何检测</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="298"/>
        <source>interrupted at the station</source>
        <translation>在工位上中断</translation>
    </message>
</context>
<context>
    <name>opentop::EolRunIdentity</name>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="50"/>
        <location filename="../cli/EolRunIdentity.cpp" line="88"/>
        <source>the results database is not open</source>
        <translation>结果数据库未打开</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="53"/>
        <location filename="../cli/EolRunIdentity.cpp" line="101"/>
        <source>results database: %1; nothing was sent</source>
        <translation>结果数据库：%1；未发送任何内容</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="65"/>
        <location filename="../cli/EolRunIdentity.cpp" line="107"/>
        <source>refused: %1; nothing was sent</source>
        <translation>拒绝：%1；未发送任何内容</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="66"/>
        <source>this station has users: name who tests with --user NAME (the password from OPENTOP_PASSWORD or the terminal)</source>
        <translation>此工位有用户：请用 --user NAME 指定测试者（密码取自 OPENTOP_PASSWORD 或终端）</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="73"/>
        <source>error: on a station with users the operator is the user who logs in (--user); --operator is not taken</source>
        <translation>错误：有用户的工位上，操作员即登录的用户（--user）；不接受 --operator</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="98"/>
        <source>run-units: recipe checksum %1 is not approved</source>
        <translation>run-units：配方校验和 %1 未批准</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="113"/>
        <source>refused: %1 Nothing was sent.</source>
        <translation>拒绝：%1 未发送任何内容。</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="123"/>
        <source>%1 logged in; recipe approved by %2 (approval %3)</source>
        <translation>%1 已登录；配方由 %2 批准（批准 %3）</translation>
    </message>
</context>
<context>
    <name>opentop::EolRunOutput</name>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="98"/>
        <location filename="../cli/EolRunOutput.cpp" line="121"/>
        <source>drive %1</source>
        <translation>驱动器 %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="129"/>
        <source>ok</source>
        <translation>正常</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="129"/>
        <source>FAIL</source>
        <translation>不合格</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="165"/>
        <source>rev. %1</source>
        <translation>版本 %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="167"/>
        <source>attempt %1</source>
        <translation>第 %1 次测试</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="174"/>
        <source>the result was NOT recorded: %1</source>
        <translation>结果未记录：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="178"/>
        <source>the results database did not answer: the result is kept on this station (%1) and sent when a station program next reaches the database</source>
        <translation>结果数据库没有响应：结果已保存在本工作站（%1），下次工作站程序连上数据库时会发送</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="183"/>
        <source>WARNING: motor not confirmed stopped: %1</source>
        <translation>警告：未确认电机已停止：%1</translation>
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
        <translation>%1 无法回读：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/EolSettingsWriter.cpp" line="101"/>
        <source>%1 does not keep its value: set to %2, reads %3</source>
        <translation>%1 未保持其值：设定为 %2，读取为 %3</translation>
    </message>
</context>
<context>
    <name>opentop::EolSpeedChart</name>
    <message>
        <location filename="../ui/eol/EolSpeedChart.cpp" line="20"/>
        <source>time (s)</source>
        <translation>时间 (s)</translation>
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
        <translation>速度（%1）</translation>
    </message>
    <message>
        <location filename="../ui/eol/EolSpeedChart.cpp" line="52"/>
        <source>drive %1</source>
        <translation>驱动器 %1</translation>
    </message>
</context>
<context>
    <name>opentop::EolStation</name>
    <message>
        <location filename="../model/station/EolStation.cpp" line="121"/>
        <source>a unit is being tested</source>
        <translation>正在测试一台产品</translation>
    </message>
    <message>
        <location filename="../model/station/EolStation.cpp" line="125"/>
        <source>open a recipe first</source>
        <translation>请先打开配方</translation>
    </message>
    <message>
        <location filename="../model/station/EolStation.cpp" line="145"/>
        <source>run-units: serial %1: %2</source>
        <translation>run-units：序列号 %1：%2</translation>
    </message>
    <message>
        <location filename="../model/station/EolStation.cpp" line="149"/>
        <source>not connected to a bus</source>
        <translation>未连接总线</translation>
    </message>
    <message>
        <location filename="../model/station/EolStation.cpp" line="153"/>
        <source>unit %1 starts as soon as the station&apos;s drives are safe</source>
        <translation>工作站的驱动器确认安全后，单元 %1 会立即开始</translation>
    </message>
    <message>
        <location filename="../model/station/EolStation.cpp" line="185"/>
        <source>serial %1 tested again, allowed by %2: %3</source>
        <translation>序列号 %1 重新测试,由 %2 批准:%3</translation>
    </message>
    <message>
        <location filename="../model/station/EolStation.cpp" line="227"/>
        <source>no unit was started yet</source>
        <translation>尚未开始任何产品的测试</translation>
    </message>
</context>
<context>
    <name>opentop::EolStepRunner</name>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="118"/>
        <source>step %1 (%2)</source>
        <translation>步骤 %1（%2）</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="124"/>
        <location filename="../model/eol/EolStepRunner.cpp" line="148"/>
        <source>the drive&apos;s session ended</source>
        <translation>驱动器会话已结束</translation>
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
        <translation>%1：驱动器没有通信优先级</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="256"/>
        <source>the stop command failed: %1</source>
        <translation>停止命令失败：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="269"/>
        <source>stopped after %1 s</source>
        <translation>%1 s 后停止</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="270"/>
        <source>not confirmed stopped: %1</source>
        <translation>未确认已停止：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="326"/>
        <source>communication priority could not be given back: %1</source>
        <translation>无法交还通信优先级：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="157"/>
        <source>the steps ended with the motor running</source>
        <translation>步骤结束时电机仍在运行</translation>
    </message>
</context>
<context>
    <name>opentop::EolSupport</name>
    <message>
        <location filename="../cli/EolSupport.cpp" line="26"/>
        <source>error: name one recipe file; usage: eol %1</source>
        <translation>错误：请指定一个配方文件；用法：eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="39"/>
        <source>no such file</source>
        <translation>文件不存在</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="41"/>
        <source>is a directory; name a recipe file</source>
        <translation>是目录；请指定配方文件</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="43"/>
        <source>is not a regular file (a device, FIFO or socket); name a recipe file</source>
        <translation>不是普通文件（是设备、FIFO 或套接字）；请指定配方文件</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="45"/>
        <source>is larger than %1 MB, the most a recipe file may hold</source>
        <translation>大于 %1 MB，超过配方文件的上限</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="49"/>
        <source>cannot be read: %1</source>
        <translation>无法读取：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="51"/>
        <location filename="../cli/EolSupport.cpp" line="177"/>
        <source>error: %1: %2</source>
        <translation>错误：%1：%2</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="78"/>
        <location filename="../cli/EolSupport.cpp" line="199"/>
        <source>error: %1</source>
        <translation>错误：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="86"/>
        <source>error: %1 refused: %2</source>
        <translation>错误：%1 已拒绝：%2</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="95"/>
        <source>%1 was changed after OpenTOP wrote it (its checksum does not match), so no station runs it. Check it with &quot;opentop-cli eol recipe check %1&quot; and, when it is right, sign it with &quot;opentop-cli eol recipe sign %1&quot;</source>
        <translation>%1 在 OpenTOP 写入后被修改过（校验和不一致），因此任何工位都不会运行它。请用 &quot;opentop-cli eol recipe check %1&quot; 检查，确认无误后用 &quot;opentop-cli eol recipe sign %1&quot; 签名</translation>
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
            <numerusform>%n 个位置</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolSupport.cpp" line="141"/>
        <source>%n setting(s)</source>
        <translation>
            <numerusform>%n 项设定</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolSupport.cpp" line="143"/>
        <source>%n per-unit value(s)</source>
        <translation>
            <numerusform>%n 个单台数值</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolSupport.cpp" line="144"/>
        <source>%n step(s)</source>
        <translation>
            <numerusform>%n 个步骤</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="151"/>
        <source>The file to write (recipe create; results --csv; certificate).</source>
        <translation>要写入的文件（recipe create；results --csv；certificate）。</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="152"/>
        <source>FILE</source>
        <translation>FILE</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="188"/>
        <source>error: no results database at %1 (nothing recorded there yet); name one with --db URL</source>
        <translation>错误：%1 处没有结果数据库（尚未记录任何内容）；请用 --db URL 指定</translation>
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
        <translation>不是 %1 的参数</translation>
    </message>
    <message>
        <location filename="../model/eol/EolTarget.cpp" line="51"/>
        <source>this unit&apos;s value is missing</source>
        <translation>缺少该产品的值</translation>
    </message>
    <message>
        <location filename="../model/eol/EolTarget.cpp" line="54"/>
        <source>%1 is outside this product&apos;s range %2–%3 %4</source>
        <translation>%1 超出该产品的范围 %2–%3 %4</translation>
    </message>
</context>
<context>
    <name>opentop::EolUserCommand</name>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="72"/>
        <source>Add a user (operator, technician, engineer or administrator); the first user is an administrator and needs no --user</source>
        <translation>添加用户（操作员、技术员、工程师或管理员）；第一个用户是管理员，不需要 --user</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="75"/>
        <source>List the users of the results database</source>
        <translation>列出结果数据库的用户</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="77"/>
        <source>Disable a user: they can no longer log in; their records stay</source>
        <translation>停用用户：无法再登录；其记录保留</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="81"/>
        <source>Set a user&apos;s password (your own with your old one, anyone&apos;s as administrator)</source>
        <translation>设置用户密码（自己的需输入旧密码，管理员可设置任何人的）</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="87"/>
        <source>Results database: an SQLite file or postgresql://user@host/db.</source>
        <translation>结果数据库：SQLite 文件或 postgresql://user@host/db。</translation>
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
        <translation>user add：屏幕上显示的名称。</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="94"/>
        <source>TEXT</source>
        <translation>文本</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="109"/>
        <location filename="../cli/EolUserCommand.cpp" line="168"/>
        <source>error: %1</source>
        <translation>错误：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="124"/>
        <source>no users: this station is unmanaged (anyone can run, edit and leave); add the first administrator with: opentop-cli eol user add NAME --role administrator</source>
        <translation>没有用户：此工位未受管理（任何人都可运行、编辑和退出）；添加第一位管理员：opentop-cli eol user add NAME --role administrator</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="130"/>
        <source>user</source>
        <translation>用户</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="130"/>
        <source>name</source>
        <translation>名称</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="130"/>
        <source>role</source>
        <translation>角色</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="130"/>
        <source>active</source>
        <translation>启用</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="130"/>
        <source>created</source>
        <translation>创建时间</translation>
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
        <translation>错误：--role 须为以下之一：%1</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="183"/>
        <source>Present password for %1: </source>
        <translation>%1 的当前密码：</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="194"/>
        <location filename="../cli/EolUserCommand.cpp" line="216"/>
        <source>New password for %1: </source>
        <translation>%1 的新密码：</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="203"/>
        <source>user %1 added as %2</source>
        <translation>已添加用户 %1，角色 %2</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="211"/>
        <source>user %1 disabled</source>
        <translation>已停用用户 %1</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="221"/>
        <source>password of %1 changed</source>
        <translation>已更改 %1 的密码</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="230"/>
        <source>error: %1; nothing was changed</source>
        <translation>错误：%1；未做任何更改</translation>
    </message>
</context>
<context>
    <name>opentop::ExitActions</name>
    <message>
        <location filename="../model/run/ExitActions.cpp" line="50"/>
        <source>Machine number %1: left in communication priority, as it was not confirmed stopped</source>
        <translation>站号 %1：未确认已停止，因此仍保持通信优先级</translation>
    </message>
    <message>
        <location filename="../model/run/ExitActions.cpp" line="75"/>
        <source>The stop broadcast to the %1 drives failed: %2</source>
        <translation>向 %1 台驱动器广播停止失败：%2</translation>
    </message>
    <message>
        <location filename="../model/run/ExitActions.cpp" line="81"/>
        <source>Machine number %1: STILL RUNNING (%2) %3</source>
        <translation>站号 %1：仍在运行（%2）%3</translation>
    </message>
    <message>
        <location filename="../model/run/ExitActions.cpp" line="86"/>
        <source>Machine number %1: NO ANSWER, not confirmed stopped %2</source>
        <translation>站号 %1：无应答，未确认已停止 %2</translation>
    </message>
    <message>
        <location filename="../model/run/ExitActions.cpp" line="111"/>
        <source>Machine number %1: no way to give control back to its inputs is known</source>
        <translation>站号 %1：没有已知的方法将控制权交还其输入端子</translation>
    </message>
    <message>
        <location filename="../model/run/ExitActions.cpp" line="123"/>
        <source>Machine number %1: %2</source>
        <translation>站号 %1：%2</translation>
    </message>
</context>
<context>
    <name>opentop::ExitCheck</name>
    <message>
        <location filename="../model/run/ExitCheck.cpp" line="20"/>
        <source>in communication priority (its own inputs cannot start or stop it)</source>
        <translation>处于通信优先级（其自身的输入端子无法启动或停止它）</translation>
    </message>
    <message>
        <location filename="../model/run/ExitCheck.cpp" line="21"/>
        <source>Machine number %1 (%2): %3</source>
        <translation>站号 %1（%2）：%3</translation>
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
        <translation>正在停止驱动器，然后将控制权交还其输入端子…</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="135"/>
        <source>Stopping the drives…</source>
        <translation>正在停止驱动器…</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="132"/>
        <source>Giving control back to the drives&apos; inputs…</source>
        <translation>正在将控制权交还驱动器的输入端子…</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="159"/>
        <source>Not every drive is safe</source>
        <translation>并非所有驱动器都处于安全状态</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="160"/>
        <source>Could not %1 every drive:</source>
        <translation>以下驱动器未能%1：</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="162"/>
        <source>Stay connected</source>
        <translation>保持连接</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="163"/>
        <source>Go on anyway</source>
        <translation>仍然继续</translation>
    </message>
</context>
<context>
    <name>opentop::ExitPlan</name>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="55"/>
        <source>Stop and give control back</source>
        <translation>停止并交还控制权</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="56"/>
        <source>Stop the drives</source>
        <translation>停止驱动器</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="56"/>
        <source>Give control back (I/O priority)</source>
        <translation>交还控制权（I/O 优先级）</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="58"/>
        <source>Give control back only</source>
        <translation>仅交还控制权</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="60"/>
        <source>Leave them running</source>
        <translation>保持运行</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="60"/>
        <source>Leave them so</source>
        <translation>保持现状</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="70"/>
        <location filename="../model/run/ExitPlan.cpp" line="73"/>
        <source>give control back to</source>
        <translation>交还控制权</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="71"/>
        <source>stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="71"/>
        <source>stop and give control back to</source>
        <translation>停止并交还控制权</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="82"/>
        <source>Drives are running</source>
        <translation>驱动器正在运行</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="82"/>
        <source>Drives left in communication priority</source>
        <translation>驱动器仍处于通信优先级</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="88"/>
        <source>Before you %1: these drives are left in communication priority.</source>
        <translation>%1之前：这些驱动器仍处于通信优先级。</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="89"/>
        <source>Before you %1: these drives are running or left in communication priority.</source>
        <translation>%1之前：这些驱动器正在运行或仍处于通信优先级。</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="101"/>
        <source>left as it is: it runs from its own inputs (I/O priority), which a stop over the bus does not override</source>
        <translation>保持现状：它按自身的输入端子运行（I/O 优先级），通过总线发送的停止命令无法改变</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="104"/>
        <source>stopped (confirmed by reading it), then given back to its own inputs (I/O priority, read back)</source>
        <translation>停止（读取确认），然后交还其自身的输入端子（I/O 优先级，回读确认）</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="107"/>
        <source>stopped (confirmed by reading it); its family has no I/O priority setting, so it stays under the bus&apos;s control</source>
        <translation>停止（读取确认）；该系列没有 I/O 优先级设定，因此仍由总线控制</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="110"/>
        <source>stopped (confirmed by reading it)</source>
        <translation>停止（读取确认）</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="112"/>
        <source>given back to its own inputs (I/O priority, read back)</source>
        <translation>交还其自身的输入端子（I/O 优先级，回读确认）</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="114"/>
        <source>left as it is: no way to give control back to its inputs is known</source>
        <translation>保持现状：没有已知的方法将控制权交还其输入端子</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="115"/>
        <source>   → %1</source>
        <translation>   → %1</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="122"/>
        <source>In communication priority a drive takes run and stop only from the bus: once OpenTOP lets go, only another bus master or switching its power off stops it.</source>
        <translation>在通信优先级下，驱动器只接受来自总线的运行和停止命令：OpenTOP 释放后，只有其他总线主站或切断其电源才能使其停止。</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="126"/>
        <source>Stopping broadcasts every family&apos;s stop command to the whole bus and checks that each drive above has stopped; a drive that has not stopped is not given back to its inputs.</source>
        <translation>停止时会向整条总线广播所有系列的停止命令，并检查上述每台驱动器是否已停止；未停止的驱动器不会交还其输入端子。</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="131"/>
        <source>&quot;Give control back only&quot; sets I/O priority without a stop: the machine&apos;s own inputs decide at once whether the drives run.</source>
        <translation>“仅交还控制权”不先停止，直接设定为 I/O 优先级：由设备自身的输入端子立即决定驱动器是否运行。</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="135"/>
        <source>&quot;Give control back&quot; sets I/O priority, so the machine&apos;s own inputs run the drives again.</source>
        <translation>“交还控制权”会设定为 I/O 优先级，使设备自身的输入端子重新控制驱动器运行。</translation>
    </message>
</context>
<context>
    <name>opentop::FaultInjector</name>
    <message>
        <location filename="../sim/FaultInjector.cpp" line="30"/>
        <source>fault &apos;%1&apos; must be NAME=VALUE; names: %2</source>
        <translation>故障 &apos;%1&apos; 必须写成 NAME=VALUE；名称：%2</translation>
    </message>
    <message>
        <location filename="../sim/FaultInjector.cpp" line="38"/>
        <source>late_ms must be a whole number of milliseconds 1..60000, got &apos;%1&apos;</source>
        <translation>late_ms 必须是 1..60000 的整数毫秒，实际为 &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../sim/FaultInjector.cpp" line="52"/>
        <source>unknown fault &apos;%1&apos;; allowed: %2</source>
        <translation>未知故障 &apos;%1&apos;；允许：%2</translation>
    </message>
    <message>
        <location filename="../sim/FaultInjector.cpp" line="57"/>
        <source>fault rate %1 must be a number 0..1, got &apos;%2&apos;</source>
        <translation>故障率 %1 必须是 0..1 的数，实际为 &apos;%2&apos;</translation>
    </message>
    <message>
        <location filename="../sim/FaultInjector.cpp" line="64"/>
        <source>the fault rates add up to more than 1</source>
        <translation>各故障率之和大于 1</translation>
    </message>
</context>
<context>
    <name>opentop::FileActions</name>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="22"/>
        <source>OpenTOP backups (*.json);;All files (*)</source>
        <translation>OpenTOP 备份 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="38"/>
        <location filename="../ui/files/FileActions.cpp" line="94"/>
        <source>&amp;Back up selected drive…</source>
        <translation>备份所选驱动器(&amp;B)…</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="44"/>
        <source>Back up &amp;whole bus…</source>
        <translation>备份整条总线(&amp;W)…</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="50"/>
        <source>Save the settings of every identified drive to one file</source>
        <translation>将所有已识别驱动器的设定保存到一个文件</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="52"/>
        <source>&amp;Open backup file…</source>
        <translation>打开备份文件(&amp;O)…</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="54"/>
        <source>Show the drives and settings a backup file holds</source>
        <translation>显示备份文件中的驱动器和设定</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="55"/>
        <source>Co&amp;mpare…</source>
        <translation>比较(&amp;M)…</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="58"/>
        <source>Compare drives and backup files side by side, or against factory defaults</source>
        <translation>并排比较驱动器和备份文件，或与出厂默认值比较</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="59"/>
        <source>&amp;Restore from file…</source>
        <translation>从文件恢复(&amp;R)…</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="60"/>
        <source>Preview, then write a backup&apos;s settings back to drives</source>
        <translation>预览后，将备份中的设定写回驱动器</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="93"/>
        <source>&amp;Back up selected drives…</source>
        <translation>备份所选驱动器(&amp;B)…</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="96"/>
        <source>Select an identified drive in the bus list first</source>
        <translation>请先在总线列表中选择一台已识别的驱动器</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="97"/>
        <source>Save the settings of the selected drive(s) to a file</source>
        <translation>将所选驱动器的设定保存到文件</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="108"/>
        <source>Back up to file</source>
        <translation>备份到文件</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="120"/>
        <source>Open backup file</source>
        <translation>打开备份文件</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="141"/>
        <source>Restore from backup file</source>
        <translation>从备份文件恢复</translation>
    </message>
</context>
<context>
    <name>opentop::FileCommandSupport</name>
    <message>
        <location filename="../cli/FileCommandSupport.cpp" line="29"/>
        <source>no such file</source>
        <translation>文件不存在</translation>
    </message>
    <message>
        <location filename="../cli/FileCommandSupport.cpp" line="31"/>
        <source>is a directory; name a backup file</source>
        <translation>是目录；请指定备份文件</translation>
    </message>
    <message>
        <location filename="../cli/FileCommandSupport.cpp" line="33"/>
        <source>is not a regular file (a device, FIFO or socket); name a backup file</source>
        <translation>不是普通文件（是设备、FIFO 或套接字）；请指定备份文件</translation>
    </message>
    <message>
        <location filename="../cli/FileCommandSupport.cpp" line="35"/>
        <source>error: %1: %2</source>
        <translation>错误：%1：%2</translation>
    </message>
    <message>
        <location filename="../cli/FileCommandSupport.cpp" line="43"/>
        <source>error: %1 refused: %2</source>
        <translation>错误：%1 已拒绝：%2</translation>
    </message>
</context>
<context>
    <name>opentop::FixedLineHint</name>
    <message>
        <location filename="../model/bus/FixedLineHint.cpp" line="41"/>
        <source>A DC controller in potentiometer/analog control mode talks only at %1 bit/s, 8%2%3, address %4.</source>
        <translation>处于电位器/模拟量控制模式的直流控制器只以 %1 bit/s、8%2%3、地址 %4 通信。</translation>
    </message>
    <message>
        <location filename="../model/bus/FixedLineHint.cpp" line="60"/>
        <source>%1 8%2%3, address %4</source>
        <translation>%1 8%2%3，地址 %4</translation>
    </message>
</context>
<context>
    <name>opentop::GainDesign</name>
    <message>
        <location filename="../model/tuning/GainDesign.cpp" line="21"/>
        <source>the model has no ultimate point</source>
        <translation>模型没有临界点</translation>
    </message>
    <message>
        <location filename="../model/tuning/GainDesign.cpp" line="55"/>
        <source>no gains from the %1 rule settle within %2 ms with at most %3 % overshoot on the motor&apos;s model, even with P at a tenth of the rule&apos;s</source>
        <translation>即使将 P 降到规则值的十分之一，%1 规则的增益在电机模型上也无法在 %2 ms 内以不超过 %3 % 的超调稳定</translation>
    </message>
    <message>
        <location filename="../model/tuning/GainDesign.cpp" line="60"/>
        <source>Try a rule that allows more overshoot or a smaller step (a lower operating speed), or raise the drive&apos;s current limit if the motor allows it.</source>
        <translation>请改用允许较大超调的规则或较小的阶跃（较低的运行速度）；若电机允许，也可提高驱动器的电流限值。</translation>
    </message>
</context>
<context>
    <name>opentop::GetCommand</name>
    <message>
        <location filename="../cli/GetCommand.cpp" line="44"/>
        <source>Read parameters by name in engineering units (or registers with --raw)</source>
        <translation>按名称读取参数，以工程单位显示（使用 --raw 则读取寄存器）</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="50"/>
        <source>Read every parameter of a group (see params).</source>
        <translation>读取一个组的全部参数（参见 params）。</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="50"/>
        <source>GROUP</source>
        <translation>GROUP</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="51"/>
        <source>Read every readable parameter.</source>
        <translation>读取全部可读参数。</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="53"/>
        <source>Read registers by address: ADDR or ADDR:COUNT (0x.. or decimal).</source>
        <translation>按地址读取寄存器：ADDR 或 ADDR:COUNT（0x.. 或十进制）。</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="53"/>
        <source>ADDR</source>
        <translation>ADDR</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="55"/>
        <source>Function code for --raw: 3 (holding) or 4 (input) to read, 6 or 16 to write.</source>
        <translation>--raw 的功能码：读取用 3（保持寄存器）或 4（输入寄存器），写入用 6 或 16。</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="56"/>
        <source>FC</source>
        <translation>FC</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="64"/>
        <source>error: give one machine number first: get ID NAME...</source>
        <translation>错误：请先指定一个站号：get ID NAME...</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="72"/>
        <source>error: name parameters, or give exactly one of --group, --all, --raw</source>
        <translation>错误：请指定参数名，或只指定 --group、--all、--raw 中的一个</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="80"/>
        <location filename="../cli/GetCommand.cpp" line="210"/>
        <source>error: %1</source>
        <translation>错误：%1</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="91"/>
        <source>error: %1 has no group &quot;%2&quot;; groups: %3</source>
        <translation>错误：%1 没有组 &quot;%2&quot;；可用组：%3</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="109"/>
        <source>error: %1 is a write-only command and cannot be read</source>
        <translation>错误：%1 是只写命令，无法读取</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="110"/>
        <source>error: %1 has no parameter &quot;%2&quot;; see &quot;opentop-cli params --family %1&quot;</source>
        <translation>错误：%1 没有参数 &quot;%2&quot;；请参阅 &quot;opentop-cli params --family %1&quot;</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="124"/>
        <source>interrupted</source>
        <translation>已中断</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="154"/>
        <source>Parameter</source>
        <translation>参数</translation>
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
        <translation>标签</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="159"/>
        <source>(failed: %1)</source>
        <translation>（失败：%1）</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="161"/>
        <source>  ! outside the profile&apos;s allowed values</source>
        <translation>  ! 超出设备描述的允许值</translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/GetCommand.cpp" line="168"/>
        <source>error: %n parameter(s) could not be read</source>
        <translation>
            <numerusform>错误：%n 个参数无法读取</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="191"/>
        <source>error: --raw needs ADDR or ADDR:COUNT (address 0x0000–0xFFFF, count 1–125) and --fc 3 or 4</source>
        <translation>错误：--raw 需要 ADDR 或 ADDR:COUNT（地址 0x0000–0xFFFF，数量 1–125）以及 --fc 3 或 4</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="223"/>
        <source>Address</source>
        <translation>地址</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="223"/>
        <source>Hex</source>
        <translation>十六进制</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="223"/>
        <source>Decimal</source>
        <translation>十进制</translation>
    </message>
</context>
<context>
    <name>opentop::GoldenLimits</name>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="67"/>
        <source>the golden unit did not pass its own test (%1): no limits can come from it</source>
        <translation>标准样机未通过自身的检测（%1）：无法由它确定限值</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="75"/>
        <source>machine number %1: unknown family &quot;%2&quot;</source>
        <translation>站号 %1：未知的机型系列“%2”</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="94"/>
        <source>machine number %1: unknown parameter &quot;%2&quot;</source>
        <translation>站号 %1：未知的参数“%2”</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="104"/>
        <source>machine number %1: the golden unit&apos;s %2 was not measured</source>
        <translation>站号 %1：未测量到标准样机的 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="129"/>
        <source>Hold limits measured on the golden unit on %1: the measured value ± %2 % (at least %3 % of full scale), never wider than the default limits.</source>
        <translation>保持步骤的限值于 %1 在标准样机上测量：测量值 ± %2 %（至少为满量程的 %3 %），不会比默认限值宽。</translation>
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
        <translation>无限值</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="153"/>
        <source>%1 %2 (kept: measured %3)</source>
        <translation>%1 %2（保持原值：测量值 %3）</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="155"/>
        <source>%1 %2 (default %3, measured %4)</source>
        <translation>%1 %2（默认 %3，测量值 %4）</translation>
    </message>
</context>
<context>
    <name>opentop::GoldenMeasure</name>
    <message>
        <location filename="../model/eol/GoldenMeasure.cpp" line="31"/>
        <source>machine number %1 (%2): runs its motor for about %3 s: %4</source>
        <translation>站号 %1（%2）：电机运行约 %3 s：%4</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenMeasure.cpp" line="43"/>
        <source>golden unit</source>
        <translation>标准样机</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenMeasure.cpp" line="44"/>
        <source>recipe from a golden unit</source>
        <translation>从标准样机生成配方</translation>
    </message>
</context>
<context>
    <name>opentop::GoldenMeasureButton</name>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="36"/>
        <source>Measure limits…</source>
        <translation>测量限值…</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="42"/>
        <source>Run the golden unit on the bus through the recipe&apos;s steps once and take the hold limits from what it measures: the measured value ± 25 % (at least 5 % of full scale), never wider than the limits before</source>
        <translation>让总线上的标准样机按配方步骤运行一次，以测量值确定保持步骤的限值：测量值 ± 25 %（至少为满量程的 5 %），不会比原限值宽</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="52"/>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="87"/>
        <source>Measure limits on the golden unit</source>
        <translation>在标准样机上测量限值</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="60"/>
        <source>The recipe has no positions.</source>
        <translation>配方没有任何工位。</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="61"/>
        <source>The recipe cannot be read: %1</source>
        <translation>无法读取配方：%1</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="65"/>
        <source>Machine number %1 is not a drive on the bus: connect to the golden unit and scan first.</source>
        <translation>站号 %1 不是总线上的驱动器：请先连接标准样机并扫描。</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="70"/>
        <source>Run the golden unit through the recipe&apos;s steps? These motors turn:</source>
        <translation>要让标准样机按配方步骤运行吗？以下电机会转动：</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="76"/>
        <source>Run the motors</source>
        <translation>运行电机</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="90"/>
        <source>The bus is not connected.</source>
        <translation>总线未连接。</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="95"/>
        <source>Measuring the golden unit…</source>
        <translation>正在测量标准样机…</translation>
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
        <translation>由用户停止</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="108"/>
        <source>Machine number %1: %2</source>
        <translation>站号 %1：%2</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="120"/>
        <source>%1 is not confirmed stopped.</source>
        <translation>%1 未确认停止。</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="122"/>
        <source>No limits were taken: %1</source>
        <translation>未确定任何限值：%1</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="129"/>
        <source>Machine number %1, step %2: %3</source>
        <translation>站号 %1，步骤 %2：%3</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="135"/>
        <source>The hold limits now follow the golden unit. Check them, then save the recipe.</source>
        <translation>保持步骤的限值已按标准样机确定。请确认后保存配方。</translation>
    </message>
</context>
<context>
    <name>opentop::GoldenRecipeSource</name>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="39"/>
        <source>New recipe from %1: check the settings and the test steps&apos; limits, then save it.</source>
        <translation>已从 %1 新建配方：请检查设定和测试步骤的限值，然后保存。</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="55"/>
        <source>machine number %1 is not a known drive on the bus; scan the bus first</source>
        <translation>站号 %1 不是总线上的已知驱动器；请先扫描总线</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="64"/>
        <source>Reading the golden unit&apos;s settings…</source>
        <translation>正在读取标准样机的设定…</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="64"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="73"/>
        <source>machine number %1 is not on the bus</source>
        <translation>站号 %1 不在总线上</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="86"/>
        <source>cancelled: no recipe was made</source>
        <translation>已取消：未生成配方</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="98"/>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="103"/>
        <source>New recipe</source>
        <translation>新建配方</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="98"/>
        <source>Product name:</source>
        <translation>产品名称：</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="103"/>
        <source>Revision:</source>
        <translation>版本：</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="111"/>
        <source>Golden unit&apos;s backup file</source>
        <translation>标准样机的备份文件</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="112"/>
        <source>Backups (*.json)</source>
        <translation>备份 (*.json)</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="124"/>
        <source>No drives on the bus: connect and scan first.</source>
        <translation>总线上没有驱动器：请先连接并扫描。</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="132"/>
        <source>New recipe from drives</source>
        <translation>从驱动器新建配方</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="133"/>
        <source>Machine numbers of the golden unit&apos;s drives (found: %1):</source>
        <translation>标准样机各驱动器的站号（已找到：%1）：</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="143"/>
        <source>&quot;%1&quot; is not a machine number (1–247)</source>
        <translation>&quot;%1&quot; 不是站号（1–247）</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="152"/>
        <source>New recipe from the drives on the bus: check the settings and the test steps&apos; limits, then save it.</source>
        <translation>已从总线上的驱动器新建配方：请检查设定和测试步骤的限值，然后保存。</translation>
    </message>
</context>
<context>
    <name>opentop::GroupCheck</name>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="65"/>
        <location filename="../cli/GroupCheck.cpp" line="131"/>
        <source>error: %1</source>
        <translation>错误：%1</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="73"/>
        <source>note: --no-group-check: drives in communication group %1 (which also execute what is sent to %1) were not looked for</source>
        <translation>注意：--no-group-check：未查找通信组 %1 中的驱动器（它们也会执行发往 %1 的内容）</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="79"/>
        <source>error: the drives on this bus are not known, so drives in communication group %1 (which also execute what is sent to %1, without replying) cannot be named; nothing was sent</source>
        <translation>错误：不知道此总线上有哪些驱动器，因此无法列出通信组 %1 中的驱动器（它们也会执行发往 %1 的内容，且不应答）；未发送任何内容</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="84"/>
        <source>scan the bus first (opentop-cli scan), name its drives with --bus-drives LIST, or add --no-group-check to send it without looking</source>
        <translation>请先扫描总线（opentop-cli scan）、用 --bus-drives LIST 指定其驱动器，或加上 --no-group-check 不检查直接发送</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="109"/>
        <source>warning: the communication group of %1 could not be read</source>
        <translation>警告：无法读取 %1 的通信组</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="119"/>
        <source>note: the drives on the bus are %1, from %2; drives added since are not known until the next scan</source>
        <translation>注意：总线上的驱动器为 %1，取自%2；之后加入的驱动器要到下次扫描才会知道</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="131"/>
        <source>note: %1</source>
        <translation>注意：%1</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="134"/>
        <source>add --yes to send it to all of %1 and %2; nothing was sent</source>
        <translation>加上 --yes 才会发送给 %1 和 %2 全部；未发送任何内容</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="169"/>
        <source>not readable</source>
        <translation>不可读</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="193"/>
        <source>Read back from the drives of the group:</source>
        <translation>从该组的驱动器回读：</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="194"/>
        <source>Drive</source>
        <translation>驱动器</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="194"/>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="194"/>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="194"/>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="197"/>
        <source>(not read: %1)</source>
        <translation>（未读取：%1）</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="198"/>
        <source>verified</source>
        <translation>已确认</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="199"/>
        <source>DIFFERS from what was written</source>
        <translation>与写入值不同</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="200"/>
        <source>not verified</source>
        <translation>未确认</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="248"/>
        <source>off</source>
        <translation>关闭</translation>
    </message>
</context>
<context>
    <name>opentop::GroupFollowers</name>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="78"/>
        <source>could not be read</source>
        <translation>无法读取</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="109"/>
        <source>its control priority could not be read</source>
        <translation>无法读取其控制优先级</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="111"/>
        <source>it is in %1: it takes run commands only from its input terminals and ignores them over the bus</source>
        <translation>它处于 %1：只接受输入端子的运行命令，会忽略通过通信发送的运行命令</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="115"/>
        <source>an alarm is active: it runs only once the alarm is cleared</source>
        <translation>有报警：报警清除后才会运行</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="129"/>
        <source>error code %1h</source>
        <translation>错误代码 %1h</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="154"/>
        <source>Machine number %1 follows it.</source>
        <translation>站号 %1 会跟随。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="155"/>
        <source>Machine number %1 follows it (%2).</source>
        <translation>站号 %1 会跟随（%2）。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="158"/>
        <source>Machine number %1: not known whether it follows: %2.</source>
        <translation>站号 %1：不确定是否会跟随：%2。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="160"/>
        <source>Machine number %1 does NOT follow it: %2. To run it with this drive, set its control priority to communication priority; otherwise it shows E2h &quot;Cannot execute command&quot;.</source>
        <translation>站号 %1 不会跟随：%2。若要与此驱动器一起运行，请将其控制优先级设为通信优先级；否则它会显示 E2h“无法执行命令”。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="174"/>
        <source>Machine number %1: its run state could not be read.</source>
        <translation>站号 %1：无法读取其运行状态。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="176"/>
        <source>Machine number %1 runs.</source>
        <translation>站号 %1 正在运行。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="177"/>
        <source>Machine number %1 runs (%2).</source>
        <translation>站号 %1 正在运行（%2）。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="179"/>
        <source>Machine number %1 does not run: %2.</source>
        <translation>站号 %1 没有运行：%2。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="181"/>
        <source>Machine number %1 does not run.</source>
        <translation>站号 %1 没有运行。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="183"/>
        <source>It shows %1</source>
        <translation>它显示 %1</translation>
    </message>
</context>
<context>
    <name>opentop::GroupWriteCheck</name>
    <message>
        <location filename="../ui/groups/GroupWriteCheck.cpp" line="50"/>
        <source>Machine number %1: %2</source>
        <translation>站号 %1：%2</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupWriteCheck.cpp" line="59"/>
        <source>Communication group</source>
        <translation>通信组</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupWriteCheck.cpp" line="64"/>
        <source>Their values are read back afterwards.</source>
        <translation>之后会回读它们的值。</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupWriteCheck.cpp" line="65"/>
        <source>Send, also to %1</source>
        <translation>发送，同时发给 %1</translation>
    </message>
</context>
<context>
    <name>opentop::GroupsView</name>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="34"/>
        <source>Read &amp;groups again</source>
        <translation>重新读取通信组(&amp;G)</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="35"/>
        <source>&amp;Write plan…</source>
        <translation>写入计划(&amp;W)…</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="38"/>
        <source>A drive whose communication group is another drive&apos;s machine number is that drive&apos;s child: it executes every write and command sent to its parent, without replying. Plan the groups in the last column and write them; every drive&apos;s group is then read back.</source>
        <translation>通信组为另一台驱动器站号的驱动器，即为该驱动器的组子站：它会执行发往其组父站的每条写入和命令，但不应答。请在最后一列规划通信组并写入；之后会回读每台驱动器的通信组。</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="49"/>
        <source>Machine number</source>
        <translation>站号</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="49"/>
        <source>Model</source>
        <translation>型号</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="49"/>
        <source>Group</source>
        <translation>组</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="50"/>
        <source>Follows / followed by</source>
        <translation>跟随 / 被跟随</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="50"/>
        <source>Problem</source>
        <translation>问题</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="50"/>
        <source>Plan</source>
        <translation>计划</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="51"/>
        <source>Read back</source>
        <translation>回读</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="57"/>
        <source>Read every drive&apos;s communication group from the drive</source>
        <translation>从每台驱动器读取其通信组</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="58"/>
        <source>Write the planned groups (asks first), then read every drive&apos;s group back</source>
        <translation>写入计划的通信组（先确认），然后回读每台驱动器的通信组</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="79"/>
        <location filename="../ui/groups/GroupsView.cpp" line="145"/>
        <source>Disabled</source>
        <translation>禁用</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="146"/>
        <source>Planned group of machine number %1</source>
        <translation>站号 %1 的计划通信组</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="147"/>
        <source>The group machine number %1 should have: its own number makes it a parent, another drive&apos;s number its child; Disabled: no group</source>
        <translation>站号 %1 应设的通信组站号：设为自身站号则为组父站，设为其他驱动器的站号则为其组子站；禁用：不分组</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="166"/>
        <source>child and parent</source>
        <translation>组子站兼组父站</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="167"/>
        <source>no drive %1</source>
        <translation>无驱动器 %1</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="176"/>
        <source>not read</source>
        <translation>未读取</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="198"/>
        <source>No problem found in the groups as read from the drives.</source>
        <translation>从驱动器读取的通信组中未发现问题。</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="199"/>
        <source>Problems:</source>
        <translation>问题：</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="206"/>
        <source>%1: %2 → %3</source>
        <translation>%1：%2 → %3</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="213"/>
        <source>The plan is what the drives hold.</source>
        <translation>计划与驱动器中的设定一致。</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="214"/>
        <source>Plan changes: %1.</source>
        <translation>计划修改：%1。</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="216"/>
        <source>After it: %1</source>
        <translation>之后：%1</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="242"/>
        <source>Reading every drive&apos;s group…</source>
        <translation>正在读取每台驱动器的通信组…</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/groups/GroupsView.cpp" line="248"/>
        <source>%n drive(s) did not answer</source>
        <translation>
            <numerusform>%n 台驱动器未应答</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="263"/>
        <source>Machine number %1: group %2 → %3.</source>
        <translation>站号 %1：通信组 %2 → %3。</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="268"/>
        <source>This also reaches %1 (its children), which are written again after it.</source>
        <translation>这也会作用于 %1（其组子站），之后会再次写入它们。</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="277"/>
        <source>Warning: %1</source>
        <translation>警告：%1</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="279"/>
        <source>Write communication groups</source>
        <translation>写入通信组</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/groups/GroupsView.cpp" line="280"/>
        <source>Write the planned communication group to %n drive(s)?</source>
        <translation>
            <numerusform>将计划的通信组写入 %n 台驱动器？</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="284"/>
        <source>Drives with children are written last; every drive&apos;s group is read back afterwards.</source>
        <translation>有组子站的驱动器最后写入；之后会回读每台驱动器的通信组。</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="286"/>
        <source>&amp;Write groups</source>
        <translation>写入通信组(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="317"/>
        <source>Writing group %1 to machine number %2…</source>
        <translation>正在将通信组 %1 写入站号 %2…</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="326"/>
        <source>write failed: %1</source>
        <translation>写入失败：%1</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="340"/>
        <source>Reading every drive&apos;s group back…</source>
        <translation>正在回读每台驱动器的通信组…</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="353"/>
        <source>write failed</source>
        <translation>写入失败</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="354"/>
        <source>✓ %1</source>
        <translation>✓ %1</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="355"/>
        <source>✗ %1, planned %2</source>
        <translation>✗ %1，计划为 %2</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="365"/>
        <source>Proved: every drive read back holds its planned group.</source>
        <translation>已确认：每台回读的驱动器都保持其计划的通信组。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/groups/GroupsView.cpp" line="366"/>
        <source>Not as planned: %1 (read back; %n drive(s) did not answer).</source>
        <translation>
            <numerusform>与计划不符：%1（已回读；%n 台驱动器未应答）。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::HelpActions</name>
    <message>
        <location filename="../ui/help/HelpActions.cpp" line="18"/>
        <source>&amp;User guide</source>
        <translation>用户指南(&amp;U)</translation>
    </message>
    <message>
        <location filename="../ui/help/HelpActions.cpp" line="21"/>
        <source>&amp;Keyboard shortcuts</source>
        <translation>键盘快捷键(&amp;K)</translation>
    </message>
    <message>
        <location filename="../ui/help/HelpActions.cpp" line="25"/>
        <source>&amp;About OpenTOP</source>
        <translation>关于 OpenTOP(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/help/HelpActions.cpp" line="28"/>
        <source>About &amp;Qt</source>
        <translation>关于 Qt(&amp;Q)</translation>
    </message>
</context>
<context>
    <name>opentop::IdentityDialog</name>
    <message>
        <location filename="../ui/eol/IdentityDialog.cpp" line="23"/>
        <source>Who is it?</source>
        <translation>请确认身份</translation>
    </message>
    <message>
        <location filename="../ui/eol/IdentityDialog.cpp" line="25"/>
        <source>To %1 this station needs the %2 role or higher. Log in with your user name and password.</source>
        <translation>要%1，此工位需要%2或更高角色。请用用户名和密码登录。</translation>
    </message>
    <message>
        <location filename="../ui/eol/IdentityDialog.cpp" line="42"/>
        <source>User name:</source>
        <translation>用户名:</translation>
    </message>
    <message>
        <location filename="../ui/eol/IdentityDialog.cpp" line="43"/>
        <source>Password:</source>
        <translation>密码:</translation>
    </message>
    <message>
        <location filename="../ui/eol/IdentityDialog.cpp" line="62"/>
        <source>Refused: %1</source>
        <translation>已拒绝：%1</translation>
    </message>
</context>
<context>
    <name>opentop::InputFile</name>
    <message>
        <location filename="../model/io/InputFile.cpp" line="13"/>
        <source>cannot read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
</context>
<context>
    <name>opentop::IoTerminalsPage</name>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="31"/>
        <source>Not functioning: the drive ignores this input.</source>
        <translation>无功能：驱动器忽略该输入。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="33"/>
        <source>RUN/STOP: ON runs the motor, OFF stops it.</source>
        <translation>RUN/STOP：ON 时电机运行，OFF 时停止。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="35"/>
        <source>CW/CCW: the running direction, OFF clockwise, ON counter-clockwise.</source>
        <translation>CW/CCW：运行方向，OFF 为顺时针，ON 为逆时针。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="38"/>
        <source>CW/STOP: ON runs the motor clockwise, OFF stops it.</source>
        <translation>CW/STOP：ON 时电机顺时针运行，OFF 时停止。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="40"/>
        <source>CCW/STOP: ON runs the motor counter-clockwise, OFF stops it.</source>
        <translation>CCW/STOP：ON 时电机逆时针运行，OFF 时停止。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="43"/>
        <source>Alarm-Reset: clears an alarm (alarm erase method Alarm-Reset).</source>
        <translation>Alarm-Reset：清除报警（报警清除方式为“报警复位”）。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="51"/>
        <source>M%1: bit %1 of the running data selection (M2 M1 M0 = 000–111 select SPno1–SPno8).</source>
        <translation>M%1：运行数据选择的第 %1 位（M2 M1 M0 = 000–111 选择 SPno1–SPno8）。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="56"/>
        <source>Ext-Error (EX-Er): an external interrupt that stops the motor; the only input still active in communication priority.</source>
        <translation>Ext-Error (EX-Er)：使电机停止的外部中断；通信优先级下唯一仍有效的输入。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="61"/>
        <source>H-Free: releases the motor&apos;s holding force while stopped.</source>
        <translation>H-Free：停止时释放电机的保持力。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="63"/>
        <source>Code %1 is not a known input function.</source>
        <translation>代码 %1 不是已知的输入功能。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="71"/>
        <source>Not functioning: the output stays off.</source>
        <translation>无功能：输出保持 OFF。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="73"/>
        <source>Alarm-Out: switches when an alarm stops the motor.</source>
        <translation>Alarm-Out：报警使电机停止时动作。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="75"/>
        <source>Reach Speed-Out: switches when the motor reaches the target speed.</source>
        <translation>Reach Speed-Out：电机达到目标速度时动作。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="78"/>
        <source>VA-Out: switches before the target speed, at the target speed minus the VA speed.</source>
        <translation>VA-Out：在达到目标速度之前，于目标速度减去 VA 速度处动作。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="81"/>
        <source>Speed-Out: speed pulses, 24 per motor revolution.</source>
        <translation>Speed-Out：速度脉冲，电机每转 24 个脉冲。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="83"/>
        <source>Warning-Out: switches on a warning; the motor keeps running.</source>
        <translation>Warning-Out：发生警告时动作；电机继续运行。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="86"/>
        <source>Move-Out: switches while the motor is turning.</source>
        <translation>Move-Out：电机转动期间动作。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="88"/>
        <source>Code %1 is not a known output function.</source>
        <translation>代码 %1 不是已知的输出功能。</translation>
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
        <translation>Mode1 使用 RUN/STOP 和 CW/CCW 输入（如 UBD、SBD、DBD）；Mode2 使用 CW/STOP 和 CCW/STOP 输入（如 DB、BMD）。两种模式的输入功能代码不同：切换模式会使另一模式的输入功能失效，因此每个输入 X0–X3 都需要设定新模式下的功能。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="136"/>
        <source>Control &amp;priority:</source>
        <translation>控制优先级(&amp;P)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="137"/>
        <source>In I/O priority the input terminals run the motor. In communication priority the drive runs from bus commands and of the inputs only EX-Er (external error) acts.</source>
        <translation>I/O 优先级下由输入端子控制电机运行。通信优先级下驱动器按总线命令运行，输入端子中只有 EX-Er（外部错误）有效。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="146"/>
        <source>Inputs — CN5</source>
        <translation>输入 — CN5</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="148"/>
        <source>COM0: input common (external supply)</source>
        <translation>COM0：输入公共端（外部电源）</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="151"/>
        <source>COM1: input common (internal supply)</source>
        <translation>COM1：输入公共端（内部电源）</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="156"/>
        <source>Outputs — CN6</source>
        <translation>输出 — CN6</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="174"/>
        <source>Give each flagged input the default function of the new mode (pending, not written)</source>
        <translation>为每个标记的输入设定新模式的默认功能（待写入，尚未写入）</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="203"/>
        <source>Connector pin %1</source>
        <translation>连接器引脚 %1</translation>
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
        <translation>尚未读取。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="268"/>
        <source>Not valid in %1: choose again</source>
        <translation>在 %1 下无效：请重新选择</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="296"/>
        <source>The mode changes from %1 to %2 when written; Write page writes the mode first, then the terminals.</source>
        <translation>写入时模式将从 %1 改为 %2；“写入本页”会先写入模式，再写入端子。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="306"/>
        <source>Not valid in %1: %2. Choose their functions again before writing.</source>
        <translation>在 %1 下无效：%2。写入前请重新选择它们的功能。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="309"/>
        <source>Use %1 defaults</source>
        <translation>使用 %1 默认值</translation>
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
        <translation>&quot;%1&quot; 必须是字符串</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="48"/>
        <source>&quot;%1&quot; must be a number</source>
        <translation>&quot;%1&quot; 必须是数字</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="59"/>
        <source>%1 must be a whole number</source>
        <translation>%1 必须是整数</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="64"/>
        <source>%1 is out of range</source>
        <translation>%1 超出范围</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="80"/>
        <source>%1 must be an integer or a &quot;0x...&quot; string</source>
        <translation>%1 必须是整数或 &quot;0x...&quot; 字符串</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="104"/>
        <source>&quot;%1&quot; must be an array</source>
        <translation>&quot;%1&quot; 必须是数组</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="120"/>
        <source>&quot;%1&quot; must be an object</source>
        <translation>&quot;%1&quot; 必须是对象</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="130"/>
        <source>%1: unknown key &quot;%2&quot;</source>
        <translation>%1：未知键 &quot;%2&quot;</translation>
    </message>
</context>
<context>
    <name>opentop::Language</name>
    <message>
        <location filename="../model/i18n/Language.cpp" line="140"/>
        <source>unknown language &apos;%1&apos;; available: %2</source>
        <translation>未知的语言“%1”；可用：%2</translation>
    </message>
    <message>
        <location filename="../model/i18n/Language.cpp" line="167"/>
        <source>the %1 translation is missing from this build</source>
        <translation>此版本缺少 %1 翻译</translation>
    </message>
</context>
<context>
    <name>opentop::LanguageMenu</name>
    <message>
        <location filename="../ui/i18n/LanguageMenu.cpp" line="10"/>
        <source>&amp;Language</source>
        <translation>语言(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/i18n/LanguageMenu.cpp" line="16"/>
        <source>System language (%1)</source>
        <translation>系统语言（%1）</translation>
    </message>
</context>
<context>
    <name>opentop::LimitCheck</name>
    <message>
        <location filename="../model/eol/LimitCheck.cpp" line="35"/>
        <source>%1 could not be read</source>
        <translation>无法读取 %1</translation>
    </message>
    <message>
        <location filename="../model/eol/LimitCheck.cpp" line="50"/>
        <source>%1 %2 %3, %4</source>
        <translation>%1 %2 %3，%4</translation>
    </message>
    <message>
        <location filename="../model/eol/LimitCheck.cpp" line="73"/>
        <source>allowed %1–%2 %3</source>
        <translation>允许 %1–%2 %3</translation>
    </message>
    <message>
        <location filename="../model/eol/LimitCheck.cpp" line="75"/>
        <source>allowed at most %1 %2</source>
        <translation>最多允许 %1 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/LimitCheck.cpp" line="77"/>
        <source>allowed at least %1 %2</source>
        <translation>至少允许 %1 %2</translation>
    </message>
</context>
<context>
    <name>opentop::LineFormat</name>
    <message>
        <location filename="../transport/LineFormat.cpp" line="37"/>
        <source>Baud rate %1 is not supported: use 1200–115200.</source>
        <translation>不支持波特率 %1：请使用 1200–115200。</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="39"/>
        <source>Parity &apos;%1&apos; is not supported: use N (none), E (even) or O (odd).</source>
        <translation>不支持校验位“%1”：请使用 N（无）、E（偶）或 O（奇）。</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="42"/>
        <source>%1 data bits are not supported: use 7 or 8.</source>
        <translation>不支持 %1 位数据位：请使用 7 或 8。</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="44"/>
        <source>%1 stop bits are not supported: use 1 or 2.</source>
        <translation>不支持 %1 位停止位：请使用 1 或 2。</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="66"/>
        <source>&quot;%1&quot; is not a line format: write DATA BITS, PARITY and STOP BITS as 8N1, 8E1, 8O1 or 8N2, with the baud rate before it if it differs from the port&apos;s (9600:8E1)</source>
        <translation>“%1”不是通信格式：请按数据位、校验位、停止位写成 8N1、8E1、8O1 或 8N2，如果波特率与端口不同，写在前面（9600:8E1）</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="81"/>
        <source>&quot;%1&quot;: %2</source>
        <translation>“%1”：%2</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="98"/>
        <source>&quot;%1&quot;: write MACHINE NUMBER=FORMAT, e.g. 7=9600:8E1 or 7=8N2 (machine numbers 1–247)</source>
        <translation>“%1”：请写成 站号=格式，例如 7=9600:8E1 或 7=8N2（站号 1–247）</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="107"/>
        <source>machine number %1: %2</source>
        <translation>站号 %1：%2</translation>
    </message>
</context>
<context>
    <name>opentop::LineFormatHint</name>
    <message>
        <location filename="../model/bus/LineFormatHint.cpp" line="72"/>
        <source>%1: %2 from the factory (it can be set to %3).</source>
        <translation>%1：出厂为 %2（可设为 %3）。</translation>
    </message>
    <message>
        <location filename="../model/bus/LineFormatHint.cpp" line="77"/>
        <source>Drives set to another line format than %1 do not answer it. %2</source>
        <translation>设为 %1 以外通信格式的驱动器不会应答。%2</translation>
    </message>
</context>
<context>
    <name>opentop::LinkLoss</name>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="31"/>
        <source>Machine number %1 (%2): state never read</source>
        <translation>站号 %1（%2）：状态从未读取</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="46"/>
        <source>The connection to %1 was lost at %2.</source>
        <translation>与 %1 的连接于 %2 丢失。</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="54"/>
        <source>• %1 — last answer %2 (%3 when the link dropped)</source>
        <translation>• %1 — 最后应答 %2（连接丢失时为 %3）</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="61"/>
        <source>By the last values read, no drive was running or in communication priority.</source>
        <translation>根据最后读取的数值，没有驱动器在运行或处于通信优先级。</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="62"/>
        <source>When the link dropped, by the last values read:</source>
        <translation>连接丢失时，根据最后读取的数值：</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="70"/>
        <source>OpenTOP cannot stop these drives or give control back to their inputs until the link is back: nothing is sent over a lost link. A drive in communication priority keeps its last command. Check on the machine: each drive&apos;s own STOP input, the emergency stop, and the drives&apos; power.</source>
        <translation>在连接恢复之前，OpenTOP 无法停止这些驱动器，也无法将控制权交还其输入端子：丢失的连接上不会发送任何数据。处于通信优先级的驱动器会保持最后的命令。请在设备上检查：每台驱动器自身的停止输入端子、急停以及驱动器的电源。</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="78"/>
        <source>Before you %1: the connection to %2 was lost at %3, and OpenTOP cannot reach these drives.</source>
        <translation>%1之前：与 %2 的连接已于 %3 丢失，OpenTOP 无法访问这些驱动器。</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="96"/>
        <source>Running when it dropped, by the last values read: machine number %1.</source>
        <translation>丢失时根据最后读取的数值正在运行：站号 %1。</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="99"/>
        <source>In communication priority: machine number %1.</source>
        <translation>处于通信优先级：站号 %1。</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/run/LinkLoss.cpp" line="102"/>
        <source>%n drive(s) never read.</source>
        <translation>
            <numerusform>%n 台驱动器从未读取。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="104"/>
        <source>OpenTOP cannot stop them until the link is back: check each drive&apos;s STOP input, the emergency stop and the power on the machine.</source>
        <translation>在连接恢复之前，OpenTOP 无法停止它们：请在设备上检查每台驱动器的停止输入端子、急停和电源。</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="118"/>
        <source>Machine number %1 (%2): no answer, its state is not known</source>
        <translation>站号 %1（%2）：无应答，状态未知</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="126"/>
        <source>Every drive read again: none is running or in communication priority.</source>
        <translation>已重新读取所有驱动器：没有驱动器在运行或处于通信优先级。</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="127"/>
        <source>Read again just now:</source>
        <translation>刚刚重新读取：</translation>
    </message>
</context>
<context>
    <name>opentop::MainMenus</name>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="35"/>
        <source>&amp;Bus</source>
        <translation>总线(&amp;B)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="36"/>
        <source>Main</source>
        <translation>主工具栏</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="39"/>
        <source>&amp;Connect…</source>
        <translation>连接(&amp;C)…</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="41"/>
        <source>Choose the serial port, gateway or simulated bus (Ctrl+K)</source>
        <translation>选择串口、网关或模拟总线（Ctrl+K）</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="45"/>
        <source>&amp;Scan bus</source>
        <translation>扫描总线(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="51"/>
        <source>&amp;Disconnect</source>
        <translation>断开连接(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="57"/>
        <source>Communication &amp;groups…</source>
        <translation>通信组(&amp;G)…</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="62"/>
        <source>&amp;Export alarm histories…</source>
        <translation>导出报警履历(&amp;E)…</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="64"/>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="67"/>
        <source>&amp;Files</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="72"/>
        <source>&amp;Drive</source>
        <translation>驱动器(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="75"/>
        <source>&amp;Write all pending</source>
        <translation>写入全部待写入项(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="77"/>
        <source>&amp;Re-read all</source>
        <translation>全部重新读取(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="79"/>
        <source>Write a setting to the selected drives…</source>
        <translation>向所选驱动器写入一项设定…</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="85"/>
        <source>&amp;Next page</source>
        <translation>下一页(&amp;N)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="91"/>
        <source>&amp;Previous page</source>
        <translation>上一页(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="107"/>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="113"/>
        <source>&amp;Traffic log</source>
        <translation>报文日志(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="114"/>
        <source>Bus &amp;overview</source>
        <translation>总线总览(&amp;O)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="116"/>
        <source>T&amp;rends</source>
        <translation>趋势(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="117"/>
        <source>Communication &amp;groups</source>
        <translation>通信组(&amp;G)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="130"/>
        <source>Language</source>
        <translation>语言</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="131"/>
        <source>OpenTOP will be in %1 the next time it starts.</source>
        <translation>OpenTOP 下次启动时将以 %1 显示。</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="137"/>
        <source>&amp;End of line</source>
        <translation>下线检测(&amp;E)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="139"/>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="155"/>
        <source>connect elsewhere</source>
        <translation>连接到其他总线</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="165"/>
        <source>Export alarm histories</source>
        <translation>导出报警履历</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="166"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
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
        <translation>连接到其他总线</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="141"/>
        <source>Connecting to %1… (still connected to %2)</source>
        <translation>正在连接 %1…（仍连接着 %2）</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="158"/>
        <source>Connected: %1 (the new connection failed: %2)</source>
        <translation>已连接：%1（新连接失败：%2）</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="161"/>
        <location filename="../ui/main/MainWindow.cpp" line="175"/>
        <source>Cannot connect</source>
        <translation>无法连接</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="162"/>
        <source>%1

Still connected to %2; nothing was changed.</source>
        <translation>%1

仍连接着 %2；未作任何更改。</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="165"/>
        <location filename="../ui/main/MainWindow.cpp" line="242"/>
        <source>Not connected: %1</source>
        <translation>未连接：%1</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="217"/>
        <location filename="../ui/main/MainWindow.cpp" line="219"/>
        <source>Connection lost: %1</source>
        <translation>连接丢失：%1</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="224"/>
        <source>OpenTOP — SIMULATED BUS (no hardware) — %1</source>
        <translation>OpenTOP — 模拟总线（无硬件）— %1</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="225"/>
        <source>OpenTOP — %1</source>
        <translation>OpenTOP — %1</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="226"/>
        <source>Connecting to %1…</source>
        <translation>正在连接 %1…</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="241"/>
        <source>Connected: %1</source>
        <translation>已连接：%1</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="248"/>
        <source>Connected: %1 (simulated, no hardware)</source>
        <translation>已连接：%1（模拟，无硬件）</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="276"/>
        <source>The drive does not report its variant; %1 is the configured one.</source>
        <translation>驱动器未报告其机型；%1 为所设定的机型。</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="293"/>
        <location filename="../ui/main/MainWindow.cpp" line="303"/>
        <source>disconnect</source>
        <translation>断开连接</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="300"/>
        <source>Not connected (disconnected)</source>
        <translation>未连接（已断开）</translation>
    </message>
</context>
<context>
    <name>opentop::MissingValues</name>
    <message>
        <location filename="../model/session/MissingValues.cpp" line="18"/>
        <source>cannot check the value: reading %1 failed: %2</source>
        <translation>无法检查该值：读取 %1 失败：%2</translation>
    </message>
    <message>
        <location filename="../model/session/MissingValues.cpp" line="41"/>
        <source>reading %1 failed: %2</source>
        <translation>读取 %1 失败：%2</translation>
    </message>
</context>
<context>
    <name>opentop::MonitorCommand</name>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="47"/>
        <source>Watch speed, load, state, inputs and alarms live (Ctrl-C ends)</source>
        <translation>实时监视速度、负载、状态、输入和报警（按 Ctrl-C 结束）</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="54"/>
        <source>Time between samples of a drive in ms, %1–%2 (default 500).</source>
        <translation>每台驱动器的采样间隔（ms），%1–%2（默认 500）。</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="57"/>
        <source>MS</source>
        <translation>MS</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="58"/>
        <source>Stop after N samples per drive (default: until Ctrl-C).</source>
        <translation>每台驱动器采样 N 次后停止（默认：直到按 Ctrl-C）。</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="59"/>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="61"/>
        <source>Also write every sample to FILE (CSV with a header; a row with a note where the link was lost and where it came back).</source>
        <translation>同时将每次采样写入 FILE（带表头的 CSV；连接丢失处和恢复处各有一行备注）。</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="63"/>
        <source>FILE</source>
        <translation>FILE</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="65"/>
        <source>When the link to the bus is lost, exit 1 if it is not back within SECONDS (default: reconnect by itself, 0.5 s to 5 s apart, until Ctrl-C).</source>
        <translation>与总线的连接丢失时，若 SECONDS 秒内未恢复则以 1 退出（默认：自动重新连接，间隔 0.5 秒至 5 秒，直到按 Ctrl-C）。</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="67"/>
        <source>SECONDS</source>
        <translation>SECONDS</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="79"/>
        <source>error: usage: %1</source>
        <translation>错误：用法：%1</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="89"/>
        <source>error: --interval must be %1–%2 ms, got &quot;%3&quot;</source>
        <translation>错误：--interval 必须为 %1–%2 ms，实际为 &quot;%3&quot;</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="102"/>
        <source>error: --count must be a whole number of samples, 1 or more, got &quot;%1&quot;</source>
        <translation>错误：--count 必须是 1 以上的整数采样次数，实际为 &quot;%1&quot;</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="113"/>
        <source>error: --give-up must be a number of seconds, more than 0 and at most %1, got &quot;%2&quot;</source>
        <translation>错误：--give-up 必须是大于 0 且不超过 %1 的秒数，收到“%2”</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="125"/>
        <source>error: cannot write %1: %2</source>
        <translation>错误：无法写入 %1：%2</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="134"/>
        <source>error: %1</source>
        <translation>错误：%1</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="154"/>
        <source>warning: machine number %1: %2; speeds are shown in r/min only</source>
        <translation>警告：站号 %1：%2；速度仅以 r/min 显示</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="194"/>
        <source>error: cannot write %1: %2; monitoring stopped</source>
        <translation>错误：无法写入 %1：%2；监视已停止</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="233"/>
        <source>%1 link lost: %2 (%3); reconnecting for up to %4 s (Ctrl-C ends)</source>
        <translation>%1 连接丢失：%2（%3）；最多 %4 秒内持续重新连接（Ctrl-C 结束）</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="237"/>
        <source>%1 link lost: %2 (%3); reconnecting until it is back (Ctrl-C ends)</source>
        <translation>%1 连接丢失：%2（%3）；持续重新连接直到恢复（Ctrl-C 结束）</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="246"/>
        <source>%1 link back after %2 s: %3; monitoring goes on</source>
        <translation>%1 连接已在 %2 秒后恢复：%3；继续监视</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="261"/>
        <source>error: the link to %1 was lost at %2 and is not back after %3 s (--give-up %4): %5; monitoring stopped</source>
        <translation>错误：与 %1 的连接于 %2 丢失，%3 秒后仍未恢复（--give-up %4）：%5；监视已停止</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="303"/>
        <source>%1 error: %2</source>
        <translation>%1 错误：%2</translation>
    </message>
</context>
<context>
    <name>opentop::MonitorCsv</name>
    <message>
        <location filename="../cli/MonitorCsv.cpp" line="33"/>
        <source>link lost</source>
        <translation>连接丢失</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCsv.cpp" line="38"/>
        <source>link back</source>
        <translation>连接恢复</translation>
    </message>
</context>
<context>
    <name>opentop::MonitorDetails</name>
    <message>
        <location filename="../ui/monitor/MonitorDetails.cpp" line="81"/>
        <location filename="../ui/monitor/MonitorDetails.cpp" line="88"/>
        <source>not read</source>
        <translation>未读取</translation>
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
        <translation>目标显示值</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="118"/>
        <source>Speed shown</source>
        <translation>速度显示值</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="128"/>
        <source>Active alarm</source>
        <translation>当前报警</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="170"/>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="173"/>
        <source>code %1</source>
        <translation>代码 %1</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="173"/>
        <source>active</source>
        <translation>发生中</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="180"/>
        <source>Time</source>
        <translation>时间</translation>
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
        <translation>实时值</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="199"/>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="215"/>
        <source>State</source>
        <translation>状态</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="280"/>
        <source>%1 %2 on the drive&apos;s display</source>
        <translation>驱动器显示屏上为 %1 %2</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="289"/>
        <source>Alarm %1 %2 — %3</source>
        <translation>报警 %1 %2 — %3</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="292"/>
        <source>Alarm active (reading which one…)</source>
        <translation>报警中（正在读取报警内容…）</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="347"/>
        <source>No live state: %1</source>
        <translation>无实时状态：%1</translation>
    </message>
</context>
<context>
    <name>opentop::MonitorPollBar</name>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="30"/>
        <source>Poll every</source>
        <translation>轮询周期</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="32"/>
        <source>%1 ms (%2 Hz)</source>
        <translation>%1 ms（%2 Hz）</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="33"/>
        <source>How often every monitored drive is read. Commands you give always go first; the drives share what is left of the bus in turn.</source>
        <translation>读取每台被监视驱动器的频率。您发出的命令总是优先；各驱动器轮流使用剩余的总线时间。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="45"/>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="53"/>
        <source>Resume polling</source>
        <translation>恢复轮询</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="53"/>
        <source>Pause polling</source>
        <translation>暂停轮询</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="67"/>
        <source>Polling paused: the values shown are the last ones read (%1).</source>
        <translation>轮询已暂停：显示的是最后读取的值（%1）。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="69"/>
        <source>Polling waits for the bus scan: %1.</source>
        <translation>轮询正在等待总线扫描：%1。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="71"/>
        <source>Connection lost — not live: %1.</source>
        <translation>连接丢失 — 非实时：%1。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="73"/>
        <source>Not live: %1.</source>
        <translation>非实时：%1。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="74"/>
        <source>The drive does not answer (%1) — not live: %2.</source>
        <translation>驱动器无应答（%1）— 非实时：%2。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="77"/>
        <source>Values %1 · %2 samples/s</source>
        <translation>数值 %1 · %2 次采样/s</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="81"/>
        <source>Not read yet.</source>
        <translation>尚未读取。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="82"/>
        <source>Cannot read the drive: %1</source>
        <translation>无法读取驱动器：%1</translation>
    </message>
</context>
<context>
    <name>opentop::MotionPriorityBox</name>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="34"/>
        <source>Switch to communication priority…</source>
        <translation>切换到通信优先级…</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="59"/>
        <source>Machine number %1 is in &quot;%2&quot; (%3): it takes run, stop, direction and speed selection from its input terminals and refuses motion commands over the bus, so the test run is disabled.

Switching to &quot;%4&quot; hands these commands to the bus: the input terminals no longer start or stop the motor, and the machine&apos;s own controls stay without effect until you switch back to &quot;%2&quot;.</source>
        <translation>站号 %1 处于“%2”（%3）：它通过输入端子接收运行、停止、方向和速度选择，并拒绝来自总线的运动命令，因此试运行不可用。

切换到“%4”会将这些命令交给总线：输入端子不再能启动或停止电机，设备自身的操作元件也将无效，直到切换回“%2”。</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="85"/>
        <source>Switch to communication priority</source>
        <translation>切换到通信优先级</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="86"/>
        <source>Machine number %1 will take run, stop, direction and speed selection from the bus (%2 = &quot;%3&quot;). Its input terminals then no longer start or stop the motor.</source>
        <translation>站号 %1 将通过总线接收运行、停止、方向和速度选择（%2 = &quot;%3&quot;）。之后其输入端子不再能启动或停止电机。</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="92"/>
        <source>Switch</source>
        <translation>切换</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="101"/>
        <source>Switching to communication priority…</source>
        <translation>正在切换到通信优先级…</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="109"/>
        <source>Machine number %1 takes motion commands over the bus now.</source>
        <translation>站号 %1 现在通过总线接收运动命令。</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="111"/>
        <source>Cannot switch the control priority: %1</source>
        <translation>无法切换控制优先级：%1</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="121"/>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="127"/>
        <source>Return to I/O priority</source>
        <translation>恢复为 I/O 优先级</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="122"/>
        <source>Machine number %1 will take run, stop, direction and speed selection from its input terminals again, and refuse motion commands over the bus. If an input says run, the motor runs.</source>
        <translation>站号 %1 将重新通过输入端子接收运行、停止、方向和速度选择，并拒绝来自总线的运动命令。如果输入为运行，电机就会运行。</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="130"/>
        <source>Returning to I/O priority…</source>
        <translation>正在恢复为 I/O 优先级…</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="139"/>
        <source>Machine number %1 follows its input terminals again.</source>
        <translation>站号 %1 已重新按输入端子动作。</translation>
    </message>
</context>
<context>
    <name>opentop::MotorSpeedBox</name>
    <message>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="23"/>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="49"/>
        <source>Motor speed</source>
        <translation>电机速度</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="33"/>
        <source>not set</source>
        <translation>未设定</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="34"/>
        <source>Commutations per motor revolution (a motor property, see its data sheet). r/min = %1 ÷ this × 60.</source>
        <translation>电机每转的换相次数（电机特性，参见其规格书）。r/min = %1 ÷ 此值 × 60。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="38"/>
        <source>Commutations per revolution</source>
        <translation>每转换相次数</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="79"/>
        <source>set the commutations per revolution</source>
        <translation>请设定每转换相次数</translation>
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
        <translation>全部写入(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="41"/>
        <source>Write one setting to several drives</source>
        <translation>向多台驱动器写入一项设定</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="58"/>
        <source>Machine number</source>
        <translation>站号</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="58"/>
        <source>Model</source>
        <translation>型号</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="58"/>
        <source>Current value</source>
        <translation>当前值</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="59"/>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="77"/>
        <source>Not written: another family (%1)</source>
        <translation>未写入：其他系列（%1）</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="78"/>
        <source>Not written: not identified (%1)</source>
        <translation>未写入：未识别（%1）</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="83"/>
        <source>&amp;Setting:</source>
        <translation>设定(&amp;S)：</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="89"/>
        <source>New &amp;value:</source>
        <translation>新值(&amp;V)：</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="162"/>
        <source>cannot be read</source>
        <translation>无法读取</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="165"/>
        <source>reading…</source>
        <translation>正在读取…</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="193"/>
        <source>read failed: %1</source>
        <translation>读取失败：%1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="218"/>
        <source>Drive %1: %2 is not known yet, and the allowed values depend on it.</source>
        <translation>驱动器 %1：%2 尚未知，而允许值取决于该项。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="222"/>
        <source>drive %1: %2</source>
        <translation>驱动器 %1：%2</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="228"/>
        <source>The unit differs between the drives (%1); write them one at a time.</source>
        <translation>各驱动器的单位不同（%1）；请逐台写入。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="237"/>
        <source>Not allowed on drive %1 (%2): %3</source>
        <translation>驱动器 %1（%2）不允许：%3</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="244"/>
        <source>Not allowed on the communication group of drive %1: %2</source>
        <translation>驱动器 %1 的通信组不允许：%2</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="249"/>
        <source>None of the selected drives is identified.</source>
        <translation>所选驱动器均未识别。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="263"/>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="315"/>
        <source>Drive %1: %2</source>
        <translation>驱动器 %1：%2</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="266"/>
        <source>Allowed on %1</source>
        <translation>%1 上允许</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="274"/>
        <source>Warning: %1</source>
        <translation>警告：%1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="275"/>
        <source>Allowed on %1.</source>
        <translation>%1 上允许。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="323"/>
        <source>Set it on %n drive(s) anyway?</source>
        <translation>
            <numerusform>仍要在 %n 台驱动器上设置吗？</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="324"/>
        <source>&amp;Set it</source>
        <translation>设置(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="344"/>
        <source>Write %1 to machine number(s) %2</source>
        <translation>将 %1 写入站号 %2</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="346"/>
        <source>Nothing was written.</source>
        <translation>未写入任何内容。</translation>
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
            <numerusform>正在将 %1 写入 %n 台驱动器…</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="365"/>
        <source>Written and verified on %1 of %n drive(s).</source>
        <translation>
            <numerusform>已在 %n 台驱动器中的 %1 台上写入并校验。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="374"/>
        <source>writing…</source>
        <translation>正在写入…</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="391"/>
        <source>Written and verified</source>
        <translation>已写入并校验</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="393"/>
        <source>Written, not verified: %1</source>
        <translation>已写入，未确认：%1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="394"/>
        <source>Written, not verified (cannot be read back)</source>
        <translation>已写入，未校验（无法回读）</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="395"/>
        <source>Failed: %1</source>
        <translation>失败：%1</translation>
    </message>
</context>
<context>
    <name>opentop::NameCommand</name>
    <message>
        <location filename="../cli/NameCommand.cpp" line="39"/>
        <source>Name a machine (&quot;Infeed conveyor 3&quot;) or show the names of the bus</source>
        <translation>为机器命名（“Infeed conveyor 3”）或显示此总线的名称</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="45"/>
        <source>error: name takes a machine number and one name; put a name with spaces in quotes: name 1 &quot;Infeed conveyor 3&quot;</source>
        <translation>错误：name 需要一个站号和一个名称；含空格的名称请加引号：name 1 &quot;Infeed conveyor 3&quot;</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="53"/>
        <source>error: %1</source>
        <translation>错误：%1</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="63"/>
        <source>No machine of this bus has a name yet; give one with: name ID &quot;TEXT&quot;</source>
        <translation>此总线的机器尚无名称；请用以下方式命名：name ID &quot;TEXT&quot;</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="67"/>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="67"/>
        <source>name</source>
        <translation>名称</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="78"/>
        <source>error: &quot;%1&quot; is not a machine number 1–247</source>
        <translation>错误：“%1”不是 1–247 的站号</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="88"/>
        <source>Machine number %1 has no name.</source>
        <translation>站号 %1 没有名称。</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="94"/>
        <source>error: %1 Nothing was changed.</source>
        <translation>错误：%1 未更改任何内容。</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="107"/>
        <source>Machine number %1 has no name now.</source>
        <translation>站号 %1 现在没有名称。</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="108"/>
        <source>%1 is named now; messages, files and scans show it.</source>
        <translation>%1 已命名；消息、文件和扫描都会显示此名称。</translation>
    </message>
</context>
<context>
    <name>opentop::OutputFile</name>
    <message>
        <location filename="../model/io/OutputFile.cpp" line="24"/>
        <source>cannot write %1: it is a directory; name a file</source>
        <translation>无法写入 %1：它是目录；请指定文件</translation>
    </message>
    <message>
        <location filename="../model/io/OutputFile.cpp" line="26"/>
        <source>cannot write %1: the folder %2 does not exist</source>
        <translation>无法写入 %1：文件夹 %2 不存在</translation>
    </message>
    <message>
        <location filename="../model/io/OutputFile.cpp" line="35"/>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <location filename="../model/io/OutputFile.cpp" line="40"/>
        <source>it is a directory; name a file</source>
        <translation>是目录；请指定文件</translation>
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
        <translation>站号</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="24"/>
        <source>running data No.</source>
        <translation>运行数据编号</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="26"/>
        <source>countdown</source>
        <translation>倒计时</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="28"/>
        <source>load rate</source>
        <translation>负载率</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="47"/>
        <source>Alarm %1 %2</source>
        <translation>报警 %1 %2</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="48"/>
        <source>Alarm (code not read yet)</source>
        <translation>报警（代码尚未读取）</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="59"/>
        <source>Current speed %1 %2</source>
        <translation>当前速度 %1 %2</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="63"/>
        <source>Current speed: no finite value in %1</source>
        <translation>当前速度：%1 中无有限值</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="70"/>
        <source>Current speed %1 r/min</source>
        <translation>当前速度 %1 r/min</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="70"/>
        <source>Speed not read</source>
        <translation>速度未读取</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="76"/>
        <source>Machine number %1</source>
        <translation>站号 %1</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="83"/>
        <source>Running data SPno%1</source>
        <translation>运行数据 SPno%1</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="86"/>
        <source>Running data not read</source>
        <translation>运行数据未读取</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="96"/>
        <source>Countdown set to %1 d %2 h %3 min %4 s (the drive does not report the time left)</source>
        <translation>倒计时设定为 %1 d %2 h %3 min %4 s（驱动器不报告剩余时间）</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="110"/>
        <source>Load rate %1 %</source>
        <translation>负载率 %1 %</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="113"/>
        <source>Load rate not read</source>
        <translation>负载率未读取</translation>
    </message>
</context>
<context>
    <name>opentop::PanelMirrorView</name>
    <message>
        <location filename="../ui/monitor/PanelMirrorView.cpp" line="21"/>
        <source>Drive panel</source>
        <translation>驱动器面板</translation>
    </message>
    <message>
        <location filename="../ui/monitor/PanelMirrorView.cpp" line="51"/>
        <source>Not read yet</source>
        <translation>尚未读取</translation>
    </message>
    <message>
        <location filename="../ui/monitor/PanelMirrorView.cpp" line="64"/>
        <source>%1 (more digits than the panel has)</source>
        <translation>%1（位数超过面板可显示的位数）</translation>
    </message>
    <message>
        <location filename="../ui/monitor/PanelMirrorView.cpp" line="68"/>
        <source>Panel set to show the %1 while running.</source>
        <translation>面板设定为运行时显示%1。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/PanelMirrorView.cpp" line="69"/>
        <source>Drive panel shows %1</source>
        <translation>驱动器面板显示 %1</translation>
    </message>
    <message>
        <location filename="../ui/monitor/PanelMirrorView.cpp" line="80"/>
        <source>not live</source>
        <translation>非实时</translation>
    </message>
</context>
<context>
    <name>opentop::ParameterField</name>
    <message>
        <location filename="../ui/workspace/ParameterField.cpp" line="217"/>
        <source>%1 (not valid now)</source>
        <translation>%1（当前无效）</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterField.cpp" line="246"/>
        <source>not read</source>
        <translation>未读取</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterField.cpp" line="255"/>
        <source>Allowed: %1</source>
        <translation>允许：%1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterField.cpp" line="258"/>
        <source>On the drive: %1</source>
        <translation>驱动器中：%1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterField.cpp" line="289"/>
        <source>Not accepted: %1</source>
        <translation>未接受：%1</translation>
    </message>
</context>
<context>
    <name>opentop::ParameterInitBox</name>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="40"/>
        <source>Parameter initialisation</source>
        <translation>参数初始化</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="50"/>
        <source>Returns every setting of drive %1 to its factory default, including the communication settings: afterwards the drive may answer only at the default rate, and control priority goes back to its input terminals. The motor must be stopped. The consequences for this drive are listed before anything is sent.</source>
        <translation>将驱动器 %1 的全部设定恢复为出厂默认值，包括通信设定：之后驱动器可能只在默认波特率下应答，控制优先级也会恢复为输入端子。电机必须处于停止状态。发送前会列出对该驱动器的影响。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="58"/>
        <source>&amp;Initialise all parameters of drive %1…</source>
        <translation>初始化驱动器 %1 的全部参数(&amp;I)…</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="60"/>
        <source>Asks first, naming the drive and what changes</source>
        <translation>先确认，并列出驱动器及将要改变的内容</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="88"/>
        <source>Reading what the initialisation would change…</source>
        <translation>正在读取初始化将改变的内容…</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="112"/>
        <source>Afterwards:</source>
        <translation>之后：</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="117"/>
        <source>Your %n unwritten edit(s) of this drive are discarded.</source>
        <translation>
            <numerusform>您对该驱动器的 %n 项未写入修改将被放弃。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="123"/>
        <source>Sent: %1 to machine %2 only.</source>
        <translation>已发送：%1，仅发给站号 %2。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="124"/>
        <source>Sent: %1 to machine %2.</source>
        <translation>已发送：%1，发给站号 %2。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="128"/>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="133"/>
        <source>Initialise drive %1</source>
        <translation>初始化驱动器 %1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="129"/>
        <source>Reset every setting of %1 to its factory defaults?</source>
        <translation>要将 %1 的所有设定恢复为出厂默认值吗？</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="143"/>
        <source>Cancelled; nothing was sent.</source>
        <translation>已取消；未发送任何内容。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="151"/>
        <source>Initialising drive %1…</source>
        <translation>正在初始化驱动器 %1…</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="160"/>
        <source>Drive %1 did not confirm the initialisation: %2</source>
        <translation>驱动器 %1 未确认初始化：%2</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="161"/>
        <source>Nothing was sent: %1</source>
        <translation>未发送任何内容：%1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="174"/>
        <source>&amp;Reconnect at %1 bit/s after the power-up</source>
        <translation>上电后以 %1 bit/s 重新连接(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="178"/>
        <source>Drive %1 initialised; reading its values again…</source>
        <translation>驱动器 %1 已初始化；正在重新读取其值…</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="184"/>
        <source>Drive %1 initialised; %n value(s) could not be read back (it may answer only at the default communication settings now).</source>
        <translation>
            <numerusform>驱动器 %1 已初始化；%n 个值无法回读（它现在可能只在默认通信设定下应答）。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="188"/>
        <source>Drive %1 initialised to its factory defaults; values read again.</source>
        <translation>驱动器 %1 已恢复出厂默认值；已重新读取数值。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="214"/>
        <source>Reconnecting at %1 bit/s in %2 s…</source>
        <translation>%2 s 后以 %1 bit/s 重新连接…</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="227"/>
        <source>Reconnect at %1 bit/s from the Bus menu.</source>
        <translation>请从“总线”菜单以 %1 bit/s 重新连接。</translation>
    </message>
</context>
<context>
    <name>opentop::ParameterInitialiser</name>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="65"/>
        <source>%1 drives have no parameter initialisation.</source>
        <translation>%1 驱动器没有参数初始化功能。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="68"/>
        <source>%1 = %2 (register %3)</source>
        <translation>%1 = %2（寄存器 %3）</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="76"/>
        <source>Drive %1 is running. Stop the motor first: parameter initialisation is only sent to a drive at standstill.</source>
        <translation>驱动器 %1 正在运行。请先停止电机：参数初始化只发送给处于停止状态的驱动器。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="80"/>
        <source>Whether drive %1 is running could not be read (%2), so nothing was sent.</source>
        <translation>无法读取驱动器 %1 是否在运行（%2），因此未发送任何内容。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="94"/>
        <source>Every setting of drive %1 returns to its factory default: %2. Values set for this machine are lost; save a backup first to keep them.</source>
        <translation>驱动器 %1 的全部设定将恢复为出厂默认值：%2。为该设备设定的值将丢失；如需保留，请先保存备份。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="111"/>
        <source>%1 could not be read; it returns to %2. %3</source>
        <translation>无法读取 %1；它将恢复为 %2。%3</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="114"/>
        <source>%1 goes from %2 back to %3. %4</source>
        <translation>%1 将从 %2 恢复为 %3。%4</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="119"/>
        <source>%1 stays %2 (already the default).</source>
        <translation>%1 保持 %2（已是默认值）。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="123"/>
        <source>%1 bit/s, parity %2, %3 stop bit(s)</source>
        <translation>%1 bit/s，校验位 %2，%3 个停止位</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="131"/>
        <source>The link to the drive is lost from its next power-up: it answers only at the factory line settings, %1.</source>
        <translation>从下次上电起将失去与驱动器的连接：驱动器只在出厂通信设定 %1 下应答。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="142"/>
        <source>To reach drive %1 again: switch it off and on, wait %2 s after power-on, then reconnect at %3.</source>
        <translation>要再次连接驱动器 %1：请将其断电再上电，上电后等待 %2 s，然后以 %3 重新连接。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="159"/>
        <source>Bus control is lost: the drive follows its input terminals again and refuses start, stop and speed commands over the bus; an input that is on may start the motor, with the factory input functions.</source>
        <translation>将失去总线控制：驱动器将重新按输入端子动作，并拒绝通过总线发送的启动、停止和速度命令；处于 ON 的输入可能会以出厂输入功能启动电机。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="168"/>
        <source>To control the motor over the bus again, set %1 to %2.</source>
        <translation>要再次通过总线控制电机，请将 %1 设为 %2。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="150"/>
        <source>The drive no longer follows writes sent to its group&apos;s parent, and drives that followed it no longer do.</source>
        <translation>该驱动器将不再执行发往其组父站的写入，原先跟随它的驱动器也不再跟随。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="173"/>
        <source>The machine number %1 is not a setting and does not change.</source>
        <translation>站号 %1 不是设定项，不会改变。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="175"/>
        <source>The motor must stand still: drive %1 reports it stopped now, and this is read again just before the command is sent.</source>
        <translation>电机必须静止：驱动器 %1 当前报告已停止，发送命令前会再次读取确认。</translation>
    </message>
</context>
<context>
    <name>opentop::ParameterPage</name>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="26"/>
        <location filename="../ui/workspace/ParameterPage.cpp" line="149"/>
        <source>&amp;Write page</source>
        <translation>写入本页(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="27"/>
        <source>Re&amp;vert</source>
        <translation>还原(&amp;V)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="28"/>
        <source>Re-&amp;read</source>
        <translation>重新读取(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="48"/>
        <source>Write this page&apos;s pending edits to the drive and verify them by reading back</source>
        <translation>将本页的待写入修改写入驱动器，并通过回读校验</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="49"/>
        <source>Discard this page&apos;s pending edits</source>
        <translation>放弃本页的待写入修改</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="50"/>
        <source>Read this page&apos;s values from the drive again (edits stay)</source>
        <translation>重新从驱动器读取本页的值（修改保留）</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterPage.cpp" line="137"/>
        <source>Every field is accepted now. Nothing has been written yet: Write page sends %n value(s).</source>
        <translation>
            <numerusform>所有字段现已接受。尚未写入任何值：“写入本页”将发送 %n 个值。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="150"/>
        <source>&amp;Write page (%1)</source>
        <translation>写入本页(&amp;W)（%1）</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="163"/>
        <source>Reading…</source>
        <translation>正在读取…</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterPage.cpp" line="167"/>
        <source>%n value(s) could not be read</source>
        <translation>
            <numerusform>%n 个值无法读取</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterPage.cpp" line="116"/>
        <source>Nothing was written: %n field(s) not accepted. %1</source>
        <translation>
            <numerusform>未写入任何内容：%n 个字段未被接受。%1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterPage.cpp" line="208"/>
        <source>Write %n value(s) of the page %1 to machine number %2</source>
        <translation>
            <numerusform>将页面 %1 的 %n 个值写入站号 %2</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="182"/>
        <location filename="../ui/workspace/ParameterPage.cpp" line="203"/>
        <location filename="../ui/workspace/ParameterPage.cpp" line="212"/>
        <source>Nothing was written.</source>
        <translation>未写入任何内容。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterPage.cpp" line="217"/>
        <source>Writing %n value(s)…</source>
        <translation>
            <numerusform>正在写入 %n 个值…</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::ParameterReader</name>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="55"/>
        <source>entry</source>
        <translation>条目</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="63"/>
        <source>name must be lower-case dotted words: [a-z0-9_] separated by dots</source>
        <translation>名称必须是以点分隔的小写单词：[a-z0-9_]，以点分隔</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="72"/>
        <source>&quot;label&quot; is empty</source>
        <translation>&quot;label&quot; 为空</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="74"/>
        <source>group &quot;%1&quot; is not declared in &quot;groups&quot;</source>
        <translation>组 &quot;%1&quot; 未在 &quot;groups&quot; 中声明</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="76"/>
        <source>kind must be one of %1</source>
        <translation>kind 必须是 %1 之一</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="82"/>
        <source>address must be 0x0000–0xFFFF</source>
        <translation>address 必须为 0x0000–0xFFFF</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="89"/>
        <source>read must be 3 (holding) or 4 (input)</source>
        <translation>read 必须为 3（保持寄存器）或 4（输入寄存器）</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="91"/>
        <source>write must be 6 or 16</source>
        <translation>write 必须为 6 或 16</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="95"/>
        <source>input registers (read 4) cannot be written</source>
        <translation>输入寄存器（read 4）不可写入</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="97"/>
        <source>neither readable nor writable</source>
        <translation>既不可读也不可写</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="105"/>
        <source>type must be u16, s16, u32, s32, f32, string or bits</source>
        <translation>type 必须为 u16、s16、u32、s32、f32、string 或 bits</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="114"/>
        <source>string parameters need &quot;count&quot; 1–125 registers</source>
        <translation>string 参数需要 &quot;count&quot; 为 1–125 个寄存器</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="119"/>
        <source>bits parameters have &quot;count&quot; 1 or 2</source>
        <translation>bits 参数的 &quot;count&quot; 为 1 或 2</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="124"/>
        <source>%1 takes %2 register(s), not %3</source>
        <translation>%1 占用 %2 个寄存器，而不是 %3 个</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="129"/>
        <source>&quot;wordOrder&quot; is for 2-register numbers and bit fields only</source>
        <translation>&quot;wordOrder&quot; 仅适用于 2 寄存器数值和位域</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="133"/>
        <source>&quot;wordOrder&quot; must be &quot;high-first&quot; or &quot;low-first&quot;</source>
        <translation>&quot;wordOrder&quot; 必须为 &quot;high-first&quot; 或 &quot;low-first&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="136"/>
        <source>a %1-register value cannot be written with function 06; use 16</source>
        <translation>%1 寄存器的值不能用功能码 06 写入；请使用 16</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="141"/>
        <source>safety must be one of %1</source>
        <translation>safety 必须是 %1 之一</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="143"/>
        <source>commands need a &quot;safety&quot; class</source>
        <translation>命令需要 &quot;safety&quot; 类别</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="146"/>
        <source>code table &quot;%1&quot; is not declared</source>
        <translation>代码表 &quot;%1&quot; 未声明</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="157"/>
        <source>a setting needs &quot;allowed&quot; or &quot;enum&quot;</source>
        <translation>设定需要 &quot;allowed&quot; 或 &quot;enum&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="160"/>
        <source>a writable parameter needs &quot;allowed&quot; or &quot;enum&quot;</source>
        <translation>可写参数需要 &quot;allowed&quot; 或 &quot;enum&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="165"/>
        <source>bits parameters need &quot;bits&quot;</source>
        <translation>bits 参数需要 &quot;bits&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="173"/>
        <source>&quot;backup&quot; must be true or false</source>
        <translation>&quot;backup&quot; 必须为 true 或 false</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="178"/>
        <source>only readable and writable parameters can be backed up</source>
        <translation>只有可读且可写的参数才能备份</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="191"/>
        <source>%1 needs &quot;address&quot; and &quot;count&quot;</source>
        <translation>%1 需要 &quot;address&quot; 和 &quot;count&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="193"/>
        <source>%1: the parameter is not writable</source>
        <translation>%1：该参数不可写入</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="196"/>
        <source>%1: address 0x0000–0xFFFF and count 1–%2 (limits.maxWriteRegisters)</source>
        <translation>%1：address 须为 0x0000–0xFFFF，count 须为 1–%2（limits.maxWriteRegisters）</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="205"/>
        <source>%1: tail values are registers, 0–65535</source>
        <translation>%1：tail 的值为寄存器值，0–65535</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="213"/>
        <source>%1: the parameter&apos;s registers must lie in the block, before its tail</source>
        <translation>%1：参数的寄存器必须位于块内、tail 之前</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="221"/>
        <source>scale must be positive</source>
        <translation>scale 必须为正数</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="233"/>
        <source>decimals must be 0–9</source>
        <translation>decimals 必须为 0–9</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="257"/>
        <source>recommended[%1] is not inside one of the &quot;allowed&quot; intervals</source>
        <translation>recommended[%1] 不在任何 &quot;allowed&quot; 区间内</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="275"/>
        <source>default %1 is not a whole number of steps of %2</source>
        <translation>默认值 %1 不是步长 %2 的整数倍</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="284"/>
        <source>default must be a number (or &quot;0x...&quot; code)</source>
        <translation>默认值必须是数字（或 &quot;0x...&quot; 代码）</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="287"/>
        <source>default must be a number or a string</source>
        <translation>默认值必须是数字或字符串</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="298"/>
        <source>%1 must be an object {&quot;min&quot;:…, &quot;max&quot;:…}</source>
        <translation>%1 必须是对象 {&quot;min&quot;:…, &quot;max&quot;:…}</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="305"/>
        <source>%1 needs numeric min and max</source>
        <translation>%1 需要数值型的 min 和 max</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="311"/>
        <source>%1: %2 is not a whole number of steps of %3</source>
        <translation>%1：%2 不是步长 %3 的整数倍</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="319"/>
        <source>%1: min is greater than max</source>
        <translation>%1：min 大于 max</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="333"/>
        <source>%1 must be an object {&quot;value&quot;:…, &quot;label&quot;:…}</source>
        <translation>%1 必须是对象 {&quot;value&quot;:…, &quot;label&quot;:…}</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="349"/>
        <source>%1 has no label</source>
        <translation>%1 没有 label</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="351"/>
        <source>%1 repeats a code or label</source>
        <translation>%1 有重复的代码或 label</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="362"/>
        <source>&quot;bits&quot; only belongs to type bits</source>
        <translation>&quot;bits&quot; 只属于 bits 类型</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="386"/>
        <source>%1.appliesWhen needs &quot;param&quot; and &quot;equals&quot;</source>
        <translation>%1.appliesWhen 需要 &quot;param&quot; 和 &quot;equals&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="391"/>
        <source>%1 lies outside the %2-bit register</source>
        <translation>%1 超出 %2 位寄存器</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="393"/>
        <source>%1 needs a unique name</source>
        <translation>%1 需要唯一的名称</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="407"/>
        <source>%1 must be an object</source>
        <translation>%1 必须是对象</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="419"/>
        <source>%1 needs either &quot;variant&quot; or &quot;param&quot;</source>
        <translation>%1 需要 &quot;variant&quot; 或 &quot;param&quot; 之一</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="422"/>
        <source>%1: variant &quot;%2&quot; is not declared</source>
        <translation>%1：机型 &quot;%2&quot; 未声明</translation>
    </message>
</context>
<context>
    <name>opentop::ParamsCommand</name>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="82"/>
        <source>List every parameter of the device profiles</source>
        <translation>列出设备描述中的全部参数</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="162"/>
        <source>error: params takes no arguments; use --family F</source>
        <translation>错误：params 不接受参数；请使用 --family F</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="170"/>
        <source>error: unknown family &quot;%1&quot;; known: %2</source>
        <translation>错误：未知系列 &quot;%1&quot;；已知：%2</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="192"/>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="192"/>
        <source>Label</source>
        <translation>标签</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="192"/>
        <source>Address</source>
        <translation>地址</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="192"/>
        <source>FC</source>
        <translation>FC</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="192"/>
        <source>Type</source>
        <translation>类型</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="192"/>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="193"/>
        <source>Allowed</source>
        <translation>允许值</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="193"/>
        <source>Default</source>
        <translation>默认值</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="193"/>
        <source>Access</source>
        <translation>访问</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="193"/>
        <source>Group</source>
        <translation>组</translation>
    </message>
</context>
<context>
    <name>opentop::PasswordHash</name>
    <message>
        <location filename="../model/access/PasswordHash.cpp" line="52"/>
        <source>a password needs at least %1 characters</source>
        <translation>密码至少需要 %1 个字符</translation>
    </message>
</context>
<context>
    <name>opentop::PidGains</name>
    <message>
        <location filename="../model/tuning/PidGains.cpp" line="9"/>
        <source>P %1, I %2, D %3, D period %4 ms</source>
        <translation>P %1，I %2，D %3，D 周期 %4 ms</translation>
    </message>
</context>
<context>
    <name>opentop::PlantModel</name>
    <message>
        <location filename="../model/tuning/PlantModel.cpp" line="18"/>
        <source>the relay test gives no usable model (K·Ku = %1, Tu = %2 ms)</source>
        <translation>继电器测试无法得出可用的模型（K·Ku = %1，Tu = %2 ms）</translation>
    </message>
</context>
<context>
    <name>opentop::PortsCommand</name>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="16"/>
        <source>List serial ports and USB adapters</source>
        <translation>列出串口和 USB 适配器</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="23"/>
        <source>error: ports takes no arguments</source>
        <translation>错误：ports 不接受参数</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="43"/>
        <source>No serial ports found.</source>
        <translation>未找到串口。</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="47"/>
        <source>Port</source>
        <translation>端口</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="48"/>
        <source>Adapter</source>
        <translation>适配器</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="49"/>
        <source>Manufacturer</source>
        <translation>制造商</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="50"/>
        <source>Serial no.</source>
        <translation>序列号</translation>
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
        <translation>%1 不是探测记录文件（%2）：已忽略；之前中断的探测可能在驱动器上留下了探测值</translation>
    </message>
    <message>
        <location filename="../model/session/ProbeJournal.cpp" line="42"/>
        <source>cannot create the folder of %1</source>
        <translation>无法创建 %1 的文件夹</translation>
    </message>
    <message>
        <location filename="../model/session/ProbeJournal.cpp" line="78"/>
        <location filename="../model/session/ProbeJournal.cpp" line="92"/>
        <source>%1 is locked by another program</source>
        <translation>%1 已被其他程序锁定</translation>
    </message>
</context>
<context>
    <name>opentop::ProductionMode</name>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="39"/>
        <source>&amp;Production mode (end of line)</source>
        <translation>生产模式（下线检测）(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="42"/>
        <source>The operator screen of an end-of-line station; no parameter editing until you switch back (Ctrl+Shift+P)</source>
        <translation>下线检测工位的操作员界面；切换回来之前不能编辑参数（Ctrl+Shift+P）</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="45"/>
        <source>&amp;Full screen</source>
        <translation>全屏(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="54"/>
        <source>&amp;Station name…</source>
        <translation>工作站名称(&amp;S)…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="55"/>
        <source>The name this end-of-line station records with every unit</source>
        <translation>本下线检测站记录在每个单元上的名称</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="64"/>
        <source>%1

No unit can be tested until results can be recorded. The station tries again by itself.</source>
        <translation>%1

能够记录结果之前，无法测试任何产品。工作站会自动重试。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="83"/>
        <location filename="../ui/eol/ProductionMode.cpp" line="91"/>
        <source>Station name</source>
        <translation>工作站名称</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="84"/>
        <source>The name this station records with every unit (each station of a line needs its own):</source>
        <translation>本工作站记录在每个单元上的名称（同一产线的每个工作站需各有其名）：</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="92"/>
        <source>A station needs a name.</source>
        <translation>工作站需要名称。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="93"/>
        <source>A unit is being tested: change the name once it is finished.</source>
        <translation>正在检测单元：请在完成后再更改名称。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="110"/>
        <source>Production mode</source>
        <translation>生产模式</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="111"/>
        <source>A unit is being tested. Cancel it (Esc) or let it finish before switching back to engineering mode.</source>
        <translation>正在测试一台产品。请先取消测试（Esc）或等待测试完成，再切换回工程模式。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="63"/>
        <source>Results database</source>
        <translation>结果数据库</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="124"/>
        <source>leave production mode</source>
        <translation>退出生产模式</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="171"/>
        <source>A unit is being tested</source>
        <translation>正在测试一台产品</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="172"/>
        <source>Unit %1 is being tested. Cancel it and %2? Its motors are stopped first; the unit is recorded as aborted.</source>
        <translation>正在测试产品 %1。取消测试并%2？会先停止其电机；该产品将记录为已中止。</translation>
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
        <translation>以生产模式（下线检测工位）启动，并使用该配方。</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="33"/>
        <source>RECIPE</source>
        <translation>RECIPE</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="34"/>
        <source>Per-unit values (CSV by serial number) for production mode.</source>
        <translation>生产模式下的单台数值（按序列号对应的 CSV）。</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="34"/>
        <source>CSV</source>
        <translation>CSV</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="36"/>
        <source>Results database for production mode: an SQLite file or postgresql://user@host/db.</source>
        <translation>生产模式的结果数据库：SQLite 文件或 postgresql://user@host/db。</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="37"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="39"/>
        <source>This station&apos;s name in the results (default: as set in the program, else the computer&apos;s name); not saved.</source>
        <translation>结果中本工作站的名称（默认：程序中设置的名称，否则为计算机名称）；不会保存。</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="41"/>
        <source>NAME</source>
        <translation>名称</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="42"/>
        <source>Start full screen.</source>
        <translation>以全屏启动。</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="50"/>
        <source>--units, --results-db and --station go with --production RECIPE</source>
        <translation>--units、--results-db 和 --station 须与 --production RECIPE 一起使用</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="59"/>
        <source>--station needs a name</source>
        <translation>--station 需要名称</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="64"/>
        <source>%1 cannot be run:
  %2</source>
        <translation>%1 无法运行：
  %2</translation>
    </message>
</context>
<context>
    <name>opentop::ProductionView</name>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="56"/>
        <source>Open recipe…</source>
        <translation>打开配方…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="57"/>
        <source>Per-unit values…</source>
        <translation>单台数值…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="63"/>
        <source>Recipe:</source>
        <translation>配方：</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="84"/>
        <source>Drive</source>
        <translation>驱动器</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="84"/>
        <source>Now</source>
        <translation>当前</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="161"/>
        <source>Unit %1: %2…</source>
        <translation>产品 %1：%2…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="195"/>
        <source>Recipe not usable</source>
        <translation>配方不可用</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="196"/>
        <source>%1 cannot be run; nothing will be sent:

%2</source>
        <translation>%1 无法运行；不会发送任何内容：

%2</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="217"/>
        <source>open another recipe</source>
        <translation>打开其他配方</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="220"/>
        <source>Open recipe</source>
        <translation>打开配方</translation>
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
        <translation>单台数值</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="229"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/eol/ProductionView.cpp" line="242"/>
        <source>&lt;b&gt;%1&lt;/b&gt; rev. %2 — %n drive(s)</source>
        <translation>
            <numerusform>&lt;b&gt;%1&lt;/b&gt; 版本 %2 — %n 台驱动器</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="246"/>
        <source>&lt;i&gt;none: open the product&apos;s recipe&lt;/i&gt;</source>
        <translation>&lt;i&gt;无：请打开该产品的配方&lt;/i&gt;</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="247"/>
        <source>Station %1 · results: %2 · per-unit values: %3</source>
        <translation>工位 %1 · 结果：%2 · 单台数值：%3</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="250"/>
        <source>loaded</source>
        <translation>已载入</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="250"/>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="118"/>
        <source>Unit %1: making the station&apos;s drives safe first…</source>
        <translation>单元 %1：先使工作站的驱动器进入安全状态…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="287"/>
        <source>drive %1</source>
        <translation>驱动器 %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="288"/>
        <source>drive %1 (%2)</source>
        <translation>驱动器 %1（%2）</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="289"/>
        <source>waiting</source>
        <translation>等待中</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="294"/>
        <source>Unit %1 — attempt %2</source>
        <translation>产品 %1 — 第 %2 次</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="316"/>
        <source>Kept on this station: the results server did not answer. It is sent by itself when the server answers.</source>
        <translation>已保存在本工作站：结果服务器没有响应。服务器响应后会自动发送。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="361"/>
        <source>%1
Recorded at %2, after the results database came back.</source>
        <translation>%1
结果数据库恢复后，已于 %2 记录。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="161"/>
        <location filename="../ui/eol/ProductionView.cpp" line="295"/>
        <location filename="../ui/eol/ProductionView.cpp" line="314"/>
        <location filename="../ui/eol/ProductionView.cpp" line="362"/>
        <source>Unit %1</source>
        <translation>产品 %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="341"/>
        <source>Unit %1 ended %2, but its result is not in the results database: %3
Nothing is tested until it is recorded. The station tries again by itself (next try at %4); keep the unit aside.</source>
        <translation>产品 %1 已结束（%2），但结果未写入结果数据库：%3
记录完成前不进行任何测试。工作站会自动重试（下次 %4）；请将此产品放在一边。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="322"/>
        <source>Motor not confirmed stopped</source>
        <translation>未确认电机已停止</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="323"/>
        <source>These motors may still be turning; stop them before touching the unit:

%1</source>
        <translation>这些电机可能仍在转动；接触产品前请先使其停止：

%1</translation>
    </message>
</context>
<context>
    <name>opentop::ProfileCrossCheck</name>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="49"/>
        <source>%1: storeWith &quot;%2&quot; is not a command parameter</source>
        <translation>%1：storeWith &quot;%2&quot; 不是命令参数</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="52"/>
        <source>%1: the default is not among its allowed values</source>
        <translation>%1：默认值不在允许值范围内</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="56"/>
        <source>%1: bit field &quot;%2&quot;: function &quot;%3&quot; is not a readable parameter</source>
        <translation>%1：位域 &quot;%2&quot;：功能 &quot;%3&quot; 不是可读参数</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="63"/>
        <source>%1: condition on unknown parameter &quot;%2&quot;</source>
        <translation>%1：条件引用了未知参数 &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="65"/>
        <source>%1: the default is not allowed when %2</source>
        <translation>%1：当 %2 时不允许使用默认值</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="75"/>
        <source>%1 runs past address 0xFFFF</source>
        <translation>%1 超出地址 0xFFFF</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="78"/>
        <source>%1 overlaps &quot;%2&quot; at 0x%3 (%4 registers)</source>
        <translation>%1 与 &quot;%2&quot; 在 0x%3 处重叠（%4 个寄存器）</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="107"/>
        <source>identify: &quot;%1&quot; must be a parameter inside the identify read</source>
        <translation>identify：&quot;%1&quot; 必须是 identify 读取范围内的参数</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="110"/>
        <source>identify.nameMatch is not a valid regular expression</source>
        <translation>identify.nameMatch 不是有效的正则表达式</translation>
    </message>
</context>
<context>
    <name>opentop::ProfileLoader</name>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="345"/>
        <source>not valid JSON at offset %1: %2</source>
        <translation>偏移 %1 处不是有效的 JSON：%2</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="349"/>
        <source>the top level must be a JSON object</source>
        <translation>顶层必须是 JSON 对象</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="360"/>
        <source>&quot;parameters&quot; is empty</source>
        <translation>&quot;parameters&quot; 为空</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="371"/>
        <source>must be an object</source>
        <translation>必须是对象</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="373"/>
        <source>name repeated</source>
        <translation>名称重复</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="384"/>
        <source>texts: {setting:…} names no parameter (%1)</source>
        <translation>texts：{setting:…} 指向的参数不存在（%1）</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="393"/>
        <source>%1: cannot open: %2</source>
        <translation>%1：无法打开：%2</translation>
    </message>
</context>
<context>
    <name>opentop::ProfileTranslation</name>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="79"/>
        <source>%1 is larger than %2 MB, the most a profile translation may hold</source>
        <translation>%1 大于 %2 MB，即设备描述翻译的上限</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="97"/>
        <source>larger than %1 MB, the most a profile translation may hold</source>
        <translation>大于 %1 MB，即设备描述翻译的上限</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="102"/>
        <source>not valid JSON at offset %1: %2</source>
        <translation>偏移 %1 处不是有效的 JSON：%2</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="106"/>
        <source>the top level must be a JSON object</source>
        <translation>顶层必须是 JSON 对象</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="109"/>
        <source>&quot;format&quot; must be &quot;%1&quot;</source>
        <translation>&quot;format&quot; 必须是 &quot;%1&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="112"/>
        <source>&quot;formatVersion&quot; must be %1</source>
        <translation>&quot;formatVersion&quot; 必须是 %1</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="118"/>
        <source>&quot;family&quot; is &quot;%1&quot;, but the profile is &quot;%2&quot;</source>
        <translation>&quot;family&quot; 是 &quot;%1&quot;，但设备描述是 &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="120"/>
        <source>&quot;language&quot; is &quot;%1&quot;, expected &quot;%2&quot;</source>
        <translation>&quot;language&quot; 是 &quot;%1&quot;，应为 &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="123"/>
        <source>&quot;texts&quot; must be an object of key → text</source>
        <translation>&quot;texts&quot; 必须是 键 → 文本 的对象</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="127"/>
        <source>texts &quot;%1&quot; must be a non-empty string</source>
        <translation>texts &quot;%1&quot; 必须是非空字符串</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="144"/>
        <source>%1 key(s) of the profile missing: %2</source>
        <translation>缺少设备描述的 %1 个键：%2</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="148"/>
        <source>%1 key(s) the profile does not have: %2</source>
        <translation>%1 个键不属于此设备描述：%2</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="156"/>
        <source>texts &quot;%1&quot;: the panel codes must stay as in the English (%2), found (%3)</source>
        <translation>texts &quot;%1&quot;：面板代码必须与英文相同（%2），实际为（%3）</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="161"/>
        <source>texts &quot;%1&quot;: the placeholders must stay as in the English (%2), found (%3)</source>
        <translation>texts &quot;%1&quot;：占位符必须与英文相同（%2），实际为（%3）</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="168"/>
        <source>texts &quot;%1&quot;: the settings named ({setting:…}) must stay as in the English (%2), found (%3)</source>
        <translation>texts &quot;%1&quot;：引用的设定（{setting:…}）必须与英文相同（%2），实际为（%3）</translation>
    </message>
</context>
<context>
    <name>opentop::ProposalFlow</name>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="57"/>
        <source>Proposal rejected; the drive&apos;s gains were not changed.</source>
        <translation>已拒绝建议值；驱动器的增益未改变。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="60"/>
        <source>Proposal rejected</source>
        <translation>已拒绝建议值</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="71"/>
        <source>The accepted gains failed the check: %1. Reject them, or store them only after looking at the step.</source>
        <translation>已接受的增益未通过检查：%1。请拒绝，或先查看阶跃后再保存。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="85"/>
        <source>no step test ran after Accept</source>
        <translation>接受后未执行阶跃测试</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="87"/>
        <source>Store gains that failed the check?</source>
        <translation>要保存未通过检查的增益吗？</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="88"/>
        <source>The gains accepted on %1 did not pass the check after Accept.</source>
        <translation>在 %1 接受的增益未通过接受后的检查。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="90"/>
        <source>Stored, they stay after a power cycle and the motor may oscillate or overshoot as measured. Reject writes back the gains the drive had.</source>
        <translation>保存后重新上电仍会保留，电机可能像实测那样振荡或超调。按“拒绝”会写回驱动器原来的增益。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="95"/>
        <source>Reject the gains</source>
        <translation>拒绝此增益</translation>
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
        <translation>无法打开伪终端：%1</translation>
    </message>
    <message>
        <location filename="../sim/PtySimServer.cpp" line="112"/>
        <source>%1 is in use by another simulator (PID %2); stop it first, or choose another path for --pty</source>
        <translation>%1 正被另一个模拟器（PID %2）使用；请先停止它，或为 --pty 选择其他路径</translation>
    </message>
    <message>
        <location filename="../sim/PtySimServer.cpp" line="121"/>
        <source>cannot create the lock file %1: %2</source>
        <translation>无法创建锁文件 %1：%2</translation>
    </message>
    <message>
        <location filename="../sim/PtySimServer.cpp" line="80"/>
        <source>%1 exists and is not a symlink; refusing to replace it</source>
        <translation>%1 已存在且不是符号链接；拒绝替换</translation>
    </message>
    <message>
        <location filename="../sim/PtySimServer.cpp" line="83"/>
        <source>cannot create the symlink %1 -&gt; %2</source>
        <translation>无法创建符号链接 %1 -&gt; %2</translation>
    </message>
    <message>
        <location filename="../sim/PtySimServer.cpp" line="162"/>
        <source>the port is plugged in: %1</source>
        <translation>端口已插入：%1</translation>
    </message>
    <message>
        <location filename="../sim/PtySimServer_win.cpp" line="29"/>
        <source>a simulated serial line needs a pseudo-terminal, which Windows does not have: serve Modbus TCP with --tcp PORT (e.g. --tcp 5020) and connect with --tcp 127.0.0.1:5020</source>
        <translation>模拟的串行线路需要伪终端，而 Windows 没有：请用 --tcp PORT（例如 --tcp 5020）提供 Modbus TCP，并用 --tcp 127.0.0.1:5020 连接</translation>
    </message>
</context>
<context>
    <name>opentop::ReachedDrives</name>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="47"/>
        <source>%1, variant not known</source>
        <translation>%1，机型未知</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="62"/>
        <source>machine number %1 (%2) executes this write too (communication group %3), but has no such setting at 0x%4</source>
        <translation>站号 %1（%2）也会执行此写入（通信组 %3），但在 0x%4 没有该设置</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="86"/>
        <source>machine number %1 (%2) executes this write too (communication group %3) and does not allow it: %4</source>
        <translation>站号 %1（%2）也会执行此写入（通信组 %3），但不允许此值：%4</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="95"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="110"/>
        <source>%1 cannot be checked: %2</source>
        <translation>无法检查 %1：%2</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="150"/>
        <source>verification failed in communication group %1: %2</source>
        <translation>通信组 %1 的确认失败：%2</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="209"/>
        <source>reading %1 of machine number %2, which executes this write too, failed: %3</source>
        <translation>读取站号 %2（也会执行此写入）的 %1 失败：%3</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="245"/>
        <source>machine number %1: not verified (the setting cannot be read there)</source>
        <translation>站号 %1：未确认（该设置无法在此驱动器上读取）</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="258"/>
        <source>machine number %1: not verified, reading it back failed: %2</source>
        <translation>站号 %1：未确认，读回失败：%2</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="260"/>
        <source>the drive was removed</source>
        <translation>驱动器已移除</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="273"/>
        <source>machine number %1 holds %2</source>
        <translation>站号 %1 的值为 %2</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="274"/>
        <source>machine number %1 holds %2, not %3</source>
        <translation>站号 %1 的值为 %2，不是 %3</translation>
    </message>
</context>
<context>
    <name>opentop::Recipe</name>
    <message>
        <location filename="../model/eol/Recipe.cpp" line="64"/>
        <source>position %1 (machine number %2)</source>
        <translation>位置 %1（站号 %2）</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeApprovals</name>
    <message>
        <location filename="../model/access/RecipeApprovals.cpp" line="19"/>
        <source>recipe &quot;%1&quot; rev. %2 is a draft: this version (its checksum) is not approved, so it does not run. An engineer approves it (Approve… in the recipe editor, or opentop-cli eol recipe approve FILE --user NAME).</source>
        <translation>配方“%1”版本 %2 是草稿：此版本（其校验和）未经批准，因此不会运行。请工程师批准（配方编辑器中的“批准…”，或 opentop-cli eol recipe approve FILE --user NAME）。</translation>
    </message>
    <message>
        <location filename="../model/access/RecipeApprovals.cpp" line="56"/>
        <source>a recipe without a checksum cannot be approved: sign it first</source>
        <translation>没有校验和的配方无法批准：请先签名</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeApproveButton</name>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="16"/>
        <source>Approve…</source>
        <translation>批准…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="21"/>
        <source>Approve the saved recipe for the line (an engineer): stations with users run only approved recipes</source>
        <translation>批准已保存的配方供产线使用（工程师）：有用户的工位只运行已批准的配方</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="35"/>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="43"/>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="65"/>
        <source>Approve recipe</source>
        <translation>批准配方</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="37"/>
        <source>Save the recipe first: what is approved is the saved file&apos;s checksum.</source>
        <translation>请先保存配方：批准的是已保存文件的校验和。</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="39"/>
        <source>%1 cannot be approved: %2</source>
        <translation>%1 无法批准：%2</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="44"/>
        <source>This station has no users: an approval names its approver. Set up users with opentop-cli eol user add.</source>
        <translation>此工位没有用户：批准须记录批准人。请用 opentop-cli eol user add 设置用户。</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="50"/>
        <source>approve %1 rev. %2</source>
        <translation>批准 %1 版本 %2</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="66"/>
        <source>%1 rev. %2 is approved by %3: stations run it.</source>
        <translation>%1 版本 %2 已由 %3 批准：工位可运行。</translation>
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
        <translation>%1：%2 含有设备描述不允许的值：%3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeBuilder.cpp" line="261"/>
        <source>no drive to make a recipe of</source>
        <translation>没有可用于生成配方的驱动器</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeChecker</name>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="62"/>
        <source> (for %1)</source>
        <translation> （用于 %1）</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="94"/>
        <source>the recipe names no product</source>
        <translation>配方未指定产品</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="96"/>
        <source>the recipe has no revision</source>
        <translation>配方没有版本</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="98"/>
        <source>the recipe names no drive</source>
        <translation>配方未指定驱动器</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="111"/>
        <source>%1: machine number %2 is already position %3; every drive of a unit needs its own machine number</source>
        <translation>%1：站号 %2 已用于位置 %3；一台产品中的每台驱动器都需要各自的站号</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="133"/>
        <source>%1: unknown family &quot;%2&quot;; known: %3</source>
        <translation>%1：未知系列 &quot;%2&quot;；已知：%3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="139"/>
        <source>%1: a %2 takes machine numbers %3–%4</source>
        <translation>%1：%2 的站号范围为 %3–%4</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="152"/>
        <source>%1: the %2 has no variant &quot;%3&quot;; known: %4</source>
        <translation>%1：%2 没有机型 &quot;%3&quot;；已知：%4</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="154"/>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="156"/>
        <source>%1: variant &quot;%2&quot; is named twice</source>
        <translation>%1：机型 &quot;%2&quot; 指定了两次</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="164"/>
        <source>%1: variantProof &quot;%2&quot; is not known; use &quot;required&quot; or &quot;operator&quot; (or leave it out)</source>
        <translation>%1：variantProof“%2”无法识别；请用 &quot;required&quot; 或 &quot;operator&quot;（或省略）</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="169"/>
        <source>%1: variantProof &quot;operator&quot; needs exactly one allowed variant for the operator to confirm</source>
        <translation>%1：variantProof &quot;operator&quot; 需要恰好一个允许的机型供操作员确认</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="181"/>
        <source>%1: firmware version &quot;%2&quot; is not a version as the drive reports it (major.minor, e.g. &quot;1.5&quot;)</source>
        <translation>%1：固件版本 &quot;%2&quot; 不是驱动器报告的版本格式（major.minor，例如 &quot;1.5&quot;）</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="194"/>
        <source>the %1 has no setting &quot;%2&quot;</source>
        <translation>%1 没有设定 &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="196"/>
        <source>%1 is not a setting a recipe can write</source>
        <translation>%1 不是配方可以写入的设定</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="198"/>
        <source>%1 decides how the drive communicates; a recipe cannot change it, or the station would lose the drive in the middle of the run</source>
        <translation>%1 决定驱动器的通信方式；配方不能修改它，否则工位会在运行中途失去与驱动器的连接</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="218"/>
        <source>%1: setting %2</source>
        <translation>%1：设定 %2</translation>
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
        <translation>%1 指定了两次</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="237"/>
        <source>%1: what it allows depends on %2, which the recipe does not set; add %2 to the settings</source>
        <translation>%1：其允许值取决于 %2，但配方未设定该项；请将 %2 加入设定</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="246"/>
        <source>%1 decides what %2 allows; set %2 in the recipe too, or the drive may be left with a value that is no longer valid</source>
        <translation>%1 决定 %2 的允许值；请在配方中同时设定 %2，否则驱动器可能残留一个不再有效的值</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="262"/>
        <location filename="../model/eol/RecipeChecker.cpp" line="330"/>
        <source>%1: unit &quot;%2&quot;, but the drive&apos;s value is in &quot;%3&quot;</source>
        <translation>%1：单位为 &quot;%2&quot;，但驱动器的值以 &quot;%3&quot; 为单位</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="283"/>
        <location filename="../model/eol/RecipeChecker.cpp" line="385"/>
        <source>%1: per-unit value %2</source>
        <translation>%1：单台数值 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="294"/>
        <source>%1 is given twice (as a setting or as a per-unit value)</source>
        <translation>%1 指定了两次（作为设定或单台数值）</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="300"/>
        <source>%1: the range&apos;s lowest value %2 is above its highest value %3</source>
        <translation>%1：范围的最小值 %2 大于最大值 %3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="321"/>
        <source>%1: what it allows depends on %2, which the recipe does not set</source>
        <translation>%1：其允许值取决于 %2，但配方未设定该项</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="328"/>
        <source>%1 is not a number; a per-unit value needs a numeric setting</source>
        <translation>%1 不是数值；单台数值需要数值型设定</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="334"/>
        <source>%1: range %2–%3%4</source>
        <translation>%1：范围 %2–%3%4</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="340"/>
        <source>%1 is outside what the drive allows: %2%3</source>
        <translation>%1 超出驱动器的允许范围：%2%3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="352"/>
        <source>%1 includes values the drive does not allow; allowed: %2%3</source>
        <translation>%1 包含驱动器不允许的值；允许：%2%3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="378"/>
        <source>%1: per-unit value %2: %3%4 is outside the recipe&apos;s range %5–%6%4</source>
        <translation>%1：单台数值 %2：%3%4 超出配方的范围 %5–%6%4</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="389"/>
        <source>%1: the recipe has no per-unit value %2</source>
        <translation>%1：配方中没有单台数值 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="392"/>
        <source>the recipe has no drive at machine number %1</source>
        <translation>配方中没有站号为 %1 的驱动器</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeEditor</name>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="40"/>
        <source>Recipe editor</source>
        <translation>配方编辑器</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="61"/>
        <source>Revision:</source>
        <translation>版本：</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="63"/>
        <source>Product:</source>
        <translation>产品：</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="64"/>
        <source>Description:</source>
        <translation>说明：</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="65"/>
        <source>Position:</source>
        <translation>位置：</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="108"/>
        <source>New from drives on the bus…</source>
        <translation>从总线上的驱动器新建…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="109"/>
        <source>New from backup file…</source>
        <translation>从备份文件新建…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="110"/>
        <source>Open…</source>
        <translation>打开…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="111"/>
        <source>Save</source>
        <translation>保存</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="112"/>
        <source>Save as…</source>
        <translation>另存为…</translation>
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
        <translation>从标准样机在总线上的驱动器或其备份文件生成配方，或打开已有配方。</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="238"/>
        <source>the recipe is empty</source>
        <translation>配方为空</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="249"/>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="253"/>
        <source>The recipe passes check: it can be saved and run.</source>
        <translation>配方通过检查：可以保存和运行。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/eol/RecipeEditor.cpp" line="256"/>
        <source>%n problem(s): the recipe cannot be saved until they are fixed.</source>
        <translation>
            <numerusform>%n 个问题：修正之前无法保存配方。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/eol/RecipeEditor.cpp" line="268"/>
        <source>the recipe does not pass check (%n problem(s)); nothing was saved</source>
        <translation>
            <numerusform>配方未通过检查（%n 个问题）；未保存任何内容</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="284"/>
        <source>cannot read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="296"/>
        <source>%1 is not an OpenTOP recipe file</source>
        <translation>%1 不是 OpenTOP 配方文件</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="303"/>
        <source>Opened %1</source>
        <translation>已打开 %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="304"/>
        <source>Opened %1, which does not load as it is (%2). Saving checks it and signs it again.</source>
        <translation>已打开 %1，但它无法按原样载入（%2）。保存时会进行检查并重新签名。</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="325"/>
        <source>Open recipe</source>
        <translation>打开配方</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="326"/>
        <source>Recipes (*.json);;All files (*)</source>
        <translation>配方 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="336"/>
        <source>Save recipe</source>
        <translation>保存配方</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="338"/>
        <source>Recipes (*.json)</source>
        <translation>配方 (*.json)</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="343"/>
        <source>Saved and signed: %1</source>
        <translation>已保存并签名：%1</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeFile</name>
    <message>
        <location filename="../model/eol/RecipeFile.cpp" line="268"/>
        <source>%1 is larger than %2 MB, the most a recipe file may hold; not a recipe file</source>
        <translation>%1 大于 %2 MB，超过配方文件的上限；不是配方文件</translation>
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
        <translation>站号 %1：%2；如知道其机型请指定</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeFromDrives.cpp" line="74"/>
        <source>machine number %1: %2, %3 (%4)</source>
        <translation>站号 %1：%2，%3（%4）</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeFromDrives.cpp" line="113"/>
        <source>Made from a golden unit; variants: %1.</source>
        <translation>由标准样机制作；机型：%1。</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeLimitsTable</name>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="33"/>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="33"/>
        <source>Statistic</source>
        <translation>统计量</translation>
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
        <translation>单位</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="54"/>
        <source>Add limit</source>
        <translation>添加限值</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="55"/>
        <source>Remove limit</source>
        <translation>删除限值</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="64"/>
        <source>Limits (measured over the hold):</source>
        <translation>限值（在保持期间测量）：</translation>
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
        <translation>不是 JSON 文件：%1，位于字节 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="52"/>
        <source>not an OpenTOP recipe file: the JSON is not an object</source>
        <translation>不是 OpenTOP 配方文件：JSON 不是对象</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="78"/>
        <source>&quot;positions&quot;: the recipe names no drive</source>
        <translation>&quot;positions&quot;：配方未指定驱动器</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="83"/>
        <source>%1: must be an object</source>
        <translation>%1：必须是对象</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="100"/>
        <source>not an OpenTOP recipe file (&quot;format&quot; is &quot;%1&quot;, not &quot;%2&quot;)</source>
        <translation>不是 OpenTOP 配方文件（&quot;format&quot; 为 &quot;%1&quot;，而非 &quot;%2&quot;）</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="102"/>
        <source>not an OpenTOP recipe file (no &quot;format&quot;: &quot;%1&quot;)</source>
        <translation>不是 OpenTOP 配方文件（没有 &quot;format&quot;: &quot;%1&quot;）</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="107"/>
        <source>&quot;formatVersion&quot; must be a whole number from 1</source>
        <translation>&quot;formatVersion&quot; 必须是从 1 起的整数</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="109"/>
        <source>written by a newer OpenTOP (recipe format version %1); this version reads recipe format version %2</source>
        <translation>由更新版本的 OpenTOP 写入（配方格式版本 %1）；本版本读取配方格式版本 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="115"/>
        <source>the recipe has no checksum (&quot;checksum&quot;: &quot;sha256:…&quot;); it was not written by OpenTOP or was changed afterwards</source>
        <translation>配方没有校验和（&quot;checksum&quot;: &quot;sha256:…&quot;）；它不是由 OpenTOP 写入的，或写入后被修改过</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="121"/>
        <source>the recipe was changed after it was written (checksum mismatch); open and save it with OpenTOP to accept the change</source>
        <translation>配方在写入后被修改过（校验和不一致）；请用 OpenTOP 打开并保存以接受该修改</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="138"/>
        <source>%1: &quot;machineNumber&quot; must be a machine number 1–247</source>
        <translation>%1：&quot;machineNumber&quot; 必须是站号 1–247</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="140"/>
        <location filename="../model/eol/RecipeParser.cpp" line="217"/>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="185"/>
        <source>%1 (%2): &quot;value&quot; must be a number or a text</source>
        <translation>%1（%2）：&quot;value&quot; 必须是数字或文本</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="201"/>
        <source>%1 (%2): &quot;source&quot; must be &quot;csv&quot; or &quot;operator&quot;, not &quot;%3&quot;</source>
        <translation>%1（%2）：&quot;source&quot; 必须是 &quot;csv&quot; 或 &quot;operator&quot;，而不是 &quot;%3&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="214"/>
        <source>%1: unknown step type &quot;%2&quot;; known: %3</source>
        <translation>%1：未知步骤类型 &quot;%2&quot;；已知：%3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="230"/>
        <source>%1: &quot;spno&quot; must be a running data number such as 2</source>
        <translation>%1：&quot;spno&quot; 必须是运行数据编号，例如 2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="241"/>
        <source>%1: &quot;direction&quot; must be &quot;cw&quot; or &quot;ccw&quot;</source>
        <translation>%1：&quot;direction&quot; 必须是 &quot;cw&quot; 或 &quot;ccw&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="279"/>
        <source>%1: give either &quot;equals&quot; or limits, not both</source>
        <translation>%1：请指定 &quot;equals&quot; 或限值之一，不能同时指定</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="285"/>
        <source>%1: unknown step</source>
        <translation>%1：未知步骤</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="301"/>
        <source>%1: &quot;unit&quot; must be a text (&quot;&quot; for a value without a unit)</source>
        <translation>%1：&quot;unit&quot; 必须是文本（无单位的值用 &quot;&quot;）</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="304"/>
        <source>%1: a limit needs &quot;lower&quot;, &quot;upper&quot; or both</source>
        <translation>%1：限值需要 &quot;lower&quot;、&quot;upper&quot; 或两者</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="325"/>
        <source>&quot;retest&quot; must be an object</source>
        <translation>&quot;retest&quot; 必须是对象</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="334"/>
        <source>retest: &quot;maxAttempts&quot; must be a whole number from 0 (no limit) to 100</source>
        <translation>retest：&quot;maxAttempts&quot; 必须是 0（不限）到 100 的整数</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="344"/>
        <source>retest: &quot;passedSerial&quot; must be technician, refuse or allow, not &quot;%1&quot;</source>
        <translation>retest：&quot;passedSerial&quot; 必须是 technician、refuse 或 allow，而不是 &quot;%1&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="356"/>
        <source>%1: unknown key &quot;%2&quot;; allowed: %3</source>
        <translation>%1：未知键 &quot;%2&quot;；允许：%3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="370"/>
        <source>%1&quot;%2&quot; must be a non-empty text</source>
        <translation>%1&quot;%2&quot; 必须是非空文本</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="371"/>
        <source>%1&quot;%2&quot; must be a text</source>
        <translation>%1&quot;%2&quot; 必须是文本</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="383"/>
        <source>%1: &quot;%2&quot; must be a list of texts</source>
        <translation>%1：&quot;%2&quot; 必须是文本列表</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="386"/>
        <source>%1: &quot;%2&quot; must be a list of non-empty texts</source>
        <translation>%1：&quot;%2&quot; 必须是非空文本列表</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="396"/>
        <source>%1: &quot;%2&quot; must be a number</source>
        <translation>%1：&quot;%2&quot; 必须是数字</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="422"/>
        <source>%1&quot;%2&quot; must be a list</source>
        <translation>%1&quot;%2&quot; 必须是列表</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="425"/>
        <source>%1&quot;%2&quot; has %3 entries; at most %4 are allowed</source>
        <translation>%1&quot;%2&quot; 有 %3 个条目；最多允许 %4 个</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="431"/>
        <source>%1&quot;%2&quot;: every entry must be an object</source>
        <translation>%1&quot;%2&quot;：每个条目都必须是对象</translation>
    </message>
</context>
<context>
    <name>opentop::RecipePositionForm</name>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="125"/>
        <source>every variant of the family, e.g. dbu200, dbu400</source>
        <translation>该系列的所有机型，例如 dbu200, dbu400</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="127"/>
        <source>any firmware, e.g. 1.5, 1.6</source>
        <translation>任意固件，例如 1.5, 1.6</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="129"/>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="131"/>
        <source>Setting</source>
        <translation>设定</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="129"/>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="131"/>
        <source>Name</source>
        <translation>名称</translation>
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
        <translation>单位</translation>
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
        <translation>来源</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="137"/>
        <source>Add per-unit value…</source>
        <translation>添加单台数值…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="137"/>
        <source>Add setting…</source>
        <translation>添加设定…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="138"/>
        <source>Remove</source>
        <translation>移除</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="151"/>
        <source>Settings</source>
        <translation>设定</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="152"/>
        <source>Per-unit values</source>
        <translation>单台数值</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="153"/>
        <source>Test steps</source>
        <translation>测试步骤</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="156"/>
        <source>Machine number:</source>
        <translation>站号：</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="157"/>
        <source>Name:</source>
        <translation>名称：</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="158"/>
        <source>Family:</source>
        <translation>系列：</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="159"/>
        <source>Allowed variants:</source>
        <translation>允许的机型：</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="160"/>
        <source>Allowed firmware:</source>
        <translation>允许的固件：</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="186"/>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="337"/>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="228"/>
        <source>CSV file</source>
        <translation>CSV 文件</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="229"/>
        <source>typed by the operator</source>
        <translation>由操作员输入</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="279"/>
        <source>(unknown: %1)</source>
        <translation>（未知：%1）</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="342"/>
        <source>Add a per-unit value</source>
        <translation>添加单台数值</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="342"/>
        <source>Add a setting</source>
        <translation>添加设定</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="343"/>
        <source>Setting:</source>
        <translation>设定：</translation>
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
        <translation>%1 无法执行该步骤</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="53"/>
        <source>%1, step %2 (%3)</source>
        <translation>%1，步骤 %2（%3）</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="63"/>
        <source>the drive takes motion commands only with communication priority; put a priority step before it</source>
        <translation>驱动器只在通信优先级下接受运动命令；请在其前面加入优先级步骤</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="71"/>
        <source>the motor is not running here; put a start step before it</source>
        <translation>此处电机未运行；请在其前面加入启动步骤</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="82"/>
        <source>%1: the steps leave the motor running; end them with a stop step</source>
        <translation>%1：步骤结束时电机仍在运行；请以停止步骤结束</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="92"/>
        <source>%1 %2 s is not sane; give more than 0 s and at most %3 s</source>
        <translation>%1 %2 s 不合理；请给出大于 0 s 且不超过 %3 s 的值</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="105"/>
        <source>unit &quot;%1&quot;, but %2 is measured in &quot;%3&quot;</source>
        <translation>单位为 &quot;%1&quot;，但 %2 以 &quot;%3&quot; 为单位测量</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="129"/>
        <source>the profile&apos;s selection parameter is missing</source>
        <translation>缺少设备描述中的选择参数</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="131"/>
        <source>running data %1: %2</source>
        <translation>运行数据 %1：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="146"/>
        <source>what %1 means depends on %2, which the recipe does not set; add it to the settings</source>
        <translation>%1 的含义取决于 %2，但配方未设定该项；请将其加入设定</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="154"/>
        <source>a speed of 0 stops the motor; use a stop step</source>
        <translation>速度为 0 会使电机停止；请使用停止步骤</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="168"/>
        <source>unit &quot;%1&quot;, but with these settings %2 is in &quot;%3&quot;</source>
        <translation>单位为 &quot;%1&quot;，但在这些设定下 %2 以 &quot;%3&quot; 为单位</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="185"/>
        <source>a %1 does not report its target speed; give the target</source>
        <translation>%1 不报告其目标速度；请给出目标值</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="187"/>
        <source>the target speed must be above 0</source>
        <translation>目标速度必须大于 0</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="190"/>
        <source>the tolerance %1 must be above 0 and below the target speed</source>
        <translation>容差 %1 必须大于 0 且小于目标速度</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="194"/>
        <source>the time to reach the speed</source>
        <translation>到达速度的时间</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="198"/>
        <source>the hold time</source>
        <translation>保持时间</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="200"/>
        <source>the step measures nothing; give limits</source>
        <translation>该步骤不测量任何内容；请给出限值</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="208"/>
        <source>the margin</source>
        <translation>裕量</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="211"/>
        <source>a %1 has no deceleration time setting to wait for; give the deceleration (0 s when it brakes at once)</source>
        <translation>%1 没有可等待的减速时间设定；请给出减速时间（立即制动时为 0 s）</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="217"/>
        <source>the deceleration time %1 s is not sane; give 0–%2 s</source>
        <translation>减速时间 %1 s 不合理；请给出 0–%2 s</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="232"/>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="274"/>
        <source>the %1 has no readable value &quot;%2&quot;</source>
        <translation>%1 没有可读取的值 &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="237"/>
        <source>%1 is not a number</source>
        <translation>%1 不是数字</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="247"/>
        <source>%1: &quot;%2&quot; is not a statistic; use min, mean or max</source>
        <translation>%1：&quot;%2&quot; 不是统计量；请使用 min、mean 或 max</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="254"/>
        <source>%1: the limit&apos;s unit is &quot;%2&quot;, but the value is measured in &quot;%3&quot;</source>
        <translation>%1：限值的单位为 &quot;%2&quot;，但该值以 &quot;%3&quot; 为单位测量</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="261"/>
        <source>%1: the lower limit %2 %4 is above the upper limit %3 %4</source>
        <translation>%1：下限 %2 %4 大于上限 %3 %4</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="283"/>
        <source>%1 is a number; compare it with lower and upper limits</source>
        <translation>%1 是数字；请用下限和上限进行比较</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeStepKinds</name>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="29"/>
        <source>take communication priority</source>
        <translation>获取通信优先级</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="32"/>
        <source>select running data</source>
        <translation>选择运行数据</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="33"/>
        <source>Running data:</source>
        <translation>运行数据：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="36"/>
        <source>set the speed command</source>
        <translation>设定速度命令</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="37"/>
        <source>Speed command:</source>
        <translation>速度命令：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="38"/>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="50"/>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="70"/>
        <source>Unit:</source>
        <translation>单位：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="39"/>
        <source>the speed command&apos;s unit</source>
        <translation>速度指令的单位</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="42"/>
        <source>start</source>
        <translation>启动</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="43"/>
        <source>Direction:</source>
        <translation>旋转方向：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="46"/>
        <source>wait for speed</source>
        <translation>等待速度到达</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="47"/>
        <source>Target speed:</source>
        <translation>目标速度：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="48"/>
        <source>empty: the drive&apos;s own target speed</source>
        <translation>留空：驱动器自身的目标速度</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="49"/>
        <source>Tolerance (±):</source>
        <translation>允差（±）：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="50"/>
        <source>the speed&apos;s unit</source>
        <translation>速度的单位</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="51"/>
        <source>Within:</source>
        <translation>时限：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="54"/>
        <source>hold and measure</source>
        <translation>保持并测量</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="55"/>
        <source>Duration:</source>
        <translation>保持时间：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="59"/>
        <source>stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="60"/>
        <source>Deceleration time:</source>
        <translation>减速时间：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="61"/>
        <source>empty: the drive&apos;s setting</source>
        <translation>留空：驱动器的设定值</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="62"/>
        <source>Margin:</source>
        <translation>余量：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="63"/>
        <source>check for alarms and warnings</source>
        <translation>检查报警和警告</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="66"/>
        <source>read and compare</source>
        <translation>读取并比较</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="67"/>
        <source>Parameter:</source>
        <translation>参数：</translation>
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
        <translation>留空：无</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="69"/>
        <source>Upper limit:</source>
        <translation>上限：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="70"/>
        <source>the value&apos;s unit</source>
        <translation>数值的单位</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="71"/>
        <source>Or equals:</source>
        <translation>或等于：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="72"/>
        <source>the expected text, instead of limits</source>
        <translation>期望的文本，代替限值</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="123"/>
        <source>SPno%1</source>
        <translation>SPno%1</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="125"/>
        <source>to %1</source>
        <translation>设为 %1</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="129"/>
        <source>%1 ± %2 within %3 s</source>
        <translation>%3 s 内达到 %1 ± %2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="131"/>
        <source>the drive&apos;s target speed</source>
        <translation>驱动器的目标速度</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="134"/>
        <source>for %1 s; limits: %2</source>
        <translation>持续 %1 s；限值：%2 项</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="139"/>
        <source>stopped within %1 s + %2 s</source>
        <translation>%1 s + %2 s 内停止</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="140"/>
        <source>stopped within the deceleration time + %1 s</source>
        <translation>减速时间 + %1 s 内停止</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="144"/>
        <source>no value chosen to read yet</source>
        <translation>尚未选择要读取的值</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="148"/>
        <source>%1 is &quot;%2&quot;</source>
        <translation>%1 为“%2”</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="149"/>
        <source>%1 between %2 and %3</source>
        <translation>%1 在 %2 至 %3 之间</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="150"/>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="151"/>
        <source>any</source>
        <translation>任意</translation>
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
        <translation>步骤</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="48"/>
        <source>What it does</source>
        <translation>内容</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="56"/>
        <source>Add step</source>
        <translation>添加步骤</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="61"/>
        <source>Remove</source>
        <translation>删除</translation>
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
        <translation>（未知步骤：%1）</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="216"/>
        <source>No step selected</source>
        <translation>未选择步骤</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="217"/>
        <source>Add a step, or select one to edit it.</source>
        <translation>添加步骤，或选择一个步骤进行编辑。</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="223"/>
        <source>Step %1: %2</source>
        <translation>步骤 %1：%2</translation>
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
        <translation>此步骤没有设置项。</translation>
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
        <translation>参数：</translation>
    </message>
</context>
<context>
    <name>opentop::Reconnection</name>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="31"/>
        <source>&amp;Reconnect</source>
        <translation>重新连接(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="38"/>
        <source>Open the last connection again, with the same drives and page (Ctrl+R)</source>
        <translation>以相同的驱动器和页面重新打开上一次的连接（Ctrl+R）</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="92"/>
        <source>Reconnecting to %1…</source>
        <translation>正在重新连接 %1…</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="123"/>
        <source>Reconnected to %1: reading every drive again…</source>
        <translation>已重新连接 %1：正在重新读取所有驱动器…</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="176"/>
        <source>Reconnected to %1.</source>
        <translation>已重新连接 %1。</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="200"/>
        <source>Reconnecting failed: %1</source>
        <translation>重新连接失败：%1</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="218"/>
        <location filename="../ui/main/Reconnection.cpp" line="262"/>
        <source>Connection lost</source>
        <translation>连接丢失</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="226"/>
        <location filename="../ui/main/Reconnection.cpp" line="267"/>
        <source>Reconnect</source>
        <translation>重新连接</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="268"/>
        <source>Go on anyway</source>
        <translation>仍然继续</translation>
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
        <translation>无稳定振荡：在 %2 附近只有 %1 个完整周期，需要 %3 个</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="51"/>
        <source>Raise the relay amplitude, or choose an operating speed that leaves the output room on both sides.</source>
        <translation>请加大继电器幅值，或选择输出上下都留有余量的运行速度。</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="86"/>
        <source>the oscillation (±%1) is no larger than the hysteresis (%2)</source>
        <translation>振荡（±%1）不大于滞环（%2）</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="89"/>
        <source>Raise the relay amplitude.</source>
        <translation>请加大继电器幅值。</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="97"/>
        <source>the oscillation&apos;s period, %1 ms, holds only %2 readings (one every %3 ms): at least %4 are needed, or its period and amplitude are the bus&apos;s rather than the motor&apos;s</source>
        <translation>振荡周期 %1 ms 内只读取了 %2 次（每 %3 ms 一次）：至少需要 %4 次，否则周期和幅值反映的是总线而不是电机</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="104"/>
        <source>Raise the line rate (115200 bit/s if every drive on the bus allows it) or stop polling other drives on this bus during the test; a larger relay amplitude or another speed does not change this.</source>
        <translation>请提高波特率（若总线上所有驱动器都支持，用 115200 bit/s），或在测试期间暂停轮询此总线上的其他驱动器；加大继电器幅值或改变速度都无法改善。</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="110"/>
        <source>the oscillation is not steady: periods differ by %1 %, amplitudes by %2 % (at most %3 % and %4 %)</source>
        <translation>振荡不稳定：周期相差 %1 %，幅值相差 %2 %（上限分别为 %3 % 和 %4 %）</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="116"/>
        <source>Raise the relay amplitude so that the oscillation stands out of friction and load changes, keep the load steady during the test, and stop polling other drives on this bus meanwhile.</source>
        <translation>请加大继电器幅值，使振荡不被摩擦和负载变化淹没；测试期间保持负载稳定，并暂停轮询此总线上的其他驱动器。</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="123"/>
        <source>the oscillation is lopsided: its time above and below %1 differ by %2 % of the period (at most %3 %)</source>
        <translation>振荡不对称：高于和低于 %1 的时间相差周期的 %2 %（上限 %3 %）</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="128"/>
        <source>The output for the operating speed was misjudged or the load changed: keep the load steady, choose an operating speed further from standstill and from full output, and repeat the test.</source>
        <translation>运行速度所需的输出估计有误或负载改变：请保持负载稳定，选择离静止和最大输出都较远的运行速度，再重新测试。</translation>
    </message>
</context>
<context>
    <name>opentop::RelayAutotune</name>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="65"/>
        <source>the operating speed must be above 0 and below the test&apos;s speed limit %1 %2</source>
        <translation>运行速度必须大于 0 且小于测试的速度限值 %1 %2</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="72"/>
        <source>the relay amplitude must be 0–50 % of full output</source>
        <translation>继电器幅值必须为最大输出的 0–50 %</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="75"/>
        <source>Open loop: finding the output for %1 %2</source>
        <translation>开环：正在寻找 %1 %2 所需的输出</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="148"/>
        <source>the motor did not turn at %1 % output</source>
        <translation>输出 %1 % 时电机未转动</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="180"/>
        <source>the operating speed needs %1 % output: no room for ±%2 % around it</source>
        <translation>运行速度需要 %1 % 的输出：上下没有 ±%2 % 的余量</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="185"/>
        <source>Relay test around %1 %2 (output %3 % ± %4 %)</source>
        <translation>正在 %1 %2 附近进行继电器测试（输出 %3 % ± %4 %）</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="224"/>
        <source>no steady oscillation within %1 s: %2</source>
        <translation>%1 s 内未出现稳定振荡：%2</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="226"/>
        <source>try a larger amplitude</source>
        <translation>请尝试加大幅值</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="259"/>
        <source>the relay result was refused: %1</source>
        <translation>继电器测试结果不予采用：%1</translation>
    </message>
</context>
<context>
    <name>opentop::RelayTuning</name>
    <message>
        <location filename="../model/tuning/RelayTuning.cpp" line="28"/>
        <source>Raise the relay amplitude.</source>
        <translation>请加大继电器幅值。</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayTuning.cpp" line="49"/>
        <source>the drive&apos;s own loop, as the model extrapolates it, would oscillate with a period of %1 ms, under %2 readings (one every %3 ms): the step after Accept could not show whether the gains work</source>
        <translation>按模型外推，驱动器自身的环路会以 %1 ms 的周期振荡，不到 %2 次读取（每 %3 ms 一次）：接受后的阶跃无法显示增益是否可用</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayTuning.cpp" line="55"/>
        <source>Raise the line rate (115200 bit/s if every drive on the bus allows it) or stop polling other drives on this bus during the test.</source>
        <translation>请提高波特率（若总线上所有驱动器都支持，用 115200 bit/s），或在测试期间暂停轮询此总线上的其他驱动器。</translation>
    </message>
</context>
<context>
    <name>opentop::RestoreChoice</name>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="28"/>
        <source>Drive in file / setting</source>
        <translation>文件中的驱动器 / 设定</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="28"/>
        <source>Value in file</source>
        <translation>文件中的值</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="28"/>
        <source>Restore to</source>
        <translation>恢复到</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="55"/>
        <source>(do not restore)</source>
        <translation>（不恢复）</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="59"/>
        <source>Drive %1 (%2)</source>
        <translation>驱动器 %1（%2）</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="121"/>
        <source>Two drives of the file would be restored to drive %1.</source>
        <translation>文件中的两台驱动器将恢复到驱动器 %1。</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="126"/>
        <source>Drive %1 is not on the bus (or not identified).</source>
        <translation>驱动器 %1 不在总线上（或未识别）。</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="138"/>
        <source>Nothing chosen: tick at least one setting of a drive with a target.</source>
        <translation>未选择任何内容：请为有目标驱动器的驱动器至少勾选一项设定。</translation>
    </message>
</context>
<context>
    <name>opentop::RestoreCommand</name>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="37"/>
        <source>Show what a backup file would change on its drives; with --yes write it, verified</source>
        <translation>显示备份文件将对其驱动器作出的修改；使用 --yes 则写入并校验</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="42"/>
        <source>Restore only these drives of the file, e.g. 1,5-7.</source>
        <translation>仅恢复文件中的这些驱动器，例如 1,5-7。</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="43"/>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="44"/>
        <source>Read the drives and show the plan; write nothing.</source>
        <translation>读取驱动器并显示计划；不写入任何内容。</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="45"/>
        <source>Write the plan (without it restore only shows it).</source>
        <translation>写入计划（不加此选项时 restore 仅显示计划）。</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="55"/>
        <source>%1: the drive&apos;s settings were not read; nothing compared, nothing written</source>
        <translation>%1：未读取驱动器的设定；未比较，未写入任何内容</translation>
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
        <translation>参数</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="66"/>
        <source>file value</source>
        <translation>文件值</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="66"/>
        <source>device value</source>
        <translation>设备值</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="67"/>
        <source>result</source>
        <translation>结果</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="67"/>
        <source>action</source>
        <translation>操作</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="81"/>
        <source>%1 written and verified, %2 unchanged, %3 failed, %4 not attempted</source>
        <translation>%1 项已写入并校验，%2 项未变，%3 项失败，%4 项未尝试</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="87"/>
        <source>, %1 not confirmed</source>
        <translation>，%1 项未确认</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="89"/>
        <source>; %1 of %2 store commands written</source>
        <translation>；已写入 %2 条保存命令中的 %1 条</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="124"/>
        <source>error: name one backup file: restore FILE [--ids LIST] [--yes]</source>
        <translation>错误：请指定一个备份文件：restore FILE [--ids LIST] [--yes]</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="138"/>
        <source>error: --ids: %1</source>
        <translation>错误：--ids：%1</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="144"/>
        <source>error: %1 holds no drive with machine number %2; it holds %3</source>
        <translation>错误：%1 中没有站号为 %2 的驱动器；其中有 %3</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="165"/>
        <source>error: %1; nothing written</source>
        <translation>错误：%1；未写入任何内容</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="184"/>
        <source>error: %1: %2</source>
        <translation>错误：%1：%2</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="205"/>
        <source>%1: not attempted</source>
        <translation>%1：未尝试</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="234"/>
        <source>dry run: nothing written</source>
        <translation>仅预览：未写入任何内容</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="235"/>
        <source>nothing written; add --yes to write</source>
        <translation>未写入任何内容；加上 --yes 才会写入</translation>
    </message>
</context>
<context>
    <name>opentop::RestoreDialog</name>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="38"/>
        <source>&amp;Preview</source>
        <translation>预览(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="39"/>
        <source>&amp;Write to drives…</source>
        <translation>写入驱动器(&amp;W)…</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="40"/>
        <source>&amp;Cancel</source>
        <translation>取消(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="41"/>
        <source>&amp;Save report…</source>
        <translation>保存报告(&amp;S)…</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="43"/>
        <source>Restore from a backup file</source>
        <translation>从备份文件恢复</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="45"/>
        <source>No file chosen</source>
        <translation>未选择文件</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="46"/>
        <source>&amp;Choose file…</source>
        <translation>选择文件(&amp;C)…</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="48"/>
        <source>File:</source>
        <translation>文件：</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="60"/>
        <source>Read the drives and show what would change; writes nothing</source>
        <translation>读取驱动器并显示将要改变的内容；不写入任何内容</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="61"/>
        <source>Write the previewed changes, each verified by reading it back</source>
        <translation>写入预览的修改，每项都通过回读校验</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="62"/>
        <source>Stop after the write in progress has been verified</source>
        <translation>当前写入校验完成后停止</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="63"/>
        <source>Save the report as text, or as CSV when the name ends in .csv</source>
        <translation>将报告保存为文本；文件名以 .csv 结尾时保存为 CSV</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="64"/>
        <source>C&amp;lose</source>
        <translation>关闭(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="113"/>
        <source>%1: no such file</source>
        <translation>%1：文件不存在</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="118"/>
        <source>the file could not be read</source>
        <translation>无法读取该文件</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="119"/>
        <location filename="../ui/files/RestoreDialog.cpp" line="179"/>
        <source>Refused, nothing will be written: %1</source>
        <translation>已拒绝，不会写入任何内容：%1</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/RestoreDialog.cpp" line="124"/>
        <source>%n drive(s) in the file. Choose what to restore, then Preview.</source>
        <translation>
            <numerusform>文件中有 %n 台驱动器。请选择要恢复的内容，然后点击“预览”。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="146"/>
        <source>Refused, nothing written:</source>
        <translation>已拒绝，未写入任何内容：</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="148"/>
        <source>Drive %1 from %2: %3</source>
        <translation>来自 %2 的驱动器 %1：%3</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="178"/>
        <source>Choose a backup file first.</source>
        <translation>请先选择备份文件。</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="194"/>
        <source>Nothing was read or written: %1.</source>
        <translation>未读取也未写入任何数据：%1。</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="86"/>
        <source>Reading drive %1…</source>
        <translation>正在读取驱动器 %1…</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="86"/>
        <source>Writing drive %1…</source>
        <translation>正在写入驱动器 %1…</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="94"/>
        <source>drive %1: %2 (%v of %m)</source>
        <translation>驱动器 %1：%2（%v / %m）</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="229"/>
        <source>Stopping after the write in progress has been verified…</source>
        <translation>正在等待当前写入校验完成后停止…</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="244"/>
        <location filename="../ui/files/RestoreDialog.cpp" line="325"/>
        <location filename="../ui/files/RestoreDialog.cpp" line="330"/>
        <source>Drive %1: %2</source>
        <translation>驱动器 %1：%2</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/RestoreDialog.cpp" line="247"/>
        <source>%n setting(s) to write</source>
        <translation>
            <numerusform>%n 项设定待写入</numerusform>
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
        <translation>尚未写入任何内容。点击“写入驱动器”以应用。</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="258"/>
        <source>Nothing written.</source>
        <translation>未写入任何内容。</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="306"/>
        <source>Restore from backup file</source>
        <translation>从备份文件恢复</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="307"/>
        <source>OpenTOP backups (*.json);;All files (*)</source>
        <translation>OpenTOP 备份 (*.json);;所有文件 (*)</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/RestoreDialog.cpp" line="333"/>
        <source>Write %n setting(s) to drive(s) %1, each verified by reading it back?</source>
        <translation>
            <numerusform>将 %n 项设定写入驱动器 %1，每项都通过回读校验？</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="338"/>
        <source>Write to drives</source>
        <translation>写入驱动器</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="338"/>
        <source>&amp;Write</source>
        <translation>写入(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="343"/>
        <source>Save restore report</source>
        <translation>保存恢复报告</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="344"/>
        <source>Text (*.txt);;CSV (*.csv)</source>
        <translation>文本 (*.txt);;CSV (*.csv)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="349"/>
        <source>Could not save %1: %2</source>
        <translation>无法保存 %1：%2</translation>
    </message>
</context>
<context>
    <name>opentop::RestorePlan</name>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="71"/>
        <source>the file holds a %1 drive (%2), but machine number %3 is a %4 drive; nothing written</source>
        <translation>文件中是 %1 驱动器（%2），但站号 %3 是 %4 驱动器；未写入任何内容</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="78"/>
        <source>the file is from a %1 (%2), but machine number %3 is a %4 (%5); their allowed values differ, nothing written</source>
        <translation>文件来自 %1（%2），但站号 %3 是 %4（%5）；两者的允许值不同，未写入任何内容</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="85"/>
        <source>the drive does not tell its variant: every value must suit all variants (name it with --variant to use its own ranges)</source>
        <translation>驱动器不报告其机型：每个值都必须适用于所有机型（用 --variant 指定机型以使用其自身范围）</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="143"/>
        <source>%1: the value cannot be written exactly</source>
        <translation>%1：无法精确写入该值</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/files/RestorePlan.cpp" line="163"/>
        <source>%n value(s) of the file may not be written to this drive; nothing written</source>
        <translation>
            <numerusform>文件中有 %n 个值不能写入该驱动器；未写入任何内容</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="245"/>
        <source>%1 sent after the writes, so that the settings written survive power-off</source>
        <translation>写入后发送 %1，使写入的设定在断电后仍保留</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="248"/>
        <source>%1 sent: settings written to this drive earlier (by an interrupted restore, a page or the command line) are not stored yet</source>
        <translation>已发送 %1：之前写入此驱动器的设定（中断的恢复、页面或命令行）尚未保存</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="252"/>
        <source>%1 not sent: nothing it stores is written. What a drive has stored cannot be read back: if it loses settings at power-off, switch it off and on and restore again</source>
        <translation>未发送 %1：没有写入它所保存的设定。驱动器已保存的内容无法读回：如果断电后丢失设定，请断电再上电后重新恢复</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="286"/>
        <source>keep</source>
        <translation>保留</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="288"/>
        <source>write</source>
        <translation>写入</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="290"/>
        <source>store</source>
        <translation>保存</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="301"/>
        <source>unchanged</source>
        <translation>未变</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="304"/>
        <source>written, not verified: %1</source>
        <translation>已写入，未确认：%1</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="305"/>
        <source>written</source>
        <translation>已写入</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="305"/>
        <source>written and verified</source>
        <translation>已写入并校验</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="307"/>
        <source>failed: %1</source>
        <translation>失败：%1</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="309"/>
        <source>not attempted</source>
        <translation>未尝试</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="311"/>
        <source>not confirmed (%1): the drive may or may not hold it; run the restore again to read it back</source>
        <translation>未确认（%1）：驱动器可能保存了该值，也可能没有；请再次执行恢复以回读</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="336"/>
        <source>planned</source>
        <translation>已计划</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="338"/>
        <source>restored</source>
        <translation>已恢复</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="340"/>
        <source>refused</source>
        <translation>已拒绝</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="342"/>
        <source>communication failure</source>
        <translation>通信失败</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="344"/>
        <source>verification mismatch</source>
        <translation>校验不一致</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="346"/>
        <source>interrupted</source>
        <translation>已中断</translation>
    </message>
</context>
<context>
    <name>opentop::RestorePlanTable</name>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="14"/>
        <source>Drive</source>
        <translation>驱动器</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="14"/>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="14"/>
        <source>Action</source>
        <translation>操作</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="14"/>
        <source>File value</source>
        <translation>文件值</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="15"/>
        <source>Drive value before</source>
        <translation>驱动器原值</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="15"/>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="93"/>
        <source>&amp;Differences only</source>
        <translation>仅显示差异(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="95"/>
        <source>Show only the settings that would be written (or were), and what went wrong</source>
        <translation>只显示将写入（或已写入）的设定以及出错的项目</translation>
    </message>
</context>
<context>
    <name>opentop::RestoreReport</name>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="18"/>
        <source>%1 written and verified, %2 unchanged, %3 failed, %4 not attempted</source>
        <translation>%1 项已写入并校验，%2 项未变，%3 项失败，%4 项未尝试</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="24"/>
        <source>, %1 not confirmed</source>
        <translation>，%1 项未确认</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="26"/>
        <source>; %1 of %2 store commands written</source>
        <translation>；已写入 %2 条保存命令中的 %1 条</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="35"/>
        <source>OpenTOP restore report</source>
        <translation>OpenTOP 恢复报告</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="35"/>
        <source>File: %1</source>
        <translation>文件：%1</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="36"/>
        <source>Date: %1 (UTC)</source>
        <translation>日期：%1（UTC）</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="39"/>
        <source>Written to the drives</source>
        <translation>已写入驱动器</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="39"/>
        <source>Preview only: nothing written</source>
        <translation>仅预览：未写入任何内容</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="42"/>
        <source>Machine number %1 from %2: %3</source>
        <translation>来自 %2 的站号 %1：%3</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="53"/>
        <source>  %1: %2</source>
        <translation>  %1：%2</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="55"/>
        <source>  %1: file %2, drive %3: %4</source>
        <translation>  %1：文件 %2，驱动器 %3：%4</translation>
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
        <translation>在写入任何内容之前已中断</translation>
    </message>
    <message>
        <location filename="../model/files/Restorer.cpp" line="66"/>
        <source>reading the drive failed, nothing written (%1)</source>
        <translation>读取驱动器失败，未写入任何内容（%1）</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/files/Restorer.cpp" line="119"/>
        <source>%n value(s) of the file may not be written to the drives of the communication group; nothing written</source>
        <translation>
            <numerusform>文件中有 %n 个值不可写入通信组的驱动器；未写入任何值</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/files/Restorer.cpp" line="147"/>
        <source>interrupted after %1 of %2 writes; run the restore again to complete it</source>
        <translation>在 %2 次写入中的第 %1 次后中断；请再次执行恢复以完成</translation>
    </message>
    <message>
        <location filename="../model/files/Restorer.cpp" line="183"/>
        <source>%1 not confirmed (%2): the drive may or may not hold it; run the restore again, it reads the drive back first</source>
        <translation>%1 未确认（%2）：驱动器可能保存了该值，也可能没有；请再次执行恢复，它会先回读驱动器</translation>
    </message>
    <message>
        <location filename="../model/files/Restorer.cpp" line="217"/>
        <source>after storing, the drive holds %1</source>
        <translation>保存后，驱动器中为 %1</translation>
    </message>
    <message>
        <location filename="../model/files/Restorer.cpp" line="222"/>
        <source>the settings could not be read back after storing</source>
        <translation>保存后无法回读设定</translation>
    </message>
    <message>
        <location filename="../model/files/Restorer.cpp" line="255"/>
        <source>communication settings changed (%1): they take effect when the drive is next powered on; connect with the new settings after that</source>
        <translation>通信设定已修改（%1）：驱动器下次上电时生效；之后请用新设定连接</translation>
    </message>
</context>
<context>
    <name>opentop::ResultDatabase</name>
    <message>
        <location filename="../model/eol/ResultDatabase.cpp" line="45"/>
        <source>results database %1: %2</source>
        <translation>结果数据库 %1：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultDatabase.cpp" line="49"/>
        <source>the Qt SQL driver %1 is not installed (Debian: %2)</source>
        <translation>未安装 Qt SQL 驱动 %1（Debian：%2）</translation>
    </message>
</context>
<context>
    <name>opentop::ResultQueries</name>
    <message>
        <location filename="../model/eol/ResultQueries.cpp" line="207"/>
        <source>no unit record %1</source>
        <translation>没有产品记录 %1</translation>
    </message>
</context>
<context>
    <name>opentop::ResultSchema</name>
    <message>
        <location filename="../model/eol/ResultSchema.cpp" line="242"/>
        <source>the results database has schema version %1, newer than this program knows (%2): update OpenTOP on this station; nothing was written</source>
        <translation>结果数据库的架构版本为 %1，比本程序所知的（%2）更新：请更新本工位的 OpenTOP；未写入任何内容</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultSchema.cpp" line="277"/>
        <source>the migration left a record pointing at no unit (table %1)</source>
        <translation>迁移后留下了不指向任何产品的记录（表 %1）</translation>
    </message>
</context>
<context>
    <name>opentop::ResultSink</name>
    <message>
        <location filename="../model/eol/ResultSink.cpp" line="137"/>
        <source>the results database is not open</source>
        <translation>结果数据库未打开</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultSink.cpp" line="210"/>
        <source>the results database refuses unit %1 (serial %2): %3</source>
        <translation>结果数据库拒绝单元 %1（序列号 %2）：%3</translation>
    </message>
</context>
<context>
    <name>opentop::ResultSpool</name>
    <message>
        <location filename="../model/eol/ResultSpool.cpp" line="67"/>
        <location filename="../model/eol/ResultSpool.cpp" line="103"/>
        <source>the station&apos;s spool %1: %2</source>
        <translation>工作站暂存文件 %1：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultSpool.cpp" line="71"/>
        <source>its folder cannot be made</source>
        <translation>无法创建其文件夹</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultSpool.cpp" line="131"/>
        <source>the station&apos;s spool %1: entry %2 cannot be read (%3)</source>
        <translation>工作站暂存文件 %1：第 %2 条无法读取（%3）</translation>
    </message>
</context>
<context>
    <name>opentop::ResultStore</name>
    <message>
        <location filename="../model/eol/ResultStore.cpp" line="64"/>
        <source>interrupted: the station stopped before the unit was finished (killed, power lost or crashed); the unit was not proven</source>
        <translation>已中断：工位在产品测试完成前停止（被终止、断电或崩溃）；该产品未经验证</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultStore.cpp" line="72"/>
        <source>a unit needs a serial number</source>
        <translation>产品需要序列号</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultStore.cpp" line="197"/>
        <source>a unit is finished with pass, fail, error or aborted, not %1</source>
        <translation>产品只能以 pass、fail、error 或 aborted 结束，而不是 %1</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultStore.cpp" line="227"/>
        <source>unit %1 (serial %2) was never begun in the results database</source>
        <translation>产品 %1（序列号 %2）从未在结果数据库中开始测试</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultStore.cpp" line="229"/>
        <source>unit %1 (serial %2) is already recorded as %3; its record is kept</source>
        <translation>产品 %1（序列号 %2）已记录为 %3；保留其记录</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultStore.cpp" line="251"/>
        <source>unit %1 (serial %2) is not running in the results database: it was never begun, or was already finished or marked interrupted</source>
        <translation>产品 %1（序列号 %2）在结果数据库中不处于进行中：从未开始，或已完成，或已标记为中断</translation>
    </message>
</context>
<context>
    <name>opentop::ResultUrl</name>
    <message>
        <location filename="../model/eol/ResultUrl.cpp" line="45"/>
        <source>no database given: name a file or a postgresql:// URL</source>
        <translation>未指定数据库：请指定文件或 postgresql:// URL</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultUrl.cpp" line="53"/>
        <source>unknown database URL &quot;%1&quot;: use a file path, sqlite:PATH or postgresql://user@host/database</source>
        <translation>未知的数据库 URL &quot;%1&quot;：请使用文件路径、sqlite:PATH 或 postgresql://user@host/database</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultUrl.cpp" line="57"/>
        <source>sqlite: needs a file path</source>
        <translation>sqlite: 需要文件路径</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultUrl.cpp" line="86"/>
        <source>the host in &quot;%1&quot; has no closing ]</source>
        <translation>&quot;%1&quot; 中的主机缺少右括号 ]</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultUrl.cpp" line="114"/>
        <source>unknown connection option &quot;%1&quot; in the database URL; known: %2</source>
        <translation>数据库 URL 中有未知的连接选项 &quot;%1&quot;；已知：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultUrl.cpp" line="137"/>
        <source>the port &quot;%1&quot; in the database URL is not a number from 1 to 65535</source>
        <translation>数据库 URL 中的端口 &quot;%1&quot; 不是 1 到 65535 的数字</translation>
    </message>
</context>
<context>
    <name>opentop::ResultsBrowser</name>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="61"/>
        <source>End-of-line results</source>
        <translation>下线检测结果</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="64"/>
        <source>Started</source>
        <translation>开始时间</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="64"/>
        <source>Serial</source>
        <translation>序列号</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="64"/>
        <source>Recipe</source>
        <translation>配方</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="64"/>
        <source>Station</source>
        <translation>工位</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="65"/>
        <source>Operator</source>
        <translation>操作员</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="65"/>
        <source>Verdict</source>
        <translation>判定</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="65"/>
        <source>Time (s)</source>
        <translation>时间 (s)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="66"/>
        <source>First failure</source>
        <translation>首个不合格项</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="84"/>
        <source>Export CSV…</source>
        <translation>导出 CSV…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="85"/>
        <source>Certificate PDF…</source>
        <translation>检验证书 PDF…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="136"/>
        <source>There is no results database at %1 yet: a station makes it when it records its first unit.</source>
        <translation>%1 处尚无结果数据库：工位记录第一台产品时会创建它。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="142"/>
        <source>Opening the results database %1…</source>
        <translation>正在打开结果数据库 %1…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="154"/>
        <source>Results database %1</source>
        <translation>结果数据库 %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="178"/>
        <source>Searching…</source>
        <translation>正在搜索…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="189"/>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="278"/>
        <source>the results database is not open</source>
        <translation>结果数据库未打开</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="220"/>
        <source>%1 rev. %2</source>
        <translation>%1 版本 %2</translation>
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
            <numerusform>%n 台产品：合格 %1，不合格 %2，工位错误 %3 · %4</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="253"/>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="306"/>
        <source>no unit is selected</source>
        <translation>未选择产品</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="258"/>
        <source>Reading unit %1…</source>
        <translation>正在读取产品 %1…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="307"/>
        <source>the unit&apos;s record is still being read</source>
        <translation>仍在读取该产品的记录</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="316"/>
        <source>Export units as CSV</source>
        <translation>将产品导出为 CSV</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="316"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/eol/ResultsBrowser.cpp" line="321"/>
        <source>%n unit(s) written to %1</source>
        <translation>
            <numerusform>已将 %n 台产品写入 %1</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="332"/>
        <source>Save certificate</source>
        <translation>保存检验证书</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="333"/>
        <source>PDF files (*.pdf)</source>
        <translation>PDF 文件 (*.pdf)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="338"/>
        <source>Certificate written to %1</source>
        <translation>检验证书已写入 %1</translation>
    </message>
</context>
<context>
    <name>opentop::ResultsFilterBar</name>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="21"/>
        <source>SQLite file or postgresql://user@host/database</source>
        <translation>SQLite 文件或 postgresql://user@host/database</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="22"/>
        <source>Open</source>
        <translation>打开</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="23"/>
        <source>File…</source>
        <translation>文件…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="30"/>
        <source>any; * and ? as wildcards (SN-10*)</source>
        <translation>全部；可用 * 和 ? 作通配符（SN-10*）</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="32"/>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="34"/>
        <source>any</source>
        <translation>任意</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="36"/>
        <source>Today</source>
        <translation>今天</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="37"/>
        <source>Last 24 hours</source>
        <translation>最近 24 小时</translation>
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
        <translation>任意</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="47"/>
        <source>Search</source>
        <translation>搜索</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="51"/>
        <source>Serial:</source>
        <translation>序列号：</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="52"/>
        <source>Recipe:</source>
        <translation>配方：</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="53"/>
        <source>Station:</source>
        <translation>工位：</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="54"/>
        <source>Period:</source>
        <translation>时间段：</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="55"/>
        <source>Verdict:</source>
        <translation>判定：</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="63"/>
        <source>Database:</source>
        <translation>数据库：</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="105"/>
        <source>Open results database</source>
        <translation>打开结果数据库</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="106"/>
        <source>SQLite databases (*.db *.sqlite);;All files (*)</source>
        <translation>SQLite 数据库 (*.db *.sqlite);;所有文件 (*)</translation>
    </message>
</context>
<context>
    <name>opentop::RetestPolicy</name>
    <message>
        <location filename="../model/eol/RetestPolicy.cpp" line="20"/>
        <source>serial %1 has passed already; this recipe never tests a passed unit again</source>
        <translation>序列号 %1 已合格；此配方不再测试已合格的产品</translation>
    </message>
    <message>
        <location filename="../model/eol/RetestPolicy.cpp" line="23"/>
        <source>serial %1 has passed already; testing it again needs a technician</source>
        <translation>序列号 %1 已合格；重新测试需要技术员许可</translation>
    </message>
    <message>
        <location filename="../model/eol/RetestPolicy.cpp" line="29"/>
        <source>serial %1 was tested %2 times under this recipe, its limit; another attempt needs a technician</source>
        <translation>序列号 %1 在此配方下已测试 %2 次，已达上限；再次测试需要技术员许可</translation>
    </message>
    <message>
        <location filename="../model/eol/RetestPolicy.cpp" line="50"/>
        <source>the results database is not open</source>
        <translation>结果数据库未打开</translation>
    </message>
    <message>
        <location filename="../model/eol/RetestPolicy.cpp" line="58"/>
        <source>earlier tests of %1 were not checked (%2): the result is kept in the station&apos;s spool</source>
        <translation>未能检查 %1 此前的测试记录（%2）：结果保存在工位暂存文件中</translation>
    </message>
</context>
<context>
    <name>opentop::RoleEvaluator</name>
    <message>
        <location filename="../model/profile/RoleEvaluator.cpp" line="102"/>
        <source>%1 = %2 (%3, function %4)</source>
        <translation>%1 = %2（%3，功能 %4）</translation>
    </message>
</context>
<context>
    <name>opentop::RunCommand</name>
    <message>
        <location filename="../cli/RunCommand.cpp" line="50"/>
        <source>Test run: start, stop, direction, running data, hold/free, speed (needs --yes)</source>
        <translation>试运行：启动、停止、方向、运行数据、保持/释放、速度（需要 --yes）</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="55"/>
        <source>Send the command (it moves or stops a motor).</source>
        <translation>发送命令（会使电机运动或停止）。</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="65"/>
        <source>error: usage: %1 (one machine number; a negative speed after --)</source>
        <translation>错误：用法：%1（一个站号；负速度放在 -- 之后）</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="73"/>
        <location filename="../cli/RunCommand.cpp" line="78"/>
        <location filename="../cli/RunCommand.cpp" line="83"/>
        <location filename="../cli/RunCommand.cpp" line="145"/>
        <source>error: %1</source>
        <translation>错误：%1</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="88"/>
        <source>Would send to machine number %1: %2
This moves or stops a motor: add --yes to send it.</source>
        <translation>将向站号 %1 发送：%2
这会使电机运动或停止：加上 --yes 才会发送。</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="109"/>
        <source>note: %1</source>
        <translation>注意：%1</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="137"/>
        <source>Sent to machine number %1: %2</source>
        <translation>已发送到站号 %1：%2</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="139"/>
        <source>Sent to machine number %1, executed also by %2 (communication group): %3</source>
        <translation>已发送到站号 %1，%2 也会执行（通信组）：%3</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="175"/>
        <source>(not read: %1)</source>
        <translation>（未读取：%1）</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="184"/>
        <source>State of machine number %1:</source>
        <translation>站号 %1 的状态：</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="200"/>
        <source>Communication group of %1, read after the command:</source>
        <translation>%1 的通信组，命令后读取：</translation>
    </message>
</context>
<context>
    <name>opentop::RunControl</name>
    <message>
        <location filename="../model/run/RunControl.cpp" line="59"/>
        <source>%1 needs one value, e.g. &quot;%1 %2&quot;</source>
        <translation>%1 需要一个值，例如 &quot;%1 %2&quot;</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="62"/>
        <source>%1 takes no value</source>
        <translation>%1 不接受值</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="70"/>
        <source>select needs a running data number, e.g. &quot;select 2&quot;; got &quot;%1&quot;</source>
        <translation>select 需要运行数据编号，例如 &quot;select 2&quot;；实际为 &quot;%1&quot;</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="80"/>
        <source>unknown run command &quot;%1&quot;; use start, stop, cw, ccw, select N, hold, free, coast or speed VALUE</source>
        <translation>未知运行命令 &quot;%1&quot;；请使用 start、stop、cw、ccw、select N、hold、free、coast 或 speed VALUE</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="127"/>
        <source>%1 drives have no &quot;%2&quot; command; they take: %3</source>
        <translation>%1 驱动器没有 &quot;%2&quot; 命令；可用命令：%3</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="148"/>
        <source>%1 has no selection codes</source>
        <translation>%1 没有选择代码</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="149"/>
        <source>select %1: choose %2–%3 (%4 … %5)</source>
        <translation>select %1：请选择 %2–%3（%4 … %5）</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="186"/>
        <source>cannot read %1 to check that the drive takes motion commands: %2</source>
        <translation>无法读取 %1 以确认驱动器是否接受运动命令：%2</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="206"/>
        <source>machine number %1 is in &quot;%2&quot; (%3); nothing was sent</source>
        <translation>站号 %1 处于“%2”（%3）；未发送任何内容</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="210"/>
        <source>In &quot;%1&quot; the drive takes run, stop, direction and speed selection from its input terminals and refuses motion commands over the bus. To test-run it from here, switch it to &quot;%2&quot;: opentop-cli set %3 %4=%5 (and back to &quot;%1&quot;, =%6, when the machine&apos;s own controls should run it again).</source>
        <translation>在“%1”下，驱动器通过输入端子接收运行、停止、方向和速度选择，并拒绝来自总线的运动命令。要在此处试运行，请将其切换为“%2”：opentop-cli set %3 %4=%5（当需要由设备自身的操作元件控制时，再改回“%1”，=%6）。</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="265"/>
        <source>An alarm is active: the drive refuses to run until it is cleared. See opentop-cli alarms %1, then alarms %1 --reset --yes.</source>
        <translation>有报警发生：报警清除前驱动器拒绝运行。请查看 opentop-cli alarms %1，然后执行 alarms %1 --reset --yes。</translation>
    </message>
</context>
<context>
    <name>opentop::RunLiveState</name>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="26"/>
        <source>The drive now</source>
        <translation>驱动器当前状态</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="49"/>
        <source>State</source>
        <translation>状态</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="51"/>
        <source>Alarm</source>
        <translation>报警</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="58"/>
        <source>Running data</source>
        <translation>运行数据</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="95"/>
        <source>%1:</source>
        <translation>%1：</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="133"/>
        <source>%1 (%2 %3)</source>
        <translation>%1（%2 %3）</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="135"/>
        <source>not reported</source>
        <translation>未报告</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="143"/>
        <location filename="../ui/run/RunLiveState.cpp" line="146"/>
        <location filename="../ui/run/RunLiveState.cpp" line="156"/>
        <source>not read</source>
        <translation>未读取</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="143"/>
        <source>SPno%1</source>
        <translation>SPno%1</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="148"/>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="151"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="153"/>
        <source>active</source>
        <translation>发生中</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="172"/>
        <source>waiting for the first answer…</source>
        <translation>正在等待首次应答…</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="172"/>
        <source>not watched</source>
        <translation>未监视</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="178"/>
        <source>Not live: %1</source>
        <translation>非实时：%1</translation>
    </message>
</context>
<context>
    <name>opentop::RunningData</name>
    <message>
        <location filename="../model/profile/RunningData.cpp" line="76"/>
        <source>SPno%1 slows down from %2 r/min in %3 s: the manual asks for a deceleration time of more than %4 s when slowing down from high speed (about %5 r/min and above).</source>
        <translation>SPno%1 在 %3 s 内从 %2 r/min 减速：手册要求从高速（约 %5 r/min 及以上）减速时，减速时间应大于 %4 s。</translation>
    </message>
    <message>
        <location filename="../model/profile/RunningData.cpp" line="144"/>
        <source>Short deceleration from high speed on %1 (%2 r/min in %3 s): the manual asks for a deceleration time of more than %4 s when slowing down from high speed (about %5 r/min and above).</source>
        <translation>%1 从高速减速过快（%3 s 内从 %2 r/min 减速）：手册要求从高速（约 %5 r/min 及以上）减速时，减速时间应大于 %4 s。</translation>
    </message>
</context>
<context>
    <name>opentop::RunningDataPage</name>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="40"/>
        <location filename="../ui/pages/RunningDataPage.cpp" line="55"/>
        <source>Running data</source>
        <translation>运行数据</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="55"/>
        <source>Speed (r/min)</source>
        <translation>速度 (r/min)</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="55"/>
        <source>Acceleration (s)</source>
        <translation>加速时间 (s)</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="56"/>
        <source>Deceleration (s)</source>
        <translation>减速时间 (s)</translation>
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
        <translation>由输入 M0 = %1、M1 = %2、M2 = %3 或运行数据选择命令选择</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="95"/>
        <source>SS trimmer</source>
        <translation>SS 调节器</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="96"/>
        <source>SPno1 has no acceleration register: the SS trimmer on the drive sets it (0.5–30 s); it is not stored in the drive</source>
        <translation>SPno1 没有加速时间寄存器：由驱动器上的 SS 调节器设定（0.5–30 s）；不保存在驱动器中</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="99"/>
        <source>SD trimmer</source>
        <translation>SD 调节器</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="100"/>
        <source>SPno1 has no deceleration register: the SD trimmer on the drive sets it (0.5 s or 2–30 s); it is not stored in the drive</source>
        <translation>SPno1 没有减速时间寄存器：由驱动器上的 SD 调节器设定（0.5 s 或 2–30 s）；不保存在驱动器中</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="104"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="105"/>
        <source>This drive has no register for this value</source>
        <translation>该驱动器没有此值的寄存器</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="112"/>
        <source>Initialize</source>
        <translation>初始化</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="114"/>
        <source>Reset SPno%1 on the drive to its factory defaults</source>
        <translation>将驱动器上的 SPno%1 恢复为出厂默认值</translation>
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
        <translation>SPno1 按外部调速电位器 VR（CN3）的速度运行，使用 SS/SD 调节器的时间；不保存在驱动器中</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="255"/>
        <source>Allowed speed on this %1: %2 (0 stops the motor)</source>
        <translation>该 %1 允许的速度：%2（0 使电机停止）</translation>
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
        <translation>允许的速度：%1</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="269"/>
        <source>The drive&apos;s variant is not known, so a speed must suit every variant (0 stops the motor): %1</source>
        <translation>驱动器机型未知，因此速度必须适用于所有机型（0 使电机停止）：%1</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="281"/>
        <source>its factory default</source>
        <translation>其出厂默认值</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="303"/>
        <source>The SPno1 speed and times come from the external VR and the SS/SD trimmers; they do not change.</source>
        <translation>SPno1 的速度和时间来自外部 VR 和 SS/SD 调节器；不会改变。</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="310"/>
        <source>Your unwritten edits in this row are discarded.</source>
        <translation>该行中未写入的修改将被放弃。</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="316"/>
        <source>Reset running data SPno%1 of drive %2 to these factory defaults?</source>
        <translation>将驱动器 %2 的运行数据 SPno%1 恢复为以下出厂默认值？</translation>
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
            <numerusform>SPno%1 已初始化；%n 个值无法回读</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="361"/>
        <source>SPno%1 initialized to its factory defaults</source>
        <translation>SPno%1 已恢复为出厂默认值</translation>
    </message>
</context>
<context>
    <name>opentop::ScanCommand</name>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="66"/>
        <source>Find and identify the drives on the bus (machine numbers 1–247)</source>
        <translation>查找并识别总线上的驱动器（站号 1–247）</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="72"/>
        <source>First machine number to ask, 1–247 (default 1).</source>
        <translation>询问的起始站号，1–247（默认 1）。</translation>
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
        <translation>询问的结束站号，1–247（默认 247）。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="75"/>
        <source>Wait per machine number in ms, 10–5000 (default: derived from the baud rate; raise it for slow adapters or gateways).</source>
        <translation>每个站号的等待时间（ms），10–5000（默认：根据波特率得出；适配器或网关较慢时请加大）。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="77"/>
        <source>MS</source>
        <translation>MS</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="79"/>
        <source>Also ask the machine numbers not found in every other line format a drive can be set to (a DC controller at 8E1 on a DBU bus at 8N1): one more pass per format, off by default.</source>
        <translation>对没有找到的站号，也以驱动器可设定的其他每种通信格式询问（8N1 的 DBU 总线上 8E1 的 DC 控制器）：每种格式多扫描一轮，默认关闭。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="94"/>
        <source>error: --%1 must be a number %2–%3, not &quot;%4&quot;</source>
        <translation>错误：--%1 必须是 %2–%3 的数字，而不是 &quot;%4&quot;</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="106"/>
        <source>error: scan takes no arguments; use --from N --to N</source>
        <translation>错误：scan 不接受参数；请使用 --from N --to N</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="115"/>
        <source>error: --from %1 is after --to %2</source>
        <translation>错误：--from %1 大于 --to %2</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="133"/>
        <source>Scanning machine numbers %1–%2 on %3, %4 ms each…</source>
        <translation>正在扫描 %3 上的站号 %1–%2，每个 %4 ms…</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="180"/>
        <source>Interrupted before any machine number was scanned.</source>
        <translation>在扫描任何站号之前已中断。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="182"/>
        <source>Interrupted: machine numbers %1–%2 were scanned (%3 of %4); %5–%6 were not asked.</source>
        <translation>已中断：已扫描站号 %1–%2（%4 个中的 %3 个）；%5–%6 未询问。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="196"/>
        <source>error: the scan stopped at machine number %1: %2</source>
        <translation>错误：扫描在站号 %1 处停止：%2</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="208"/>
        <source>note: remembered for %1: %2; set, run and restore read their communication groups before a write</source>
        <translation>注意：已为 %1 记住：%2；set、run 和 restore 写入前会读取其通信组</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="217"/>
        <source>warning: %1</source>
        <translation>警告：%1</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="219"/>
        <source>note: %1 drive(s) answered only after the %2 ms wait and were asked again; if scans miss drives, give a longer --wait.</source>
        <translation>注意：%1 台驱动器在 %2 ms 等待时间之后才应答，已重新询问；如果扫描漏掉驱动器，请加大 --wait。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="228"/>
        <source>warning: machine number %1 answered, but its identification failed, also when asked again %2 more times; it is not counted as a drive. Add it by hand: name it in a command (it is identified again then, within --timeout; raise it for a slow device), or check its line settings and scan again with a longer --wait.</source>
        <translation>警告：站号 %1 有应答，但识别失败，再询问 %2 次仍然如此；它不计为驱动器。请手动添加：在命令中指定这个站号（届时会在 --timeout 内重新识别；设备应答慢时请加大），或检查它的通信设定后用更长的 --wait 重新扫描。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="237"/>
        <source>No drive answered at machine numbers %1–%2. Check:
  - the wiring, and the A/B polarity (swap A and B if unsure);
  - baud rate and parity: the drives&apos; settings must match %3 (--baud, --parity, --family);
  - the termination (120 Ω at both ends of the bus) and that the drives are powered.</source>
        <translation>站号 %1–%2 上没有驱动器应答。请检查：
  - 接线，以及 A/B 极性（不确定时交换 A 和 B）；
  - 波特率和校验位：驱动器的设定必须与 %3 一致（--baud、--parity、--family）；
  - 终端电阻（总线两端各 120 Ω），以及驱动器是否已通电。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="250"/>
        <source>hint: %1 Retry with the same connection and: %2</source>
        <translation>提示：%1 请使用相同连接并加上以下选项重试：%2</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="263"/>
        <source>Serial line: %1</source>
        <translation>串行线路：%1</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="266"/>
        <source>warning: %1 The scan waits up to %2 ms longer per machine number because of it.</source>
        <translation>警告：%1 因此扫描时每个站号最多会多等待 %2 ms。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="390"/>
        <source>warning: machine number %1 (%2) answers with garbled replies: two drives probably have the same machine number. Check the address switches of the drives on this bus, give each drive its own machine number, power them off and on, and scan again.</source>
        <translation>警告：站号 %1（%2）的应答损坏：可能有两台驱动器使用相同的站号。请检查此总线上各驱动器的地址开关，为每台驱动器设定各自的站号，断电再上电后重新扫描。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="276"/>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="276"/>
        <source>hex</source>
        <translation>十六进制</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="276"/>
        <source>switches</source>
        <translation>开关</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="276"/>
        <source>family</source>
        <translation>系列</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="277"/>
        <source>model</source>
        <translation>型号</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="277"/>
        <source>firmware</source>
        <translation>固件</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="277"/>
        <source>state</source>
        <translation>状态</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="283"/>
        <source>name</source>
        <translation>名称</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="289"/>
        <source>comm. group</source>
        <translation>通信组</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="294"/>
        <source>line format</source>
        <translation>通信格式</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="311"/>
        <source>the port&apos;s</source>
        <translation>端口的</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="371"/>
        <source>1 drive found in %1 s</source>
        <translation>在 %1 s 内找到 1 台驱动器</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="372"/>
        <source>%1 drives found in %2 s</source>
        <translation>在 %2 s 内找到 %1 台驱动器</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="374"/>
        <source>; 1 possible duplicate machine number: %1</source>
        <translation>；1 个可能重复的站号：%1</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="376"/>
        <source>; %1 possible duplicate machine numbers: %2</source>
        <translation>；%1 个可能重复的站号：%2</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="380"/>
        <source>; answered, identification failed: %1 (add by hand)</source>
        <translation>；有应答但识别失败：%1（请手动添加）</translation>
    </message>
</context>
<context>
    <name>opentop::ScanDrives</name>
    <message>
        <location filename="../cli/ScanDrives.cpp" line="43"/>
        <source>%1 — variant unknown</source>
        <translation>%1 — 机型未知</translation>
    </message>
    <message>
        <location filename="../cli/ScanDrives.cpp" line="44"/>
        <source>the drive does not report its variant; give it with --variant %1=VARIANT (%2)</source>
        <translation>驱动器未报告其机型；请用 --variant %1=VARIANT 指定（%2）</translation>
    </message>
</context>
<context>
    <name>opentop::ScanFormats</name>
    <message>
        <location filename="../cli/ScanFormats.cpp" line="44"/>
        <source>Scanning machine numbers %1–%2 at %3 (--try-formats), %4 ms each…</source>
        <translation>以 %3 扫描站号 %1–%2（--try-formats），每个 %4 ms…</translation>
    </message>
    <message>
        <location filename="../cli/ScanFormats.cpp" line="71"/>
        <source>Machine number %1 answered at %2: it is asked at that format from now on (--drive-format %1=%3).</source>
        <translation>站号 %1 以 %2 应答：之后都以该格式询问它（--drive-format %1=%3）。</translation>
    </message>
    <message>
        <location filename="../cli/ScanFormats.cpp" line="99"/>
        <source>hint: %1 If one is on this bus, give its machine number its format with --drive-format ID=BAUD:FORMAT (e.g. 7=9600:8E1), or scan with --try-formats: %2 more passes, %3 more requests, about %4 s more.</source>
        <translation>提示：%1 如果总线上有这种驱动器，请用 --drive-format ID=BAUD:FORMAT（例如 7=9600:8E1）指定它的站号的格式，或用 --try-formats 扫描：多 %2 轮、多 %3 个请求，约多 %4 s。</translation>
    </message>
</context>
<context>
    <name>opentop::ScanProgress</name>
    <message>
        <location filename="../cli/ScanProgress.cpp" line="34"/>
        <source>scanning %1/%2 (%3 %), machine number %4, %5 found</source>
        <translation>正在扫描 %1/%2（%3 %），站号 %4，已找到 %5 台</translation>
    </message>
    <message>
        <location filename="../cli/ScanProgress.cpp" line="49"/>
        <source>scan: %1 % (%2 of %3 machine numbers), %4 found</source>
        <translation>扫描：%1 %（%3 个站号中的 %2 个），已找到 %4 台</translation>
    </message>
    <message>
        <location filename="../cli/ScanProgress.cpp" line="60"/>
        <source>scan: machine number %1 answered, identification failed: retrying (%2 of %3)…</source>
        <translation>扫描：站号 %1 有应答，但识别失败：正在重试（第 %2 次，共 %3 次）…</translation>
    </message>
</context>
<context>
    <name>opentop::SerialEntry</name>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="28"/>
        <source>Scan or type the serial number, then Enter</source>
        <translation>扫描或输入序列号，然后按 Enter</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="29"/>
        <source>Cancel unit (Esc)</source>
        <translation>取消本台测试（Esc）</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="73"/>
        <source>Serial number NOT taken: %1.</source>
        <translation>序列号未被接受：%1。</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="102"/>
        <source>Serial %1 was NOT taken: unit %2 is being tested. Scan it again once its verdict shows.</source>
        <translation>序列号 %1 未被接受：单元 %2 正在检测中。请在其判定结果显示后再扫描一次。</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="104"/>
        <location filename="../ui/eol/SerialEntry.cpp" line="106"/>
        <source>another</source>
        <translation>另一个单元</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="105"/>
        <source>A serial number was NOT taken: %1. Unit %2 is being tested.</source>
        <translation>序列号未被接受：%1。单元 %2 正在检测中。</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="122"/>
        <source>Per-unit value</source>
        <translation>单台数值</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="123"/>
        <source>Drive %1: %2 (%3–%4 %5)</source>
        <translation>驱动器 %1：%2（%3–%4 %5）</translation>
    </message>
</context>
<context>
    <name>opentop::SerialLineFields</name>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="29"/>
        <source>Adapter switches itself</source>
        <translation>适配器自行切换</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="30"/>
        <source>Auto (kernel, else RTS)</source>
        <translation>自动（内核，否则 RTS）</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="31"/>
        <source>Kernel RS-485 mode</source>
        <translation>内核 RS-485 模式</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="32"/>
        <source>RTS from the program</source>
        <translation>由程序控制 RTS</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="34"/>
        <source>Who switches the RS-485 transceiver between sending and receiving. USB–RS-485 adapters do it themselves; on-board RS-485 ports need the driver&apos;s RS-485 mode (kernel) or RTS switched by the program. The status bar says what the driver accepted.</source>
        <translation>由谁切换 RS-485 收发器的发送与接收。USB–RS-485 适配器会自行切换；板载 RS-485 端口需要驱动程序的 RS-485 模式（内核）或由程序切换 RTS。状态栏会显示驱动程序接受的设置。</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="38"/>
        <source>RS-485 d&amp;irection:</source>
        <translation>RS-485 收发方向(&amp;I)：</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="43"/>
        <source>high while sending</source>
        <translation>发送时为高电平</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="44"/>
        <source>low while sending</source>
        <translation>发送时为低电平</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="45"/>
        <source>The RTS level that enables the transceiver&apos;s driver</source>
        <translation>使能收发器发送端的 RTS 电平</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="50"/>
        <source>delay </source>
        <translation>延时 </translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="51"/>
        <source> µs</source>
        <translation> µs</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="52"/>
        <source>default delay</source>
        <translation>默认延时</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="53"/>
        <source>Before and after sending. Default: the driver&apos;s own, or one character time from the program; the kernel rounds up to whole ms.</source>
        <translation>发送前后的延时。默认：使用驱动程序自身的延时，或由程序使用 1 个字符时间；内核会向上取整到整 ms。</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="58"/>
        <source>RTS le&amp;vel:</source>
        <translation>RTS 电平(&amp;V)：</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="62"/>
        <source>&amp;Low latency (no 16 ms hold-back in USB adapters)</source>
        <translation>低延迟（USB 适配器不再缓存 16 ms）(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="65"/>
        <source>Asks the driver to pass received bytes on at once. Many USB–serial chips otherwise hold them for up to 16 ms, which slows scans and polling.</source>
        <translation>要求驱动程序立即转交收到的字节。否则许多 USB 转串口芯片最多会缓存 16 ms，使扫描和轮询变慢。</translation>
    </message>
</context>
<context>
    <name>opentop::SerialLock</name>
    <message>
        <location filename="../model/session/SerialLock.cpp" line="39"/>
        <source>%1 = %2 prohibits configuration over the serial interface: OpenTOP may then no longer be able to change this drive&apos;s settings over the serial line it talks on. To undo it: write %1 = %3 again if the drive still accepts it; while it is not stored, switch the drive off and on; otherwise switch the controller to potentiometer/analog control, connect at 9600 bit/s, 8E1, address 1 and write %1 = %3 there.</source>
        <translation>%1 = %2 会禁止通过串口进行配置：之后 OpenTOP 可能无法再通过当前通信的串行线路修改该驱动器的设定。撤销方法：若驱动器仍接受，再次写入 %1 = %3；尚未保存时，将驱动器断电再上电；否则将控制器切换为电位器/模拟量控制，以 9600 bit/s、8E1、地址 1 连接，并在该连接下写入 %1 = %3。</translation>
    </message>
</context>
<context>
    <name>opentop::SerialRule</name>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="65"/>
        <source>no serial number</source>
        <translation>无序列号</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="67"/>
        <source>a serial number has at most %1 characters; this one has %2</source>
        <translation>序列号最多 %1 个字符；此序列号有 %2 个</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="71"/>
        <source>a serial number may not hold control characters, format characters or line breaks; character %1 is %2</source>
        <translation>序列号不能包含控制字符、格式字符或换行；第 %1 个字符为 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="75"/>
        <source>serial number &quot;%1&quot; begins or ends with white space; a serial number is tested exactly as given</source>
        <translation>序列号 &quot;%1&quot; 的开头或结尾有空白；序列号将完全按输入内容检测</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="85"/>
        <source>serial number &quot;%1&quot; does not match the recipe&apos;s serial pattern %2</source>
        <translation>序列号 &quot;%1&quot; 不符合配方的序列号格式 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="87"/>
        <source>serial number &quot;%1&quot; does not match the recipe&apos;s serial pattern %2 (e.g. %3)</source>
        <translation>序列号 &quot;%1&quot; 不符合配方的序列号格式 %2（例如 %3）</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="104"/>
        <source>&quot;serialPattern&quot; has %1 characters; at most %2 are allowed</source>
        <translation>&quot;serialPattern&quot; 有 %1 个字符；最多允许 %2 个</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="108"/>
        <source>&quot;serialPattern&quot; may not hold control characters, format characters or line breaks (no serial number holds one); character %1 is %2</source>
        <translation>&quot;serialPattern&quot; 不能包含控制字符、格式字符或换行（序列号不会包含这些字符）；第 %1 个字符为 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="115"/>
        <source>&quot;serialPattern&quot; %1 is not a valid regular expression: %2 at character %3</source>
        <translation>&quot;serialPattern&quot; %1 不是有效的正则表达式：第 %3 个字符处 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="121"/>
        <source>&quot;serialPattern&quot; %1 cannot be matched against a whole serial number</source>
        <translation>&quot;serialPattern&quot; %1 无法与整个序列号匹配</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="127"/>
        <source>&quot;serialExample&quot; needs a &quot;serialPattern&quot; that it matches</source>
        <translation>&quot;serialExample&quot; 需要一个与其匹配的 &quot;serialPattern&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="130"/>
        <source>&quot;serialExample&quot;: %1</source>
        <translation>&quot;serialExample&quot;：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="140"/>
        <source>any, at most %1 characters</source>
        <translation>任意，最多 %1 个字符</translation>
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
        <translation>按名称写入参数，经过验证、回读和校验</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="53"/>
        <source>Write registers by address: ADDR=VALUE (repeatable; VALUE,VALUE... with --fc 16).</source>
        <translation>按地址写入寄存器：ADDR=VALUE（可重复；配合 --fc 16 时可写 VALUE,VALUE...）。</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="54"/>
        <source>ADDR=VALUE</source>
        <translation>ADDR=VALUE</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="55"/>
        <source>Function code for --raw writes: 6 (default) or 16.</source>
        <translation>--raw 写入的功能码：6（默认）或 16。</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="55"/>
        <source>FC</source>
        <translation>FC</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="64"/>
        <source>error: usage: set ID NAME=VALUE... (e.g. set 1 spno2.accel=2.5), or set ID --raw ADDR=VALUE</source>
        <translation>错误：用法：set ID NAME=VALUE...（例如 set 1 spno2.accel=2.5），或 set ID --raw ADDR=VALUE</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="76"/>
        <source>error: &quot;%1&quot; is not NAME=VALUE</source>
        <translation>错误：&quot;%1&quot; 不是 NAME=VALUE</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="83"/>
        <location filename="../cli/SetCommand.cpp" line="92"/>
        <location filename="../cli/SetCommand.cpp" line="108"/>
        <source>error: %1</source>
        <translation>错误：%1</translation>
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
        <translation>确认会使电机运动、复位、清除、初始化或保存的命令，以及串口配置锁定的设定。</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="149"/>
        <source>next: %1</source>
        <translation>下一步：%1</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="151"/>
        <source>next: opentop-cli --baud %1 --parity %2 --stop-bits %3 ... (the factory line settings)</source>
        <translation>下一步：opentop-cli --baud %1 --parity %2 --stop-bits %3 ...（出厂通信设定）</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="196"/>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="196"/>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="196"/>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="202"/>
        <source>written, verified</source>
        <translation>已写入，已校验</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="204"/>
        <source>written, not verified: %1</source>
        <translation>已写入，未确认：%1</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="205"/>
        <source>written (command, not readable)</source>
        <translation>已写入（命令，不可读）</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="207"/>
        <source>not confirmed (%1): the drive may or may not hold it; &quot;get&quot; reads it back</source>
        <translation>未确认（%1）：驱动器可能保存了该值，也可能没有；可用 &quot;get&quot; 回读</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="218"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="225"/>
        <source>note: the drive uses %1 from its next power-up on: switch the drive off and on, then connect with the new setting (--baud, --parity)</source>
        <translation>注意：驱动器从下次上电起使用 %1：请将驱动器断电再上电，然后用新设定（--baud、--parity）连接</translation>
    </message>
</context>
<context>
    <name>opentop::SetRaw</name>
    <message>
        <location filename="../cli/SetRaw.cpp" line="30"/>
        <source>error: --fc for raw writes is 6 or 16</source>
        <translation>错误：raw 写入的 --fc 为 6 或 16</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="56"/>
        <source>error: &quot;%1&quot; is not ADDR=VALUE (0x.. or decimal, 0–65535; several values, comma separated, only with --fc 16)</source>
        <translation>错误：&quot;%1&quot; 不是 ADDR=VALUE（0x.. 或十进制，0–65535；多个值以逗号分隔，仅限 --fc 16）</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="73"/>
        <source>error: 0x%1 is not a register the profile knows; add --yes to write it anyway; nothing was written</source>
        <translation>错误：0x%1 不是设备描述中已知的寄存器；如仍要写入请加上 --yes；未写入任何内容</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="83"/>
        <location filename="../cli/SetRaw.cpp" line="128"/>
        <source>error: %1; nothing was written</source>
        <translation>错误：%1；未写入任何内容</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="84"/>
        <source>%1 is a %2 command; add --yes</source>
        <translation>%1 是%2命令；请加上 --yes</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="91"/>
        <source>error: the write covers part of %1; add --yes to write it anyway; nothing was written</source>
        <translation>错误：此次写入只覆盖 %1 的一部分；如仍要写入请加上 --yes；未写入任何内容</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="141"/>
        <source>Address</source>
        <translation>地址</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="141"/>
        <source>Written</source>
        <translation>已写入</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="141"/>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="174"/>
        <source>written</source>
        <translation>已写入</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="176"/>
        <source>written, verified</source>
        <translation>已写入，已校验</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="178"/>
        <source>written, but reads back differently</source>
        <translation>已写入，但回读值不同</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="181"/>
        <source>written (not readable back: %1)</source>
        <translation>已写入（无法回读：%1）</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="193"/>
        <source>Also written to %1 (communication group); not read back: no parameter of the profile</source>
        <translation>同时写入了 %1（通信组）；未回读：不是设备描述中的参数</translation>
    </message>
</context>
<context>
    <name>opentop::SettingsWrite</name>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="29"/>
        <source>%1 is given twice (%2=%3 and %4); give each setting once; nothing written</source>
        <translation>%1 指定了两次（%2=%3 和 %4）；每项设定只能指定一次；未写入任何内容</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="76"/>
        <source>%1 has no parameter &quot;%2&quot;; see &quot;opentop-cli params --family %1&quot;</source>
        <translation>%1 没有参数 &quot;%2&quot;；请参阅 &quot;opentop-cli params --family %1&quot;</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="80"/>
        <source>%1 is read-only</source>
        <translation>%1 为只读</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="83"/>
        <source>%1 is a %2 command; add --yes to send it</source>
        <translation>%1 是%2命令；加上 --yes 才会发送</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="105"/>
        <source>cannot read %1 to check the values; nothing written</source>
        <translation>无法读取 %1 来检查这些值；未写入任何内容</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="157"/>
        <source>Add --yes to set it.</source>
        <translation>加上 --yes 才会设定。</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="229"/>
        <source>interrupted as it was sent</source>
        <translation>发送时已中断</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="231"/>
        <source>not written (interrupted)</source>
        <translation>未写入（已中断）</translation>
    </message>
</context>
<context>
    <name>opentop::ShiftPlan</name>
    <message>
        <location filename="../model/eol/ShiftPlan.cpp" line="30"/>
        <source>&quot;%1&quot; is not a time of day such as 06:00</source>
        <translation>&quot;%1&quot; 不是 06:00 这样的时刻</translation>
    </message>
    <message>
        <location filename="../model/eol/ShiftPlan.cpp" line="35"/>
        <source>shift starts must be in order from the day&apos;s first: %1</source>
        <translation>班次开始时间必须从当天第一个班次起按顺序排列：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/ShiftPlan.cpp" line="42"/>
        <source>no shift start given; e.g. 06:00,14:00,22:00</source>
        <translation>未指定班次开始时间；例如 06:00,14:00,22:00</translation>
    </message>
</context>
<context>
    <name>opentop::ShortcutsDialog</name>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="63"/>
        <source>Main window</source>
        <translation>主窗口</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="36"/>
        <source>Everywhere, dialogs included</source>
        <translation>所有位置，包括对话框</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="37"/>
        <source>STOP ALL (stop every drive on the bus)</source>
        <translation>全部停止（停止总线上的所有驱动器）</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="73"/>
        <source>Keyboard shortcuts</source>
        <translation>键盘快捷键</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="77"/>
        <source>Where</source>
        <translation>位置</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="77"/>
        <source>Command</source>
        <translation>命令</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="77"/>
        <source>Keys</source>
        <translation>按键</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="87"/>
        <source> or </source>
        <translation> 或 </translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="96"/>
        <source>STOP ALL&apos;s keys work in every window of the program, also while a dialog is open.</source>
        <translation>“全部停止”的快捷键在程序的任何窗口中都有效，打开对话框时也有效。</translation>
    </message>
</context>
<context>
    <name>opentop::SimApp</name>
    <message>
        <location filename="../sim/SimApp.cpp" line="77"/>
        <source>opentop-sim: %1@%2 talks %3 (its own line settings): it answers only frames sent in that format</source>
        <translation>opentop-sim：%1@%2 使用 %3（它自己的线路设定）：只应答以该格式发送的帧</translation>
    </message>
    <message>
        <location filename="../sim/SimApp.cpp" line="83"/>
        <source>opentop-sim: warning: %1@%2 cannot use %3 %4 and will not answer</source>
        <translation>opentop-sim：警告：%1@%2 无法使用 %3 %4，将不会应答</translation>
    </message>
    <message>
        <location filename="../sim/SimApp.cpp" line="97"/>
        <source>opentop-sim: --defect %1:%2: no drive with machine number %1 on the bus %3</source>
        <translation>opentop-sim：--defect %1:%2：总线 %3 上没有站号为 %1 的驱动器</translation>
    </message>
    <message>
        <location filename="../sim/SimApp.cpp" line="104"/>
        <source>opentop-sim: --defect %1 (%2@%1): %3</source>
        <translation>opentop-sim：--defect %1（%2@%1）：%3</translation>
    </message>
    <message>
        <location filename="../sim/SimApp.cpp" line="138"/>
        <source>the port is unplugged already</source>
        <translation>端口已拔出</translation>
    </message>
    <message>
        <location filename="../sim/SimApp.cpp" line="140"/>
        <source>unplugged</source>
        <translation>已拔出</translation>
    </message>
    <message>
        <location filename="../sim/SimApp.cpp" line="167"/>
        <source>error: %1</source>
        <translation>错误：%1</translation>
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
        <translation>address 必须为 0..0xFFFF，实际为 &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../sim/SimBackdoor.cpp" line="27"/>
        <source>function must be 3, 4 or 6 (write-only), got &apos;%1&apos;</source>
        <translation>function 必须为 3、4 或 6（只写），实际为 &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../sim/SimBackdoor.cpp" line="40"/>
        <source>value must be -32768..65535, got &apos;%1&apos;</source>
        <translation>value 必须为 -32768..65535，实际为 &apos;%1&apos;</translation>
    </message>
</context>
<context>
    <name>opentop::SimBackend</name>
    <message>
        <location filename="../sim/SimBackend.cpp" line="24"/>
        <source>no simulated bus</source>
        <translation>无模拟总线</translation>
    </message>
    <message>
        <location filename="../sim/SimBackend.cpp" line="47"/>
        <source>the simulated bus is not open</source>
        <translation>模拟总线未打开</translation>
    </message>
    <message>
        <location filename="../sim/SimBackend.cpp" line="53"/>
        <source>the simulated adapter was unplugged</source>
        <translation>模拟适配器已拔出</translation>
    </message>
    <message>
        <location filename="../sim/SimBackend.cpp" line="85"/>
        <source>interrupted while waiting</source>
        <translation>等待时被中断</translation>
    </message>
    <message>
        <location filename="../sim/SimBackend.cpp" line="92"/>
        <source>no reply within %1 ms</source>
        <translation>%1 ms 内无应答</translation>
    </message>
</context>
<context>
    <name>opentop::SimBus</name>
    <message>
        <location filename="../sim/SimBus.cpp" line="38"/>
        <source>unknown device type &apos;%1&apos;; known: %2</source>
        <translation>未知设备类型 &apos;%1&apos;；已知：%2</translation>
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
        <translation>没有站号 %1 的设备</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="118"/>
        <source>baud=%1: this drive talks at %2 bit/s</source>
        <translation>baud=%1：该驱动器的波特率为 %2 bit/s</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="126"/>
        <source>format=%1: this drive offers %2 only</source>
        <translation>format=%1：该驱动器只提供 %2</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="132"/>
        <source>this simulated drive has no line settings of its own</source>
        <translation>该模拟驱动器没有自己的线路设定</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="145"/>
        <source>machine number %1 is outside 1..247</source>
        <translation>站号 %1 超出 1..247</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="146"/>
        <source>machine number %1 is used twice</source>
        <translation>站号 %1 重复使用</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="317"/>
        <source>no device with machine number %1 (bus: %2)</source>
        <translation>没有站号为 %1 的设备（总线：%2）</translation>
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
        <translation>命令：
  help                      本说明
  list                      设备及其状态
  alarm ID CODE             触发报警（DBU）
  warning ID CODE           触发警告，CODE 为 0 时清除（DBU）
  load ID PERCENT           增加负载率（DBU）或电流（DC）
  vr ID RPM                 Ext-VR 速度，供 SPno1 使用（DBU）
  input ID MASK             输入端子：X0..X3（DBU），SQ1 SQ2 DE（DC）
  ignore-stop ID on|off     应答停止命令但继续运行（DBU）
  power-cycle ID            设备断电后重新上电
  get ID ADDR [fc]          显示寄存器（fc 3、4，只写用 6）
  set ID ADDR VALUE [fc]    不经任何检查修改寄存器
  defect ID DEFECT[,...]    为驱动器添加缺陷（参见 --help），例如
                            defect 3 max_speed=800 或 defect 4 alarm=0x07@2s
  defect ID clear           清除驱动器的全部缺陷
  defects                   各驱动器的缺陷
  motor ID [KEY=VALUE ...]  显示或修改直流控制器的电机和负载，
                            例如 motor 7 load=0.05 inertia=3e-4（参见 --motor）
  unplug                    在客户端仍连接时关闭 pty（模拟拔出适配器）
  replug                    在同一符号链接后创建新的 pty
  quit                      停止模拟器</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="66"/>
        <source>bye</source>
        <translation>再见</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="71"/>
        <source>%1 needs the pty server (--pty)</source>
        <translation>%1 需要 pty 服务器（--pty）</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="82"/>
        <source>, defects: %1</source>
        <translation>，缺陷：%1</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="95"/>
        <source>no drive has defects</source>
        <translation>没有驱动器有缺陷</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="101"/>
        <source>unknown command &apos;%1&apos;; type help for the list</source>
        <translation>未知命令 &apos;%1&apos;；输入 help 查看列表</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="105"/>
        <source>usage: %1 ID ...; ID is a machine number on the bus (%2)</source>
        <translation>用法：%1 ID ...；ID 为总线上的站号（%2）</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="111"/>
        <source>&apos;%1&apos; is not a machine number; the bus has %2</source>
        <translation>&apos;%1&apos; 不是站号；总线上有 %2</translation>
    </message>
</context>
<context>
    <name>opentop::SimDefectSpec</name>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="45"/>
        <source>firmware=MAJOR.MINOR (e.g. firmware=1.4), max_speed=N (e.g. max_speed=800), stall, load=+N, load=-N or load=xF (e.g. load=+40, load=x1.5), alarm=CODE@TIME (e.g. alarm=0x07@1500ms, alarm=overload@2s; DC: alarm=stall@1s), nostick=PARAM, nostore=PARAM (a parameter name or register address, e.g. nostick=spno2.speed, nostore=0x0081), turnaround=MS (e.g. turnaround=14), clear</source>
        <translation>firmware=MAJOR.MINOR（例如 firmware=1.4），max_speed=N（例如 max_speed=800），stall，load=+N、load=-N 或 load=xF（例如 load=+40、load=x1.5），alarm=CODE@TIME（例如 alarm=0x07@1500ms、alarm=overload@2s；DC：alarm=stall@1s），nostick=PARAM，nostore=PARAM（参数名或寄存器地址，例如 nostick=spno2.speed、nostore=0x0081），turnaround=MS（例如 turnaround=14），clear</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="123"/>
        <source>unknown defect &quot;%1&quot;; allowed: %2</source>
        <translation>未知缺陷 &quot;%1&quot;；允许：%2</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="126"/>
        <source>&quot;%1&quot; needs a value: %2=...</source>
        <translation>&quot;%1&quot; 需要一个值：%2=...</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="128"/>
        <source>&quot;%1&quot; takes no value; write %2</source>
        <translation>&quot;%1&quot; 不接受值；请写成 %2</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="141"/>
        <source>firmware=%1: write MAJOR.MINOR with each 0..255, e.g. firmware=1.4</source>
        <translation>firmware=%1：请写成 MAJOR.MINOR，各为 0..255，例如 firmware=1.4</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="148"/>
        <source>max_speed=%1: write a whole number 0..%2, e.g. max_speed=800</source>
        <translation>max_speed=%1：请写成 0..%2 的整数，例如 max_speed=800</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="158"/>
        <source>load=%1: a factor is x0.1..x10, e.g. load=x1.5</source>
        <translation>load=%1：倍数为 x0.1..x10，例如 load=x1.5</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="163"/>
        <source>load=%1: an offset is -200..+200, e.g. load=+40</source>
        <translation>load=%1：偏移量为 -200..+200，例如 load=+40</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="166"/>
        <source>load=%1: write load=+N, load=-N (an offset) or load=xF (a factor), e.g. load=+40 or load=x1.5</source>
        <translation>load=%1：请写成 load=+N、load=-N（偏移量）或 load=xF（倍数），例如 load=+40 或 load=x1.5</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="175"/>
        <source>alarm=%1: write alarm=CODE@TIME, e.g. alarm=0x07@1500ms or alarm=overload@2s</source>
        <translation>alarm=%1：请写成 alarm=CODE@TIME，例如 alarm=0x07@1500ms 或 alarm=overload@2s</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="180"/>
        <source>alarm=%1: the time after the start is 0..3600 s, written 1500ms, 1.5s or 1500 (ms)</source>
        <translation>alarm=%1：启动后的时间为 0..3600 s，写成 1500ms、1.5s 或 1500（ms）</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="189"/>
        <source>turnaround=%1: write the answer delay in ms, 0..1000, e.g. turnaround=14</source>
        <translation>turnaround=%1：请写出应答延时（ms），范围 0..1000，例如 turnaround=14</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="194"/>
        <source>%1=%2: name a parameter (e.g. spno2.speed) or a register address (e.g. 0x1102)</source>
        <translation>%1=%2：请指定参数名（例如 spno2.speed）或寄存器地址（例如 0x1102）</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="210"/>
        <source>no defect given; allowed: %1</source>
        <translation>未指定缺陷；允许：%1</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="216"/>
        <source>empty item in &quot;%1&quot;</source>
        <translation>&quot;%1&quot; 中有空项</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="234"/>
        <source>&quot;%1&quot;: write ID:DEFECT[,DEFECT...] with ID the machine number 1..247, e.g. 3:firmware=1.4 or 5:max_speed=800,load=+40</source>
        <translation>&quot;%1&quot;：请写成 ID:DEFECT[,DEFECT...]，ID 为站号 1..247，例如 3:firmware=1.4 或 5:max_speed=800,load=+40</translation>
    </message>
</context>
<context>
    <name>opentop::SimDefects</name>
    <message>
        <location filename="../sim/SimDefects.cpp" line="71"/>
        <source>a %1 reports no firmware version</source>
        <translation>%1 不报告固件版本</translation>
    </message>
    <message>
        <location filename="../sim/SimDefects.cpp" line="83"/>
        <source>alarm=%1: a %2 has no alarm codes; its protection is the stall stop: write alarm=stall@TIME</source>
        <translation>alarm=%1：%2 没有报警代码；其保护功能为堵转停止：请写成 alarm=stall@TIME</translation>
    </message>
    <message>
        <location filename="../sim/SimDefects.cpp" line="99"/>
        <source>alarm=%1: not an alarm of a %2; allowed: %3</source>
        <translation>alarm=%1：不是 %2 的报警；允许：%3</translation>
    </message>
    <message>
        <location filename="../sim/SimDefects.cpp" line="110"/>
        <source>%1=%2: no writable parameter of a %3 has this name or address; e.g. %4</source>
        <translation>%1=%2：%3 没有该名称或地址的可写参数；例如 %4</translation>
    </message>
</context>
<context>
    <name>opentop::SimDevice</name>
    <message>
        <location filename="../sim/SimDevice.cpp" line="248"/>
        <source>missing command</source>
        <translation>缺少命令</translation>
    </message>
    <message>
        <location filename="../sim/SimDevice.cpp" line="257"/>
        <source>slave %1 power cycled</source>
        <translation>从站 %1 已重新上电</translation>
    </message>
    <message>
        <location filename="../sim/SimDevice.cpp" line="299"/>
        <source>usage: defect ID DEFECT[,DEFECT...] or defect ID clear; DEFECT: %1</source>
        <translation>用法：defect ID DEFECT[,DEFECT...] 或 defect ID clear；DEFECT：%1</translation>
    </message>
    <message>
        <location filename="../sim/SimDevice.cpp" line="306"/>
        <source>slave %1 defects: %2</source>
        <translation>从站 %1 的缺陷：%2</translation>
    </message>
    <message>
        <location filename="../sim/SimDevice.cpp" line="308"/>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <location filename="../sim/SimDevice.cpp" line="313"/>
        <source>&apos;%1&apos; is not supported by a %2 device</source>
        <translation>%2 设备不支持 &apos;%1&apos;</translation>
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
        <translation>用法：opentop-sim --devices SPEC [选项]
在伪终端上或作为 Modbus TCP 网关模拟 Modbus RTU 驱动器。

  --devices SPEC     设备和站号，例如 dbu200@1,dbu400@150,dcpid@7
                     驱动器自己的线路设定写在大括号内，例如
                     dcpid@7{format=8E1,baud=19200}：只接收以该格式发送的
                     帧（pty 会传递客户端的速率和校验位）
  --pty [PATH]       在 pty 上提供服务（默认）；PATH：同时创建该符号链接
  --tcp HOST:PORT    提供 Modbus TCP 服务（HOST 默认为 127.0.0.1，PORT 0：任意）
  --baud N           用于线路时序和设备设定的线路速率（19200）；驱动器只接收
                     自己速率和校验位的帧
  --parity N|E|O     线路校验位（N）：没有自己设定的驱动器
                     设为 --baud 和 --parity
  --wire-timing      按 --baud 下真实线路的时序延迟应答
  --turnaround MS    使用 --wire-timing 时设备的转换时间（2）
  --half-duplex      配合 --wire-timing：请求与线路上的应答重叠时
                     两者都会损坏，距应答 3.5 个字符以内的请求会丢失
  --faults LIST      例如 drop=0.02,crc=0.01,late=0.01,busy=0.01,late_ms=1000
  --seed N           故障注入的随机种子（1）
  --defect ID:LIST   驱动器 ID 的缺陷（可重复），LIST 取值：
                       firmware=MAJOR.MINOR  识别时报告该版本
                       max_speed=N           电机在 N 处饱和（DBU r/min，
                                             DC 换相次数/s），负载高
                       stall                 电机不转，负载高
                       load=+N|-N|xF         负载率（DC：电流 %）偏移或缩放
                       alarm=CODE@TIME       运行 TIME 后报警，例如
                                             0x07@1500ms、overload@2s（DC：stall@1s）
                       nostick=PARAM         写入被应答，但旧值保持不变
                       nostore=PARAM         下次重新上电时值丢失
                     例如 --defect 3:firmware=1.4 --defect 5:max_speed=800,load=+40
  --motor LIST       直流控制器的电机和负载，例如 inertia=2e-4,load=0.05；
                     supply（V）、resistance（ohm）、no_load（满占空比时的 1/s）、
                     commutations（每转换相次数）、inertia（kg m2）、viscous
                     （N m s/rad）、coulomb（N m）、load（N m）、gate（ms）、tacho（V s）
  --quiet            不在 stderr 上输出报文跟踪
  --lang CODE        消息的语言：en, zh_TW, zh_CN, ko, ja
  --help             本说明
  --version          程序版本

输出 &quot;pty: PATH&quot;（以及 &quot;tcp: HOST:PORT&quot;），然后输出 &quot;ready&quot;。从 stdin 读取控制台命令
（输入 help）。收到 SIGINT、SIGTERM 或 quit 时停止。
</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="92"/>
        <source>--lang needs a language code such as ko</source>
        <translation>--lang 需要语言代码，例如 ko</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="95"/>
        <source>--devices needs a device list such as dbu200@1,dcpid@7</source>
        <translation>--devices 需要设备列表，例如 dbu200@1,dcpid@7</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="104"/>
        <source>--tcp needs HOST:PORT, e.g. 127.0.0.1:5020</source>
        <translation>--tcp 需要 HOST:PORT，例如 127.0.0.1:5020</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="110"/>
        <source>--tcp needs HOST:PORT with PORT 0..65535, got &apos;%1&apos;</source>
        <translation>--tcp 需要 HOST:PORT，PORT 为 0..65535，实际为 &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="122"/>
        <source>--baud must be one of %1, got &apos;%2&apos;</source>
        <translation>--baud 必须是 %1 之一，实际为 &apos;%2&apos;</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="129"/>
        <source>--parity must be N, E or O, got &apos;%1&apos;</source>
        <translation>--parity 必须为 N、E 或 O，实际为 &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="139"/>
        <source>--turnaround must be 0..1000 ms, got &apos;%1&apos;</source>
        <translation>--turnaround 必须为 0..1000 ms，实际为 &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="143"/>
        <source>--faults needs a list such as drop=0.02,crc=0.01</source>
        <translation>--faults 需要列表，例如 drop=0.02,crc=0.01</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="147"/>
        <source>--faults: %1</source>
        <translation>--faults：%1</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="153"/>
        <source>--seed must be a whole number 0..4294967295, got &apos;%1&apos;</source>
        <translation>--seed 必须是 0..4294967295 的整数，实际为 &apos;%1&apos;</translation>
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
        <translation>--motor 需要列表，例如 inertia=2e-4,load=0.05</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="172"/>
        <source>--motor: %1</source>
        <translation>--motor：%1</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="177"/>
        <source>unknown argument &apos;%1&apos;; options: --devices, --pty, --tcp, --baud, --parity, --wire-timing, --half-duplex, --turnaround, --faults, --seed, --defect, --motor, --quiet, --help, --version</source>
        <translation>未知参数 &apos;%1&apos;；选项：--devices, --pty, --tcp, --baud, --parity, --wire-timing, --half-duplex, --turnaround, --faults, --seed, --defect, --motor, --quiet, --help, --version</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="186"/>
        <source>--devices SPEC is required, e.g. --devices dbu200@1,dcpid@7</source>
        <translation>必须指定 --devices SPEC，例如 --devices dbu200@1,dcpid@7</translation>
    </message>
</context>
<context>
    <name>opentop::SpeedDisplay</name>
    <message>
        <location filename="../model/profile/SpeedDisplay.cpp" line="90"/>
        <source>speed display settings not known: %1</source>
        <translation>速度显示设定未知：%1</translation>
    </message>
    <message>
        <location filename="../model/profile/SpeedDisplay.cpp" line="92"/>
        <source>speed display unit code %1 is unknown (0–3)</source>
        <translation>速度显示单位代码 %1 未知（0–3）</translation>
    </message>
    <message>
        <location filename="../model/profile/SpeedDisplay.cpp" line="94"/>
        <source>speed display ratios must be positive (reduction %1, increase %2)</source>
        <translation>速度显示比必须为正数（减速比 %1，增速比 %2）</translation>
    </message>
    <message>
        <location filename="../model/profile/SpeedDisplay.cpp" line="98"/>
        <source>speed display decimals %1 outside 0–3</source>
        <translation>速度显示小数位数 %1 超出 0–3</translation>
    </message>
</context>
<context>
    <name>opentop::SpeedUnitsPage</name>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="36"/>
        <source>Speed display</source>
        <translation>速度显示</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="52"/>
        <source>Unit shown</source>
        <translation>显示单位</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="53"/>
        <source>&amp;Unit:</source>
        <translation>单位(&amp;U)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="54"/>
        <source>Reduction r&amp;atio:</source>
        <translation>减速比(&amp;A)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="55"/>
        <source>&amp;Increasing ratio:</source>
        <translation>增速比(&amp;I)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="60"/>
        <source>Linear speed</source>
        <translation>线速度</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="61"/>
        <source>Roller diameter for &amp;yd/min:</source>
        <translation>yd/min 用滚筒直径(&amp;Y)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="62"/>
        <source>Roller diameter for &amp;m/min:</source>
        <translation>m/min 用滚筒直径(&amp;M)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="65"/>
        <source>Time for a distance</source>
        <translation>移动距离所需时间</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="66"/>
        <source>Roller &amp;diameter:</source>
        <translation>滚筒直径(&amp;D)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="67"/>
        <source>Dis&amp;tance:</source>
        <translation>距离(&amp;T)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="68"/>
        <source>Distance u&amp;nit:</source>
        <translation>距离单位(&amp;N)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="69"/>
        <source>Time &amp;format (min = m:ss):</source>
        <translation>时间格式（min = m:ss）(&amp;F)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="72"/>
        <source>Display</source>
        <translation>显示</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="73"/>
        <source>D&amp;ecimals (0–3):</source>
        <translation>小数位数（0–3）(&amp;E)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="74"/>
        <source>U&amp;pdate time:</source>
        <translation>更新时间(&amp;P)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="78"/>
        <source>Display corrections (motor r/min)</source>
        <translation>显示修正（电机 r/min）</translation>
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
        <translation>驱动器显示预览</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="88"/>
        <source> r/min</source>
        <translation> r/min</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="89"/>
        <source>Motor speed for the preview</source>
        <translation>用于预览的电机速度</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="90"/>
        <source>Motor &amp;speed:</source>
        <translation>电机速度(&amp;S)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="93"/>
        <source>Forward</source>
        <translation>正转</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="94"/>
        <source>Reverse (shown with “-”)</source>
        <translation>反转（显示为“-”）</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="95"/>
        <source>Dire&amp;ction:</source>
        <translation>方向(&amp;C)：</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="110"/>
        <source>Drive shows:</source>
        <translation>驱动器显示：</translation>
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
        <translation>驱动器显示 %1 %2</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="259"/>
        <source>Section ro-%1: correction %2 r/min, shaft speed %3 r/min.</source>
        <translation>区段 ro-%1：修正 %2 r/min，轴转速 %3 r/min。</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="264"/>
        <source>%1 has more digits than the drive&apos;s %2-digit display can show.</source>
        <translation>%1 的位数超过驱动器 %2 位显示屏可显示的位数。</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="268"/>
        <source>Computed %1 %2; the %3-digit display drops the decimals that do not fit.</source>
        <translation>计算值 %1 %2；%3 位显示屏会舍去放不下的小数位。</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="275"/>
        <source>Includes edits not yet written.</source>
        <translation>包含尚未写入的修改。</translation>
    </message>
</context>
<context>
    <name>opentop::SpnoSelector</name>
    <message>
        <location filename="../ui/run/SpnoSelector.cpp" line="29"/>
        <source>The running data that Select running data sends; &quot;The drive now&quot; shows the running data the drive runs</source>
        <translation>“选择运行数据”发送的运行数据；“驱动器当前状态”显示驱动器正在运行的运行数据</translation>
    </message>
    <message>
        <location filename="../ui/run/SpnoSelector.cpp" line="70"/>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <location filename="../ui/run/SpnoSelector.cpp" line="84"/>
        <source>The running data that Select running data sends. The drive reported SPno%1 at %2; &quot;The drive now&quot; shows what it runs now.</source>
        <translation>“选择运行数据”发送的运行数据。驱动器在 %2 报告为 SPno%1；“驱动器当前状态”显示其当前运行的数据。</translation>
    </message>
</context>
<context>
    <name>opentop::StaleLook</name>
    <message>
        <location filename="../ui/widgets/StaleLook.cpp" line="52"/>
        <source>not read yet</source>
        <translation>尚未读取</translation>
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
        <translation>%1 的通信组</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="182"/>
        <source>It runs with running data SPno%1</source>
        <translation>以运行数据 SPno%1 运行</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="184"/>
        <source> at %1</source>
        <translation> （%1）</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="187"/>
        <source>, direction %1 (the direction command sent since)</source>
        <translation>，方向 %1（此后已发送方向命令）</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="188"/>
        <source>, direction %1</source>
        <translation>，方向 %1</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="191"/>
        <source>Which running data it runs with could not be read.</source>
        <translation>无法读取以哪组运行数据运行。</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="194"/>
        <source>Warning: %1</source>
        <translation>警告：%1</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="196"/>
        <source>The start also reaches machine number(s) %1: %2.</source>
        <translation>启动也会作用于站号 %1：%2。</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="202"/>
        <source>Not read: %1.</source>
        <translation>未读取：%1。</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="219"/>
        <source>This starts the motor of machine number %1.</source>
        <translation>这将启动站号 %1 的电机。</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="221"/>
        <source>This sets the speed command of machine number %1 to %2: its motor runs.</source>
        <translation>这将把站号 %1 的速度命令设定为 %2：其电机将运行。</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="225"/>
        <source>Make sure that nobody is near the machine and that it may move. STOP ALL stops every drive at any time.</source>
        <translation>请确认设备附近无人且设备可以运动。“全部停止”可随时停止所有驱动器。</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="228"/>
        <source>You are asked once per drive while the program runs.</source>
        <translation>程序运行期间，每台驱动器只询问一次。</translation>
    </message>
</context>
<context>
    <name>opentop::StationAccess</name>
    <message>
        <location filename="../model/access/StationAccess.cpp" line="74"/>
        <location filename="../model/access/StationAccess.cpp" line="127"/>
        <source>the results database is not open</source>
        <translation>结果数据库未打开</translation>
    </message>
    <message>
        <location filename="../model/access/StationAccess.cpp" line="105"/>
        <source>the results database is not open, so nobody can be identified</source>
        <translation>结果数据库未打开，因此无法确认任何人的身份</translation>
    </message>
    <message>
        <location filename="../model/access/StationAccess.cpp" line="160"/>
        <source>the station&apos;s users are being read from the results database</source>
        <translation>正在从结果数据库读取工位用户</translation>
    </message>
    <message>
        <location filename="../model/access/StationAccess.cpp" line="161"/>
        <source>the station&apos;s users cannot be read: %1</source>
        <translation>无法读取工位用户：%1</translation>
    </message>
    <message>
        <location filename="../model/access/StationAccess.cpp" line="166"/>
        <source>nobody is logged in: log in with your user name and password (or badge)</source>
        <translation>无人登录：请用用户名和密码（或工牌）登录</translation>
    </message>
    <message>
        <location filename="../model/access/StationAccess.cpp" line="170"/>
        <source>the recipe&apos;s approval is being read from the results database</source>
        <translation>正在从结果数据库读取配方批准</translation>
    </message>
</context>
<context>
    <name>opentop::StationActions</name>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="24"/>
        <source>Reset alarm and test again</source>
        <translation>复位报警并重新测试</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="25"/>
        <source>Technician: test again…</source>
        <translation>技术员：重新测试…</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="50"/>
        <source>A technician may allow unit %1 to be tested again.</source>
        <translation>技术员可允许单元 %1 重新测试。</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="57"/>
        <source>Resetting the alarm of machine number %1…</source>
        <translation>正在复位站号 %1 的报警…</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="66"/>
        <source>The alarm is not cleared; nothing was started:
%1</source>
        <translation>报警未清除；未开始任何测试：
%1</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="76"/>
        <source>reset the alarm</source>
        <translation>报警复位</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="82"/>
        <source>serial %1</source>
        <translation>序列号 %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="91"/>
        <source>test serial %1 again</source>
        <translation>重新测试序列号 %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="105"/>
        <source>An alarm was active on machine number %1 before the test: nothing was written. Reset it (the drive&apos;s own reset; one that needs a power cycle says so) and the unit is tested again.</source>
        <translation>测试前站号 %1 上已有报警：未写入任何内容。请复位报警（使用驱动器自身的复位功能；需要重新上电的报警会另行提示），产品随即重新测试。</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="134"/>
        <source>(no name)</source>
        <translation>（未填姓名）</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="136"/>
        <source>Test again</source>
        <translation>重新测试</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="137"/>
        <source>%1

Test unit %2 again? It is recorded as allowed by %3.</source>
        <translation>%1

要重新测试产品 %2 吗？将记录为由 %3 许可。</translation>
    </message>
</context>
<context>
    <name>opentop::StationAlarmReset</name>
    <message>
        <location filename="../model/eol/StationAlarmReset.cpp" line="56"/>
        <source>machine number %1: not connected to a bus</source>
        <translation>站号 %1：未连接总线</translation>
    </message>
    <message>
        <location filename="../model/eol/StationAlarmReset.cpp" line="57"/>
        <source>machine number %1 is not a position of the recipe</source>
        <translation>站号 %1 不是配方中的位置</translation>
    </message>
    <message>
        <location filename="../model/eol/StationAlarmReset.cpp" line="65"/>
        <source>machine number %1: %2 drives have no alarm reset command; switch the drive off and on</source>
        <translation>站号 %1：%2 驱动器没有报警复位命令；请将驱动器断电再上电</translation>
    </message>
    <message>
        <location filename="../model/eol/StationAlarmReset.cpp" line="75"/>
        <source>machine number %1: %2</source>
        <translation>站号 %1：%2</translation>
    </message>
</context>
<context>
    <name>opentop::StationFigures</name>
    <message>
        <location filename="../ui/eol/StationFigures.cpp" line="27"/>
        <source>This shift: no figures yet (%1)</source>
        <translation>本班次：暂无数据（%1）</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationFigures.cpp" line="28"/>
        <source>results database not read</source>
        <translation>尚未读取结果数据库</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationFigures.cpp" line="31"/>
        <source>This shift: tested %1 · passed %2 · failed %3 · station errors %4 · %5</source>
        <translation>本班次：已测 %1 · 合格 %2 · 不合格 %3 · 工位错误 %4 · %5</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationFigures.cpp" line="39"/>
        <source>This station, this recipe version, since %1 (read %2). The same figures: %3</source>
        <translation>本工位、此配方版本，自 %1 起（读取于 %2）。用命令查看相同数据：%3</translation>
    </message>
</context>
<context>
    <name>opentop::StationLogin</name>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="38"/>
        <source>operator</source>
        <translation>操作员</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="40"/>
        <source>Operator:</source>
        <translation>操作员:</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="44"/>
        <source>user name</source>
        <translation>用户名</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="49"/>
        <source>password</source>
        <translation>密码</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="51"/>
        <source>Log in</source>
        <translation>登录</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="52"/>
        <source>Log in:</source>
        <translation>登录:</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="57"/>
        <source>Log out</source>
        <translation>注销</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="104"/>
        <source>Not logged in: %1</source>
        <translation>未登录：%1</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="125"/>
        <source>Logged in: &lt;b&gt;%1&lt;/b&gt; (%2)</source>
        <translation>已登录：&lt;b&gt;%1&lt;/b&gt;（%2）</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="131"/>
        <source>No users set up: anyone can run, edit and leave; set up users with opentop-cli eol user add</source>
        <translation>尚未设置用户：任何人都可运行、编辑和退出；请用 opentop-cli eol user add 设置用户</translation>
    </message>
</context>
<context>
    <name>opentop::StationNotice</name>
    <message numerus="yes">
        <location filename="../ui/eol/StationNotice.cpp" line="31"/>
        <source>%n result(s) kept on this station, not yet in the results database: %1. They are sent by themselves, in order, when it answers.</source>
        <translation>
            <numerusform>本工作站保存了 %n 条结果，尚未存入结果数据库：%1。数据库响应后会按顺序自动发送。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/eol/StationNotice.cpp" line="35"/>
        <source>it does not answer</source>
        <translation>数据库没有响应</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationNotice.cpp" line="38"/>
        <source>Unit %1 (begun %2) was not finished: the station stopped during its test. It is recorded as interrupted; test it again.</source>
        <translation>单元 %1（开始于 %2）未完成：工作站在检测中停止。已记录为“中断”，请重新检测。</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationNotice.cpp" line="44"/>
        <source>Making the recipe&apos;s drives safe: reading each, stopping one left running, giving control back to their inputs…</source>
        <translation>正在使配方的驱动器进入安全状态：逐一读取、停止仍在运转者、将控制权交还其输入端子…</translation>
    </message>
</context>
<context>
    <name>opentop::StationRecipe</name>
    <message>
        <location filename="../model/station/StationRecipe.cpp" line="68"/>
        <source>this recipe takes per-unit values from a CSV file: open it first</source>
        <translation>该配方从 CSV 文件获取单台数值：请先打开该文件</translation>
    </message>
</context>
<context>
    <name>opentop::StationResults</name>
    <message>
        <location filename="../model/station/StationResults.cpp" line="63"/>
        <source>opening the results database</source>
        <translation>正在打开结果数据库</translation>
    </message>
    <message>
        <location filename="../model/station/StationResults.cpp" line="65"/>
        <source>NOT REACHABLE (%1); trying again by itself</source>
        <translation>无法连接（%1）；正在自动重试</translation>
    </message>
    <message>
        <location filename="../model/station/StationResults.cpp" line="66"/>
        <source>no results database</source>
        <translation>无结果数据库</translation>
    </message>
    <message>
        <location filename="../model/station/StationResults.cpp" line="72"/>
        <source>the result of unit %1 (%2) is not in the results database yet: nothing is tested until it is. The station tries again by itself (%3)</source>
        <translation>产品 %1 的结果（%2）尚未写入结果数据库：写入之前不进行任何测试。工作站会自动重试（%3）</translation>
    </message>
    <message>
        <location filename="../model/station/StationResults.cpp" line="77"/>
        <source>the results database is being opened; try again in a moment</source>
        <translation>正在打开结果数据库；请稍后再试</translation>
    </message>
    <message>
        <location filename="../model/station/StationResults.cpp" line="79"/>
        <source>the results database is not open; nothing is tested unless it is recorded</source>
        <translation>结果数据库未打开；不记录就不进行测试</translation>
    </message>
    <message>
        <location filename="../model/station/StationResults.cpp" line="80"/>
        <source>the results database cannot be reached (%1); nothing is tested unless it is recorded. The station tries again by itself.</source>
        <translation>无法连接结果数据库（%1）；不记录就不进行测试。工作站会自动重试。</translation>
    </message>
</context>
<context>
    <name>opentop::StationSafeState</name>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="44"/>
        <source>%1: no answer (%2); not checked</source>
        <translation>%1：没有响应（%2）；未检查</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="49"/>
        <source>%1 was RUNNING (%2)</source>
        <translation>%1 原本在运转（%2）</translation>
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
        <translation>；控制权已交还其输入端子（I/O 优先）</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="99"/>
        <source>drive %1</source>
        <translation>驱动器 %1</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="100"/>
        <source>drive %1 (%2)</source>
        <translation>驱动器 %1（%2）</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="104"/>
        <source>the recipe&apos;s family %1 is not known</source>
        <translation>配方的机型系列 %1 未知</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="148"/>
        <source>whether its motor runs cannot be read</source>
        <translation>无法读取电机是否在运转</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="159"/>
        <source>it runs from its input terminals (I/O priority): not the station&apos;s to stop; stop it at the machine</source>
        <translation>它由输入端子控制运转（I/O 优先）：不由工作站停止；请在机台上停止</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="184"/>
        <source>the stop was refused: %1</source>
        <translation>停止命令被拒绝：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="198"/>
        <source>NOT CONFIRMED STOPPED: %1</source>
        <translation>未确认停止：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="240"/>
        <source>control could not be given back to its inputs: %1</source>
        <translation>无法将控制权交还其输入端子：%1</translation>
    </message>
</context>
<context>
    <name>opentop::StationYield</name>
    <message>
        <location filename="../model/eol/StationYield.cpp" line="48"/>
        <source>the results database is not open</source>
        <translation>结果数据库未打开</translation>
    </message>
</context>
<context>
    <name>opentop::StatusLight</name>
    <message>
        <location filename="../ui/widgets/StatusLight.cpp" line="30"/>
        <source>Status not known yet</source>
        <translation>状态未知</translation>
    </message>
    <message>
        <location filename="../ui/widgets/StatusLight.cpp" line="44"/>
        <source>Status light %1: %2</source>
        <translation>状态灯 %1：%2</translation>
    </message>
    <message>
        <location filename="../ui/widgets/StatusLight.cpp" line="48"/>
        <source>The drive&apos;s manual: %1</source>
        <translation>驱动器手册：%1</translation>
    </message>
</context>
<context>
    <name>opentop::StepMeasure</name>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="85"/>
        <source>%1: the drive stopped answering: %2</source>
        <translation>%1：驱动器停止应答：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="93"/>
        <source>%1: the drive raised an alarm while running</source>
        <translation>%1：驱动器在运行中发生报警</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="113"/>
        <source>%1: %2 %3</source>
        <translation>%1：%2 %3</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="132"/>
        <source>%1: the drive has no speed to wait for</source>
        <translation>%1：驱动器没有可等待的速度</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="155"/>
        <source>time to reach speed</source>
        <translation>到达速度时间</translation>
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
        <translation>%1：未在 %5 s 内达到 %2 %3 ±%4 %3（最后读取 %6 %3）</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="170"/>
        <source>its target</source>
        <translation>其目标值</translation>
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
        <translation>%1：驱动器未报告报警</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="225"/>
        <source>alarms raised</source>
        <translation>发生的报警</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="227"/>
        <source>%1: the drive has an alarm</source>
        <translation>%1：驱动器有报警</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="234"/>
        <source>%1: nothing to read</source>
        <translation>%1：无可读取内容</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="248"/>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="251"/>
        <source>%1: %2 reads &quot;%3&quot;, expected &quot;%4&quot;</source>
        <translation>%1：%2 读取为 &quot;%3&quot;，预期为 &quot;%4&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="259"/>
        <source>%1: %2 reads %3 %4, %5</source>
        <translation>%1：%2 读取为 %3 %4，%5</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="299"/>
        <source>time to stop</source>
        <translation>停止时间</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="303"/>
        <source>%1: stopped after %2 s, allowed at most %3 s</source>
        <translation>%1：%2 s 后停止，最多允许 %3 s</translation>
    </message>
</context>
<context>
    <name>opentop::StepMetrics</name>
    <message>
        <location filename="../model/tuning/StepMetrics.cpp" line="18"/>
        <source>the step has no height (from = to)</source>
        <translation>阶跃幅度为零（from = to）</translation>
    </message>
    <message>
        <location filename="../model/tuning/StepMetrics.cpp" line="19"/>
        <source>too few samples after the step (%1)</source>
        <translation>阶跃后的采样点过少（%1）</translation>
    </message>
</context>
<context>
    <name>opentop::StepTest</name>
    <message>
        <location filename="../model/tuning/StepTest.cpp" line="39"/>
        <source>a step test runs forward from one speed to another: from and to must differ and be 0 or more</source>
        <translation>阶跃测试以正转从一个速度变到另一个速度：起始速度和目标速度必须不同，且不小于 0</translation>
    </message>
    <message>
        <location filename="../model/tuning/StepTest.cpp" line="47"/>
        <source>%1 %2 is beyond the test&apos;s speed limit %3 %2</source>
        <translation>%1 %2 超出测试的速度限值 %3 %2</translation>
    </message>
    <message>
        <location filename="../model/tuning/StepTest.cpp" line="55"/>
        <source>Running to %1 %2</source>
        <translation>正在运行至 %1 %2</translation>
    </message>
    <message>
        <location filename="../model/tuning/StepTest.cpp" line="88"/>
        <source>Step to %1 %2</source>
        <translation>阶跃至 %1 %2</translation>
    </message>
</context>
<context>
    <name>opentop::StepTestPanel</name>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="22"/>
        <source>Run step test…</source>
        <translation>运行阶跃测试…</translation>
    </message>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="29"/>
        <source>From:</source>
        <translation>从：</translation>
    </message>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="30"/>
        <source>To:</source>
        <translation>到：</translation>
    </message>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="31"/>
        <source>Record time:</source>
        <translation>记录时间：</translation>
    </message>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="32"/>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="75"/>
        <source>Enter two different speeds of 0 %1 or more.</source>
        <translation>请输入两个不同且不小于 0 %1 的速度。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="79"/>
        <source>Enter a record time of 100–60000 ms.</source>
        <translation>请输入 100–60000 ms 的记录时间。</translation>
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
        <translation>立即停止总线上的所有驱动器（%1），然后检查每台是否已停止。</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="87"/>
        <source>STOPPING…</source>
        <translation>正在停止…</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="103"/>
        <source>The stop broadcast to %1 drives FAILED: %2</source>
        <translation>向 %1 台驱动器广播停止失败：%2</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="106"/>
        <source>Stop sent to every drive. No drives are known on the bus, so none was checked; scan the bus to have them checked.</source>
        <translation>已向所有驱动器发送停止。总线上没有已知的驱动器，因此未检查任何驱动器；请扫描总线以便进行检查。</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="114"/>
        <source>Machine number %1: stopped after %2 s</source>
        <translation>站号 %1：%2 s 后停止</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="117"/>
        <source>Machine number %1: STILL RUNNING (%2)</source>
        <translation>站号 %1：仍在运行（%2）</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="120"/>
        <source>Machine number %1: NO ANSWER, not confirmed stopped</source>
        <translation>站号 %1：无应答，未确认已停止</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="135"/>
        <source>STOP ALL: the stop broadcast FAILED</source>
        <translation>全部停止：停止广播失败</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="136"/>
        <source>STOP ALL: stop sent, no drive checked</source>
        <translation>全部停止：已发送停止，未检查驱动器</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="137"/>
        <source>STOP ALL: every drive stopped</source>
        <translation>全部停止：所有驱动器已停止</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="138"/>
        <source>STOP ALL: not every drive is confirmed stopped</source>
        <translation>全部停止：并非所有驱动器都已确认停止</translation>
    </message>
</context>
<context>
    <name>opentop::StopAllCommand</name>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="54"/>
        <source>Broadcast stop to every drive, then confirm each has stopped (needs --yes)</source>
        <translation>向所有驱动器广播停止，然后确认每台是否已停止（需要 --yes）</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="60"/>
        <source>Send the stop broadcast.</source>
        <translation>发送停止广播。</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="62"/>
        <source>Machine numbers to confirm, e.g. 1,2,5-7 (default on a simulated bus: its drives).</source>
        <translation>要确认的站号，例如 1,2,5-7（模拟总线上默认为其所有驱动器）。</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="63"/>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="72"/>
        <source>error: usage: %1 (no other arguments)</source>
        <translation>错误：用法：%1（不接受其他参数）</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="80"/>
        <source>error: --ids: %1</source>
        <translation>错误：--ids：%1</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="87"/>
        <source>Would broadcast to every drive on the bus (machine number 0, no reply):</source>
        <translation>将向总线上的所有驱动器广播（站号 0，无应答）：</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="91"/>
        <source>Add --yes to send it.</source>
        <translation>加上 --yes 才会发送。</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="119"/>
        <source>Broadcast %1: %2</source>
        <translation>广播 %1：%2</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="120"/>
        <source>Broadcast %1 FAILED: %2: %3</source>
        <translation>广播 %1 失败：%2：%3</translation>
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
        <translation>状态</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="124"/>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="124"/>
        <source>After</source>
        <translation>之后</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="124"/>
        <source>Detail</source>
        <translation>详情</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="156"/>
        <source>Only the broadcast was sent: drives do not answer a broadcast, so nothing confirms that they stopped. To confirm, pass the machine numbers on this bus, e.g. --ids 1,2,5-7 (opentop-cli scan finds them).</source>
        <translation>只发送了广播：驱动器不应答广播，因此无法确认它们已停止。如需确认，请指定该总线上的站号，例如 --ids 1,2,5-7（opentop-cli scan 可找到它们）。</translation>
    </message>
</context>
<context>
    <name>opentop::StopConfirmer</name>
    <message>
        <location filename="../model/run/StopConfirmer.cpp" line="80"/>
        <source>%1 drives report neither running state nor speed</source>
        <translation>%1 驱动器既不报告运行状态也不报告速度</translation>
    </message>
    <message>
        <location filename="../model/run/StopConfirmer.cpp" line="111"/>
        <source>%1 is %2: the drive does not take motion commands over the bus (it follows its input terminals)</source>
        <translation>%1 为 %2：驱动器不接受来自总线的运动命令（按其输入端子动作）</translation>
    </message>
    <message>
        <location filename="../model/run/StopConfirmer.cpp" line="185"/>
        <source>still at %1 after %2 s</source>
        <translation>%2 s 后仍为 %1</translation>
    </message>
    <message>
        <location filename="../model/run/StopConfirmer.cpp" line="187"/>
        <source>still running after %1 s</source>
        <translation>%1 s 后仍在运行</translation>
    </message>
</context>
<context>
    <name>opentop::TcpSimServer</name>
    <message>
        <location filename="../sim/TcpSimServer.cpp" line="36"/>
        <source>cannot listen on %1:%2: %3</source>
        <translation>无法在 %1:%2 上监听：%3</translation>
    </message>
</context>
<context>
    <name>opentop::TerminalLamps</name>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="184"/>
        <source>n/a</source>
        <translation>不适用</translation>
    </message>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="185"/>
        <source>%1: not applicable (%2)</source>
        <translation>%1：不适用（%2）</translation>
    </message>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="188"/>
        <source>?</source>
        <translation>?</translation>
    </message>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="189"/>
        <source>%1: not read</source>
        <translation>%1：未读取</translation>
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
        <translation>%1 为 ON</translation>
    </message>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="194"/>
        <source>%1 is OFF</source>
        <translation>%1 为 OFF</translation>
    </message>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="196"/>
        <source>%1 (last state read, not live)</source>
        <translation>%1（最后读取的状态，非实时）</translation>
    </message>
</context>
<context>
    <name>opentop::TestRunPanel</name>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="48"/>
        <source>&lt;b&gt;Test run of machine number %1&lt;/b&gt;</source>
        <translation>&lt;b&gt;站号 %1 的试运行&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="54"/>
        <source>Machine number %1 has not been identified as a drive of a known family; a test run needs one.</source>
        <translation>站号 %1 尚未识别为已知系列的驱动器；试运行需要已识别的驱动器。</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="31"/>
        <source>&amp;Start</source>
        <translation>启动(&amp;S)</translation>
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
        <translation>释放(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="54"/>
        <source>Se&amp;lect running data</source>
        <translation>选择运行数据(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="67"/>
        <source>Return to &amp;I/O priority</source>
        <translation>恢复为 I/O 优先级(&amp;I)</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="69"/>
        <source>Give run, stop, direction and speed selection back to the drive&apos;s input terminals</source>
        <translation>将运行、停止、方向和速度选择交还给驱动器的输入端子</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="161"/>
        <source>Cannot read %1 to check that the drive takes motion commands: %2</source>
        <translation>无法读取 %1 以确认驱动器是否接受运动命令：%2</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="197"/>
        <source>Not started: the variant of %1 was not given.</source>
        <translation>未启动：未指定 %1 的机型。</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="204"/>
        <source>Reading what the start will run…</source>
        <translation>正在读取启动后将运行的内容…</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="220"/>
        <source>Start the motor</source>
        <translation>启动电机</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="234"/>
        <source>Sending %1…</source>
        <translation>正在发送 %1…</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="263"/>
        <source>Not every drive of its communication group runs: see below.</source>
        <translation>通信组中并非所有驱动器都在运行：见下方。</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="281"/>
        <source>Sent: %1</source>
        <translation>已发送：%1</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="350"/>
        <source>Polling is paused: the controller brakes the motor %1 s after the last frame it receives (%2). Resume polling to keep the motor running.</source>
        <translation>轮询已暂停：控制器在收到最后一帧报文 %1 s 后会使电机制动（%2）。请恢复轮询以保持电机运行。</translation>
    </message>
</context>
<context>
    <name>opentop::TrafficDescriber</name>
    <message>
        <location filename="../model/traffic/TrafficDescriber.cpp" line="150"/>
        <source>broadcast: every drive executes it</source>
        <translation>广播：所有驱动器都会执行</translation>
    </message>
    <message>
        <location filename="../model/traffic/TrafficDescriber.cpp" line="159"/>
        <source>to %1 (group parent: also %2)</source>
        <translation>发往 %1（组父站：%2 也会执行）</translation>
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
        <translation>%1（%2 ms）</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="123"/>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="125"/>
        <source>Direction</source>
        <translation>方向</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="127"/>
        <source>Drive</source>
        <translation>驱动器</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="129"/>
        <source>Function</source>
        <translation>功能码</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="131"/>
        <source>Bytes</source>
        <translation>字节</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="133"/>
        <source>Meaning</source>
        <translation>含义</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="135"/>
        <source>Error</source>
        <translation>错误</translation>
    </message>
</context>
<context>
    <name>opentop::TrafficLogView</name>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="43"/>
        <source>&amp;Errors only</source>
        <translation>仅显示错误(&amp;E)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="44"/>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="171"/>
        <source>&amp;Pause</source>
        <translation>暂停(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="53"/>
        <source>All drives</source>
        <translation>所有驱动器</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="55"/>
        <source>All</source>
        <translation>全部</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="56"/>
        <source>Tx (requests)</source>
        <translation>Tx（请求）</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="57"/>
        <source>Rx (replies)</source>
        <translation>Rx（应答）</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="58"/>
        <source>Events (no reply)</source>
        <translation>事件（无应答）</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="62"/>
        <source>&amp;Clear</source>
        <translation>清除(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="64"/>
        <source>&amp;Save…</source>
        <translation>保存(&amp;S)…</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="67"/>
        <source>&amp;Drive:</source>
        <translation>驱动器(&amp;D)：</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="69"/>
        <source>Di&amp;rection:</source>
        <translation>方向(&amp;R)：</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="83"/>
        <source>Frames</source>
        <translation>帧数</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="112"/>
        <source>Drive</source>
        <translation>驱动器</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="112"/>
        <source>Requests</source>
        <translation>请求</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="112"/>
        <source>Replies</source>
        <translation>应答</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="112"/>
        <source>Timeouts</source>
        <translation>超时</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="112"/>
        <source>CRC errors</source>
        <translation>CRC 错误</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="113"/>
        <source>Exceptions</source>
        <translation>异常</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="113"/>
        <source>Wrong/garbled</source>
        <translation>错误/损坏</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="113"/>
        <source>Mean ms</source>
        <translation>平均 ms</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="113"/>
        <source>Late replies</source>
        <translation>迟到应答</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="113"/>
        <source>Max ms</source>
        <translation>最大 ms</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="115"/>
        <source>Statistics per drive</source>
        <translation>各驱动器统计</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="119"/>
        <source>Frames that answered nothing asked at the time: a reply to an earlier request that came too late, discarded and never taken as a value</source>
        <translation>不是对当时请求的应答的帧：之前请求的应答迟到，已丢弃，从未当作数值使用</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="171"/>
        <source>&amp;Resume</source>
        <translation>继续(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="242"/>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="320"/>
        <source>Broadcast</source>
        <translation>广播</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="242"/>
        <source>Drive %1</source>
        <translation>驱动器 %1</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="309"/>
        <source>%1 addresses did not answer: %2</source>
        <translation>%1 个地址未应答：%2</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="311"/>
        <source>No reply from machine numbers %1</source>
        <translation>站号 %1 无应答</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="352"/>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="357"/>
        <source>Save traffic log</source>
        <translation>保存报文日志</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="352"/>
        <source>Text files (*.txt)</source>
        <translation>文本文件 (*.txt)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="358"/>
        <source>Could not save %1: %2</source>
        <translation>无法保存 %1：%2</translation>
    </message>
</context>
<context>
    <name>opentop::Transport</name>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="16"/>
        <source>No serial port given: enter a device such as /dev/ttyUSB0 or COM3.</source>
        <translation>未指定串口：请输入设备，例如 /dev/ttyUSB0 或 COM3。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="20"/>
        <source>Baud rate %1 is not supported: use 1200–115200 (e.g. 9600, 19200, 38400, 57600, 115200).</source>
        <translation>不支持波特率 %1：请使用 1200–115200（例如 9600、19200、38400、57600、115200）。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="26"/>
        <source>Parity &apos;%1&apos; is not supported: use N (none), E (even) or O (odd).</source>
        <translation>不支持校验位 &apos;%1&apos;：请使用 N（无）、E（偶）或 O（奇）。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="31"/>
        <source>%1 data bits are not supported: use 7 or 8.</source>
        <translation>不支持 %1 个数据位：请使用 7 或 8。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="35"/>
        <source>%1 stop bits are not supported: use 1 or 2.</source>
        <translation>不支持 %1 个停止位：请使用 1 或 2。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="39"/>
        <source>Byte timeout %1 ms is not allowed: use 1–10000 ms, or 0 to derive it from the baud rate.</source>
        <translation>不允许字节超时 %1 ms：请使用 1–10000 ms，或 0 表示根据波特率推算。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="45"/>
        <source>RS-485 mode %1 is not supported: use off, auto, kernel or rts.</source>
        <translation>不支持 RS-485 模式 %1：请使用 off、auto、kernel 或 rts。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="52"/>
        <source>Line format of machine number %1: %2 Use machine numbers 1–247.</source>
        <translation>站号 %1 的通信格式：%2 请使用站号 1–247。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="60"/>
        <source>RTS delay %1 µs is not allowed: use 0–%2 µs (0: the driver&apos;s or libmodbus&apos; own).</source>
        <translation>不允许 RTS 延时 %1 µs：请使用 0–%2 µs（0：使用驱动程序或 libmodbus 自身的延时）。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="69"/>
        <source>No host given: enter the gateway&apos;s address, e.g. 192.168.1.10.</source>
        <translation>未指定主机：请输入网关地址，例如 192.168.1.10。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="73"/>
        <source>TCP port %1 is not allowed: use 1–65535 (Modbus TCP uses 502).</source>
        <translation>不允许 TCP 端口 %1：请使用 1–65535（Modbus TCP 使用 502）。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="80"/>
        <source>No simulated devices given: use a list such as dbu200@1,dcpid@7.</source>
        <translation>未指定模拟设备：请使用 dbu200@1,dcpid@7 这样的列表。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="86"/>
        <source>Timeout %1 ms is not allowed: use 10–10000 ms.</source>
        <translation>不允许超时 %1 ms：请使用 10–10000 ms。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="90"/>
        <source>%1 retries are not allowed: use 0–10.</source>
        <translation>不允许重试 %1 次：请使用 0–10。</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="56"/>
        <source>Vendor name</source>
        <translation>厂商名称</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="58"/>
        <source>Product code</source>
        <translation>产品代码</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="60"/>
        <source>Revision</source>
        <translation>版本</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="62"/>
        <source>Vendor URL</source>
        <translation>厂商 URL</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="64"/>
        <source>Product name</source>
        <translation>产品名称</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="66"/>
        <source>Model name</source>
        <translation>型号名称</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="68"/>
        <source>User application name</source>
        <translation>用户应用名称</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="70"/>
        <source>Object 0x%1</source>
        <translation>对象 0x%1</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="26"/>
        <source>Cannot open %1: %2</source>
        <translation>无法打开 %1：%2</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="89"/>
        <source>read twice: a read of the same length was unanswered, and the first reply could have been its late answer</source>
        <translation>读取两次：同样长度的读取尚未得到应答，第一个应答可能是它的迟到应答</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="102"/>
        <source>replies disagree: late answers to earlier reads are likely</source>
        <translation>应答不一致：很可能是之前读取的迟到应答</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="115"/>
        <location filename="../transport/ModbusClientWorker.cpp" line="373"/>
        <source>%1 is not open</source>
        <translation>%1 未打开</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="160"/>
        <source>send failed</source>
        <translation>发送失败</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="186"/>
        <source>interrupted while waiting</source>
        <translation>等待时被中断</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="190"/>
        <location filename="../transport/MockBackend.cpp" line="101"/>
        <source>no reply within %1 ms</source>
        <translation>%1 ms 内无应答</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="226"/>
        <source>another reply followed: this one may have answered an earlier request</source>
        <translation>之后又收到一个应答：这个应答可能是对之前请求的应答</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="253"/>
        <source>a drive&apos;s own line format needs a serial port; a Modbus TCP gateway sets its line itself</source>
        <translation>驱动器自己的通信格式需要串口；Modbus TCP 网关自行设定它的线路</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="269"/>
        <source>cannot switch the line to %1: %2</source>
        <translation>无法把线路切换到 %1：%2</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="312"/>
        <source>no reply within %1 ms (a late reply to an earlier request was discarded)</source>
        <translation>%1 ms 内无应答（之前请求的迟到应答已丢弃）</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="334"/>
        <location filename="../transport/RtuFrame.cpp" line="140"/>
        <source>reply from slave %1, expected %2</source>
        <translation>来自从站 %1 的应答，预期为 %2</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusContext.cpp" line="140"/>
        <location filename="../transport/RtuBackend.cpp" line="191"/>
        <location filename="../transport/TcpBackend.cpp" line="112"/>
        <source>reply incomplete</source>
        <translation>应答不完整</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusContext.cpp" line="144"/>
        <location filename="../transport/RtuFrame.cpp" line="133"/>
        <source>CRC mismatch</source>
        <translation>CRC 不一致</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="344"/>
        <location filename="../transport/RtuBackend.cpp" line="198"/>
        <location filename="../transport/TcpBackend.cpp" line="118"/>
        <source>receive failed</source>
        <translation>接收失败</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="362"/>
        <source>late reply discarded: complete %1 ms after the request, where an answer needs at least %2 ms on the wire</source>
        <translation>已丢弃迟到应答：请求后 %1 ms 即接收完毕，而应答在线路上至少需要 %2 ms</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="378"/>
        <source> (connection closed)</source>
        <translation> （连接已关闭）</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="393"/>
        <source>stale bytes discarded before sending</source>
        <translation>发送前丢弃了残留字节</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="440"/>
        <source>late bytes discarded after an error</source>
        <translation>出错后丢弃了迟到的字节</translation>
    </message>
    <message>
        <location filename="../transport/MockBackend.cpp" line="57"/>
        <source>mock is not open</source>
        <translation>mock 未打开</translation>
    </message>
    <message>
        <location filename="../transport/ModbusBackend.cpp" line="39"/>
        <source>→ %1 bytes</source>
        <translation>→ %1 字节</translation>
    </message>
    <message>
        <location filename="../transport/ModbusBackend.cpp" line="51"/>
        <source>echo %1 = %2</source>
        <translation>回显 %1 = %2</translation>
    </message>
    <message>
        <location filename="../transport/ModbusBackend.cpp" line="54"/>
        <source>echo %1 ×%2</source>
        <translation>回显 %1 ×%2</translation>
    </message>
    <message>
        <location filename="../transport/ModbusClientWorker.cpp" line="220"/>
        <location filename="../transport/ModbusClientWorker.cpp" line="239"/>
        <source>cancelled before sending</source>
        <translation>发送前已取消</translation>
    </message>
    <message>
        <location filename="../transport/ModbusClientWorker.cpp" line="285"/>
        <source>cannot open %1</source>
        <translation>无法打开 %1</translation>
    </message>
    <message>
        <location filename="../transport/ModbusClientWorker.cpp" line="327"/>
        <source>client closed</source>
        <translation>客户端已关闭</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="142"/>
        <source>Slave address %1 is not allowed: use 1–247, or 0 to broadcast a write.</source>
        <translation>不允许从站地址 %1：请使用 1–247，或用 0 广播写入。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="147"/>
        <source>Function code 0x%1 is not allowed: use 0x01–0x7F.</source>
        <translation>不允许功能码 0x%1：请使用 0x01–0x7F。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="151"/>
        <source>Timeout %1 ms is not allowed: use 10–10000 ms, or -1 for the default.</source>
        <translation>不允许超时 %1 ms：请使用 10–10000 ms，或用 -1 表示默认值。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="156"/>
        <source>%1 retries are not allowed: use 0–10, or -1 for the default.</source>
        <translation>不允许重试 %1 次：请使用 0–10，或用 -1 表示默认值。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="169"/>
        <source>Function 0x%1 cannot be broadcast: only functions 06h and 10h (writes) may be sent to machine number 0; use slave address 1–247.</source>
        <translation>功能码 0x%1 不能广播：只有功能码 06h 和 10h（写入）可以发给站号 0；请使用从站地址 1–247。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="176"/>
        <source>Function code 0x%1 must be sent as a raw request.</source>
        <translation>功能码 0x%1 必须作为原始请求发送。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="180"/>
        <source>Raw request data of %1 bytes is too long: at most %2 bytes.</source>
        <translation>%1 字节的原始请求数据过长：最多 %2 字节。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="193"/>
        <source>Cannot read %1 registers at once: use 1–125 registers.</source>
        <translation>无法一次读取 %1 个寄存器：请使用 1–125 个寄存器。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="200"/>
        <source>Write single register needs exactly 1 value, not %1.</source>
        <translation>写单个寄存器需要且只需要 1 个值，而不是 %1 个。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="206"/>
        <source>Cannot write %1 registers at once: use 1–123 registers.</source>
        <translation>无法一次写入 %1 个寄存器：请使用 1–123 个寄存器。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="211"/>
        <source>%1 values given for %2 registers.</source>
        <translation>为 %2 个寄存器给出了 %1 个值。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="220"/>
        <source>Registers %1 ×%2 run past the last address 0xFFFF.</source>
        <translation>寄存器 %1 ×%2 超出最后地址 0xFFFF。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="231"/>
        <source>device identification code %1 object %2</source>
        <translation>设备识别代码 %1 对象 %2</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="239"/>
        <source>raw %1 %2</source>
        <translation>原始 %1 %2</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="243"/>
        <source>read %1 %2 ×%3</source>
        <translation>读取 %1 %2 ×%3</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="247"/>
        <source>write %1 %2 = %3</source>
        <translation>写入 %1 %2 = %3</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="250"/>
        <source>write %1 %2 ×%3 = %4</source>
        <translation>写入 %1 %2 ×%3 = %4</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="256"/>
        <source>broadcast %1</source>
        <translation>广播 %1</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="11"/>
        <source>ok</source>
        <translation>正常</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="13"/>
        <source>timeout</source>
        <translation>超时</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="15"/>
        <source>CRC error</source>
        <translation>CRC 错误</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="17"/>
        <source>reply from wrong slave</source>
        <translation>应答来自错误的从站</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="19"/>
        <source>exception</source>
        <translation>异常</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="21"/>
        <source>malformed reply</source>
        <translation>应答格式错误</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="23"/>
        <source>port error</source>
        <translation>端口错误</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="25"/>
        <source>not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="27"/>
        <source>invalid request</source>
        <translation>无效请求</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="29"/>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="38"/>
        <source>Illegal function</source>
        <translation>非法功能</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="40"/>
        <source>Illegal data address</source>
        <translation>非法数据地址</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="42"/>
        <source>Illegal data value</source>
        <translation>非法数据值</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="44"/>
        <source>Slave device failure</source>
        <translation>从站设备故障</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="46"/>
        <source>Acknowledge (processing)</source>
        <translation>确认（处理中）</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="48"/>
        <source>Slave device busy</source>
        <translation>从站设备忙</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="50"/>
        <source>Negative acknowledge</source>
        <translation>否定确认</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="52"/>
        <source>Memory parity error</source>
        <translation>存储器奇偶校验错误</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="54"/>
        <source>Gateway path unavailable</source>
        <translation>网关路径不可用</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="56"/>
        <source>Gateway target device failed to respond</source>
        <translation>网关目标设备无响应</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="60"/>
        <source>Prohibited action</source>
        <translation>禁止的操作</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="62"/>
        <source>Undefined error</source>
        <translation>未定义的错误</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="64"/>
        <source>Unknown exception</source>
        <translation>未知异常</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="74"/>
        <source>exception %1 %2</source>
        <translation>异常 %1 %2</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="79"/>
        <source>timeout after %1 attempts</source>
        <translation>%1 次尝试后超时</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="81"/>
        <source>timeout (no reply)</source>
        <translation>超时（无应答）</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="89"/>
        <source> (%1 attempts)</source>
        <translation> （%1 次尝试）</translation>
    </message>
    <message>
        <location filename="../transport/PortLock.cpp" line="22"/>
        <source>%1 is in use by another program; close it first.</source>
        <translation>%1 正被其他程序占用；请先将其关闭。</translation>
    </message>
    <message>
        <location filename="../transport/PortLock.cpp" line="27"/>
        <source>another program</source>
        <translation>其他程序</translation>
    </message>
    <message>
        <location filename="../transport/PortLock.cpp" line="29"/>
        <source>%1 is in use by %2 (PID %3); close it first.</source>
        <translation>%1 正被 %2（PID %3）占用；请先将其关闭。</translation>
    </message>
    <message>
        <location filename="../transport/RtuBackend.cpp" line="127"/>
        <source>: your user may not open serial ports. Add it to the dialout group with
    sudo usermod -aG dialout $USER
then log out and in again (the group applies to new sessions only).</source>
        <translation>：当前用户无权打开串口。请用以下命令将其加入 dialout 组：
    sudo usermod -aG dialout $USER
然后注销并重新登录（该组仅对新会话生效）。</translation>
    </message>
    <message>
        <location filename="../transport/RtuBackend.cpp" line="134"/>
        <source> (the device may not support this parity; ptys need N)</source>
        <translation> （设备可能不支持该校验位；pty 需要 N）</translation>
    </message>
    <message>
        <location filename="../transport/RtuBackend.cpp" line="169"/>
        <source>reply announces %1 bytes, more than an RTU frame holds</source>
        <translation>应答声明 %1 字节，超过 RTU 帧的容量</translation>
    </message>
    <message>
        <location filename="../transport/RtuBackend.cpp" line="190"/>
        <source>no reply</source>
        <translation>无应答</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="127"/>
        <source>reply too short (%1 bytes)</source>
        <translation>应答过短（%1 字节）</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="148"/>
        <source>exception reply of %1 bytes</source>
        <translation>%1 字节的异常应答</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="159"/>
        <source>reply function %1, expected %2</source>
        <translation>应答功能码 %1，预期为 %2</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="166"/>
        <source>reply ends inside its own data</source>
        <translation>应答在其自身数据内部结束</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="171"/>
        <source>reply of %1 bytes, expected %2</source>
        <translation>应答 %1 字节，预期为 %2</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="181"/>
        <source>MEI type %1, expected %2</source>
        <translation>MEI 类型 %1，预期为 %2</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="194"/>
        <source>byte count %1, expected %2</source>
        <translation>字节数 %1，预期为 %2</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="207"/>
        <source>echo %1 = %2 differs from the write</source>
        <translation>回显 %1 = %2 与写入不一致</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="218"/>
        <source>echo %1 ×%2 differs from the write</source>
        <translation>回显 %1 ×%2 与写入不一致</translation>
    </message>
    <message>
        <location filename="../transport/SerialPortList.cpp" line="87"/>
        <source>An adapter missing here has no driver: see Device Manager, Ports (COM &amp; LPT). A port can also be typed, e.g. COM12.</source>
        <translation>此处未列出的适配器尚未安装驱动程序：请查看设备管理器的“端口 (COM 和 LPT)”。也可以直接输入端口，例如 COM12。</translation>
    </message>
    <message>
        <location filename="../transport/SerialPortList.cpp" line="92"/>
        <source>Pseudo-terminals (e.g. /dev/pts/3 or a socat link) are not listed: type their path.</source>
        <translation>伪终端（例如 /dev/pts/3 或 socat 链接）不会列出：请输入其路径。</translation>
    </message>
    <message>
        <location filename="../transport/TcpBackend.cpp" line="61"/>
        <source>Cannot open %1: the name %2 was not found (%3); check the gateway&apos;s name, or give its address</source>
        <translation>无法打开 %1：找不到名称 %2（%3）；请检查网关的名称，或改用其地址</translation>
    </message>
    <message>
        <location filename="../transport/TcpBackend.cpp" line="128"/>
        <source>MBAP length %1</source>
        <translation>MBAP 长度 %1</translation>
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
        <translation>错误：%1</translation>
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
        <translation>发送时 RTS 为高电平</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="32"/>
        <source>RTS low while sending</source>
        <translation>发送时 RTS 为低电平</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="35"/>
        <source>, %1 before and after</source>
        <translation>，发送前后各 %1</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="37"/>
        <source>, %1 before, %2 after</source>
        <translation>，发送前 %1，发送后 %2</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="43"/>
        <source>RS-485: switched by the adapter</source>
        <translation>RS-485：由适配器切换</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="45"/>
        <source>RS-485: kernel mode left on by the driver (%1)</source>
        <translation>RS-485：驱动程序保持内核模式开启（%1）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="49"/>
        <source>RS-485: kernel (%1)</source>
        <translation>RS-485：内核（%1）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="52"/>
        <source>RS-485: RTS from the program (%1; kernel mode refused: %2)</source>
        <translation>RS-485：由程序控制 RTS（%1；内核模式被拒绝：%2）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="56"/>
        <source>RS-485: RTS from the program (%1)</source>
        <translation>RS-485：由程序控制 RTS（%1）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="61"/>
        <source>RS-485: not available (kernel mode refused: %1; RTS not switchable: %2)</source>
        <translation>RS-485：不可用（内核模式被拒绝：%1；RTS 无法切换：%2）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="66"/>
        <source>RS-485: RTS not switchable on this port (%1)</source>
        <translation>RS-485：此端口无法切换 RTS（%1）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="69"/>
        <source>RS-485: kernel mode refused by the driver (%1)</source>
        <translation>RS-485：驱动程序拒绝内核模式（%1）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="78"/>
        <source>latency timer %1 ms</source>
        <translation>延迟定时器 %1 ms</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="86"/>
        <source>low latency: not a UART, no adapter latency</source>
        <translation>低延迟：非 UART，无适配器延迟</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="90"/>
        <source>low latency: on (but %1)</source>
        <translation>低延迟：开启（但 %1）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="92"/>
        <source>low latency: on</source>
        <translation>低延迟：开启</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="95"/>
        <source>low latency: the driver&apos;s setting (FTDI: Latency Timer 1 ms in Device Manager)</source>
        <translation>低延迟：由驱动程序设置（FTDI：在设备管理器中将 Latency Timer 设为 1 ms）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="100"/>
        <source>low latency: not offered by the driver (%1)</source>
        <translation>低延迟：驱动程序不支持（%1）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="104"/>
        <source>low latency: not offered by the driver (USB adapter: up to %1 ms assumed)</source>
        <translation>低延迟：驱动程序不支持（USB 适配器：按最多 %1 ms 估计）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="108"/>
        <source>low latency: not offered by the driver</source>
        <translation>低延迟：驱动程序不支持</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="112"/>
        <source>low latency: off</source>
        <translation>低延迟：关闭</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="113"/>
        <source>low latency: off (%1)</source>
        <translation>低延迟：关闭（%1）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="137"/>
        <source>low latency is off</source>
        <translation>低延迟已关闭</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="139"/>
        <source>the driver took low latency but kept its latency timer</source>
        <translation>驱动程序接受了低延迟，但保留了其延迟定时器</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="142"/>
        <source>the driver did not take low latency</source>
        <translation>驱动程序未接受低延迟</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="145"/>
        <source>see docs/hardware.md, or use an adapter whose driver offers low latency</source>
        <translation>请参阅 docs/hardware.md，或改用驱动程序支持低延迟的适配器</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="149"/>
        <source>as root: echo 1 &gt; %1, or the udev rule in docs/hardware.md</source>
        <translation>以 root 身份执行：echo 1 &gt; %1，或使用 docs/hardware.md 中的 udev 规则</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="153"/>
        <source>The adapter holds received bytes for up to %1 ms before passing them on (%2). Fix: %3.</source>
        <translation>适配器会将收到的字节缓存最多 %1 ms 后才转交（%2）。解决方法：%3。</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineSetup.cpp" line="131"/>
        <source>the driver left it off</source>
        <translation>驱动程序仍保持关闭</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineSetup.cpp" line="200"/>
        <source>the port does not take %1</source>
        <translation>端口不接受 %1</translation>
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
        <translation>时间 (hh:mm:ss)</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendChart.cpp" line="109"/>
        <source>Drive %1</source>
        <translation>驱动器 %1</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendChart.cpp" line="300"/>
        <source>There is no trend data to export yet.</source>
        <translation>尚无可导出的趋势数据。</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendChart.cpp" line="313"/>
        <source>Cannot write the picture %1.</source>
        <translation>无法写入图片 %1。</translation>
    </message>
</context>
<context>
    <name>opentop::TrendCsv</name>
    <message>
        <location filename="../model/monitor/TrendCsv.cpp" line="28"/>
        <source>time</source>
        <translation>时间</translation>
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
        <translation>暂停</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="51"/>
        <source>Live</source>
        <translation>实时</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="54"/>
        <source>How often each charted drive is polled. Commands you give always go first; the drives take turns on the bus.</source>
        <translation>每台绘图驱动器的轮询频率。您发出的命令总是优先；各驱动器轮流使用总线。</translation>
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
        <translation>冻结图表；数值仍会继续记录。</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="78"/>
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="81"/>
        <source>Back to the latest values after zooming or pausing.</source>
        <translation>缩放或暂停后回到最新值。</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="86"/>
        <source>Clear markers</source>
        <translation>清除标记</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="89"/>
        <source>Export CSV…</source>
        <translation>导出 CSV…</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="92"/>
        <source>Export PNG…</source>
        <translation>导出 PNG…</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="97"/>
        <source>Drive / quantity</source>
        <translation>驱动器 / 测量项</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="111"/>
        <source>Poll rate:</source>
        <translation>轮询频率：</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="113"/>
        <source>Window:</source>
        <translation>时间窗：</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="141"/>
        <source>%1 Hz (%2 ms)</source>
        <translation>%1 Hz（%2 ms）</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="200"/>
        <source>%1 [%2]</source>
        <translation>%1 [%2]</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="253"/>
        <source>Export trend as CSV</source>
        <translation>将趋势导出为 CSV</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="253"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="256"/>
        <source>Export CSV</source>
        <translation>导出 CSV</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="262"/>
        <source>Export trend as picture</source>
        <translation>将趋势导出为图片</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="263"/>
        <source>PNG pictures (*.png)</source>
        <translation>PNG 图片 (*.png)</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="266"/>
        <source>Export PNG</source>
        <translation>导出 PNG</translation>
    </message>
</context>
<context>
    <name>opentop::TrendReadout</name>
    <message>
        <location filename="../ui/trends/TrendReadout.cpp" line="25"/>
        <source>Markers: click in the chart to set marker A, click again to set marker B.</source>
        <translation>标记：在图表中单击设置标记 A，再次单击设置标记 B。</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendReadout.cpp" line="28"/>
        <source>A %1   B %2   Δt = B − A = %3 s</source>
        <translation>A %1   B %2   Δt = B − A = %3 s</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendReadout.cpp" line="31"/>
        <source>A %1   (click in the chart to set marker B)</source>
        <translation>A %1   （在图表中单击设置标记 B）</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendReadout.cpp" line="32"/>
        <source>B %1   (click in the chart to set marker A)</source>
        <translation>B %1   （在图表中单击设置标记 A）</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendReadout.cpp" line="34"/>
        <source>no data</source>
        <translation>无数据</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendReadout.cpp" line="44"/>
        <source>%1:   A %2   B %3   Δ %4</source>
        <translation>%1：   A %2   B %3   Δ %4</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendReadout.cpp" line="46"/>
        <source>%1:   %2 %3</source>
        <translation>%1：   %2 %3</translation>
    </message>
</context>
<context>
    <name>opentop::TuneCommand</name>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="82"/>
        <source>Speed-loop step test and relay autotune of a DC controller (needs --yes)</source>
        <translation>直流控制器的速度环阶跃测试和继电器自整定（需要 --yes）</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="88"/>
        <source>Run the test (it moves the motor).</source>
        <translation>执行测试（会使电机运动）。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="89"/>
        <source>step: speed before the step (default 0).</source>
        <translation>step：阶跃前的速度（默认 0）。</translation>
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
        <translation>step：阶跃后的速度。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="91"/>
        <source>step: record this long after the step (default 1500).</source>
        <translation>step：阶跃后记录的时长（默认 1500）。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="92"/>
        <source>MS</source>
        <translation>MS</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="93"/>
        <source>autotune: operating speed of the relay test.</source>
        <translation>autotune：继电器测试的运行速度。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="94"/>
        <source>autotune: output swing, % of full output (default 10).</source>
        <translation>autotune：输出摆幅，以满输出的 % 表示（默认 10）。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="95"/>
        <source>PERCENT</source>
        <translation>PERCENT</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="97"/>
        <source>autotune: soft, medium (default), stiff, tyreus-luyben or zn-pi.</source>
        <translation>autotune：soft、medium（默认）、stiff、tyreus-luyben 或 zn-pi。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="97"/>
        <source>RULE</source>
        <translation>RULE</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="98"/>
        <source>autotune: write the proposed gains, then run a step test from half the operating speed to it.</source>
        <translation>autotune：写入建议增益，然后执行从运行速度的一半到运行速度的阶跃测试。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="101"/>
        <source>autotune: with --accept, store the gains in the drive if the step measured with them passes the check.</source>
        <translation>autotune：配合 --accept 时，若用此增益测得的阶跃通过检查，便将增益保存到驱动器。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="104"/>
        <source>autotune: with --accept, keep (and with --store, store) gains whose measured step failed the check; without it they are written back to what the drive had.</source>
        <translation>autotune：配合 --accept 时，即使测得的阶跃未通过检查也保留增益（配合 --store 则保存）；不指定时会写回驱动器原来的增益。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="107"/>
        <source>Stop at once beyond this speed (default 120 % of the test&apos;s highest).</source>
        <translation>速度超过此值时立即停止（默认为测试最高速度的 120 %）。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="108"/>
        <source>Stop at once beyond this current in A (default 20).</source>
        <translation>电流超过此值（A）时立即停止（默认 20）。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="109"/>
        <source>A</source>
        <translation>A</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="110"/>
        <source>Write the samples to FILE.</source>
        <translation>将采样数据写入 FILE。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="110"/>
        <source>FILE</source>
        <translation>FILE</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="124"/>
        <source>error: usage: %1</source>
        <translation>错误：用法：%1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="134"/>
        <source>error: --%1 must be a number 0 or more, got &apos;%2&apos;</source>
        <translation>错误：--%1 必须是不小于 0 的数，实际为 &apos;%2&apos;</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="156"/>
        <location filename="../cli/TuneCommand.cpp" line="167"/>
        <location filename="../cli/TuneCommand.cpp" line="172"/>
        <location filename="../cli/TuneCommand.cpp" line="375"/>
        <source>error: %1</source>
        <translation>错误：%1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="157"/>
        <source>step needs --to SPEED</source>
        <translation>step 需要 --to SPEED</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="158"/>
        <source>--rule must be one of %1</source>
        <translation>--rule 必须是 %1 之一</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="160"/>
        <source>autotune needs --speed SPEED</source>
        <translation>autotune 需要 --speed SPEED</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="176"/>
        <source>Would run the motor of machine number %1 from %2 to %3 and record the step response.</source>
        <translation>将使站号 %1 的电机从 %2 运行到 %3，并记录阶跃响应。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="181"/>
        <source>Would run the motor of machine number %1 in a relay test around %2 (output ±%3 %).</source>
        <translation>将使站号 %1 的电机在 %2 附近进行继电器测试（输出 ±%3 %）。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="187"/>
        <source>This moves the motor: add --yes to run it.</source>
        <translation>这会使电机运动：加上 --yes 才会执行。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="236"/>
        <source>Machine number %1, gains %2</source>
        <translation>站号 %1，增益 %2</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="238"/>
        <source>  rise time (10–90 %): %1</source>
        <translation>  上升时间（10–90 %）：%1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="239"/>
        <source>  overshoot: %1 %</source>
        <translation>  超调：%1 %</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="240"/>
        <source>  settling time (2 %): %1</source>
        <translation>  调节时间（2 %）：%1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="241"/>
        <source>  steady-state error: %1 %2</source>
        <translation>  稳态误差：%1 %2</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="242"/>
        <source>  peak current: %1 A</source>
        <translation>  峰值电流：%1 A</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="268"/>
        <source>Step %1 → %2 %3:</source>
        <translation>阶跃 %1 → %2 %3：</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="273"/>
        <source>Relay test: Ku %1, Tu %2 ms measured (amplitude ±%3 %4, %5 cycles, %6 readings per period, one every %7 ms)</source>
        <translation>继电器测试：Ku %1，实测 Tu %2 ms（幅值 ±%3 %4，%5 个周期，每周期读取 %6 次，每 %7 ms 一次）</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="365"/>
        <source>What to change: %1</source>
        <translation>应更改的项目：%1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="282"/>
        <source>Model: gain %1, time constant %2 ms, dead time %3 ms (the bus&apos;s %4 ms left out)</source>
        <translation>模型：增益 %1，时间常数 %2 ms，纯滞后时间 %3 ms（已扣除总线的 %4 ms）</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="288"/>
        <source>The drive&apos;s own loop on the model: Ku %1, Tu %2 ms</source>
        <translation>模型上驱动器自身的环路：Ku %1，Tu %2 ms</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="291"/>
        <source>Proposed (%1): %2</source>
        <translation>建议值（%1）：%2</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="292"/>
        <source>  the rule&apos;s P × %1, Ti × %2; predicted step %3 → %4 %5: overshoot %6 %, settling time %7</source>
        <translation>  规则的 P × %1，Ti × %2；预测阶跃 %3 → %4 %5：超调 %6 %，调节时间 %7</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="308"/>
        <source>Writing the proposed gains failed: %1</source>
        <translation>写入建议增益失败：%1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="311"/>
        <source>Proposed gains written (not stored).</source>
        <translation>已写入建议增益（未保存）。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="314"/>
        <source>Measured step %1 → %2 %3 with them:</source>
        <translation>用该增益测得的阶跃 %1 → %2 %3：</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="322"/>
        <source>interrupted</source>
        <translation>已中断</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="325"/>
        <source>Check after Accept: passed. %1</source>
        <translation>接受后的检查：通过。%1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="326"/>
        <source>Check after Accept: FAILED. %1</source>
        <translation>接受后的检查：未通过。%1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="335"/>
        <source>The gains before were written back (%1); nothing was stored. --override-check keeps the proposal (and with --store stores it) all the same.</source>
        <translation>已写回原来的增益（%1）；未保存任何内容。加上 --override-check 仍会保留建议值（配合 --store 则保存）。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="339"/>
        <source>Writing back the gains before failed: %1; the proposal is still in the drive (not stored).</source>
        <translation>写回原来的增益失败：%1；建议值仍在驱动器中（未保存）。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="346"/>
        <source>Storing although the check failed (--override-check).</source>
        <translation>检查未通过，仍予保存（--override-check）。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="355"/>
        <source>Gains stored in the drive.</source>
        <translation>增益已保存到驱动器。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="356"/>
        <source>Storing the gains failed: %1</source>
        <translation>保存增益失败：%1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="363"/>
        <source>Test ended: %1</source>
        <translation>测试结束：%1</translation>
    </message>
</context>
<context>
    <name>opentop::TuningChart</name>
    <message>
        <location filename="../ui/tuning/TuningChart.cpp" line="41"/>
        <source>Time (ms)</source>
        <translation>时间 (ms)</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningChart.cpp" line="45"/>
        <location filename="../ui/tuning/TuningChart.cpp" line="83"/>
        <source>Current (A)</source>
        <translation>电流 (A)</translation>
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
        <translation>已有整定测试正在进行</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="88"/>
        <source>Reading the drive&apos;s settings</source>
        <translation>正在读取驱动器设定</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="98"/>
        <source>could not read the drive&apos;s settings: %1</source>
        <translation>无法读取驱动器设定：%1</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="139"/>
        <source>the drive is not in a closed-loop speed mode: set %1 (%2) to %3 first</source>
        <translation>驱动器不处于闭环速度模式：请先将 %1（%2）设为 %3</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="141"/>
        <source> or </source>
        <translation> 或 </translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="146"/>
        <source>Setting the communication-loss braking time to %1 s</source>
        <translation>正在将通信中断停止时间设为 %1 s</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="201"/>
        <source>the drive stopped answering: %1</source>
        <translation>驱动器停止应答：%1</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="221"/>
        <source>speed %1 %2 beyond the test&apos;s limit %3 %2: stopped at once</source>
        <translation>速度 %1 %2 超出测试限值 %3 %2：已立即停止</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="228"/>
        <source>current %1 A beyond the test&apos;s limit %2 A: stopped at once</source>
        <translation>电流 %1 A 超出测试限值 %2 A：已立即停止</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="234"/>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="271"/>
        <source>Stopping the motor</source>
        <translation>正在停止电机</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="303"/>
        <source>motor stopped (confirmed)</source>
        <translation>电机已停止（已确认）</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="304"/>
        <source>the motor could not be confirmed stopped: check it</source>
        <translation>无法确认电机已停止：请检查电机</translation>
    </message>
</context>
<context>
    <name>opentop::TuningDriveSettings</name>
    <message>
        <location filename="../ui/tuning/TuningDriveSettings.cpp" line="53"/>
        <source>Could not read the speed mode: %1</source>
        <translation>无法读取速度模式：%1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningDriveSettings.cpp" line="56"/>
        <source>The drive is not in a closed-loop speed mode (now: %1). Choose one on its settings page first.</source>
        <translation>驱动器不处于闭环速度模式（当前：%1）。请先在其设定页面中选择一种闭环模式。</translation>
    </message>
</context>
<context>
    <name>opentop::TuningGains</name>
    <message>
        <location filename="../ui/tuning/TuningGains.cpp" line="43"/>
        <source>Writing the gains failed: %1</source>
        <translation>写入增益失败：%1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningGains.cpp" line="62"/>
        <source>Proposal written (temporary until stored).</source>
        <translation>已写入建议值（保存前仅临时有效）。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningGains.cpp" line="83"/>
        <source>%1: the gains before were written back (%2).</source>
        <translation>%1：已写回原来的增益（%2）。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningGains.cpp" line="102"/>
        <source>Gains stored in the drive.</source>
        <translation>增益已保存到驱动器。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningGains.cpp" line="104"/>
        <source>Storing the gains failed: %1</source>
        <translation>保存增益失败：%1</translation>
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
        <translation>超过该值时电机立即停止。留空：阶跃测试最高速度的 125 %，自整定速度的 150 %</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="19"/>
        <source>Beyond it the motor is stopped at once. Empty: 1.2 × the drive&apos;s maximum current</source>
        <translation>超过该值时电机立即停止。留空：1.2 × 驱动器最大电流</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="22"/>
        <source>Max. speed:</source>
        <translation>最高速度：</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="23"/>
        <source>Max. current:</source>
        <translation>最大电流：</translation>
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
        <translation>自动：%1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="39"/>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="48"/>
        <source>Enter a speed limit above 0 %1, or leave it empty.</source>
        <translation>请输入大于 0 %1 的速度限值，或留空。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="52"/>
        <source>Enter a current limit above 0 A, or leave it empty.</source>
        <translation>请输入大于 0 A 的电流限值，或留空。</translation>
    </message>
</context>
<context>
    <name>opentop::TuningMetricsView</name>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="25"/>
        <source>Rise time (10–90 %):</source>
        <translation>上升时间（10–90 %）：</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="26"/>
        <source>Overshoot:</source>
        <translation>超调：</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="27"/>
        <source>Settling time (2 %):</source>
        <translation>调节时间（2 %）：</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="28"/>
        <source>Steady-state error:</source>
        <translation>稳态误差：</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="29"/>
        <source>Peak current:</source>
        <translation>峰值电流：</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="40"/>
        <source>No run yet</source>
        <translation>尚未进行测试</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="41"/>
        <source>%1: recording</source>
        <translation>%1：记录中</translation>
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
        <translation>未达到</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="54"/>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="56"/>
        <source>not settled</source>
        <translation>未稳定</translation>
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
        <translation>上升时间 %1；超调 %2；调节时间 %3；稳态误差 %4；峰值电流 %5</translation>
    </message>
</context>
<context>
    <name>opentop::TuningPage</name>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="53"/>
        <location filename="../ui/tuning/TuningPage.cpp" line="213"/>
        <source>Step test</source>
        <translation>阶跃测试</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="54"/>
        <location filename="../ui/tuning/TuningPage.cpp" line="234"/>
        <source>Relay autotune</source>
        <translation>继电器自整定</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="112"/>
        <source>Ready. Nothing moves until you confirm a test.</source>
        <translation>就绪。确认测试之前，电机不会运行。</translation>
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
        <translation>无电流限值</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="208"/>
        <source>The motor of %1 will run from %2 to %3 %4 in its present speed mode, for about %5 s, and then stop.</source>
        <translation>%1 的电机将以当前速度模式从 %2 运行到 %3 %4，持续约 %5 s，然后停止。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="213"/>
        <location filename="../ui/tuning/TuningPage.cpp" line="234"/>
        <source>Run</source>
        <translation>执行</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="229"/>
        <source>The motor of %1 will run in open loop (the speed loop off) around %2 %3, its output switching by ±%4 %, for up to %5 s, and then stop.</source>
        <translation>%1 的电机将以开环方式（速度环关闭）在 %2 %3 附近运行，输出以 ±%4 % 切换，最长 %5 s，然后停止。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="252"/>
        <source>Stop command sent.</source>
        <translation>已发送停止命令。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="253"/>
        <source>Stop command failed: %1</source>
        <translation>停止命令失败：%1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="263"/>
        <source>Stopping…</source>
        <translation>正在停止…</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="277"/>
        <source>Run %1: %2 → %3 %4</source>
        <translation>测试 %1：%2 → %3 %4</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="296"/>
        <source>Step test done.</source>
        <translation>阶跃测试完成。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="297"/>
        <source>Step test ended: %1</source>
        <translation>阶跃测试结束：%1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="302"/>
        <source>The test was stopped</source>
        <translation>测试已停止</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="333"/>
        <source>Autotune ended: %1</source>
        <translation>自整定结束：%1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="335"/>
        <source>The autotune was stopped</source>
        <translation>自整定已停止</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="344"/>
        <source>Predicted: %1 → %2 %3</source>
        <translation>预测：%1 → %2 %3</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="347"/>
        <source>Autotune done: proposal %1. Accept writes it to the drive.</source>
        <translation>自整定完成：建议值 %1。接受后将写入驱动器。</translation>
    </message>
</context>
<context>
    <name>opentop::TuningRules</name>
    <message>
        <location filename="../model/tuning/TuningRules.cpp" line="61"/>
        <source>Soft (no overshoot)</source>
        <translation>柔和（无超调）</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningRules.cpp" line="63"/>
        <source>Medium (some overshoot)</source>
        <translation>适中（少量超调）</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningRules.cpp" line="65"/>
        <source>Stiff (Ziegler–Nichols)</source>
        <translation>高刚性（Ziegler–Nichols）</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningRules.cpp" line="67"/>
        <source>Tyreus–Luyben (robust)</source>
        <translation>Tyreus–Luyben（鲁棒）</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningRules.cpp" line="69"/>
        <source>PI only (Ziegler–Nichols)</source>
        <translation>仅 PI（Ziegler–Nichols）</translation>
    </message>
</context>
<context>
    <name>opentop::TuningRunList</name>
    <message>
        <location filename="../ui/tuning/TuningRunList.cpp" line="14"/>
        <source>Run</source>
        <translation>测试</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunList.cpp" line="14"/>
        <source>Gains</source>
        <translation>增益</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunList.cpp" line="43"/>
        <source>%1 (recording)</source>
        <translation>%1（记录中）</translation>
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
        <translation>保存 CSV…</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="39"/>
        <source>Save PNG…</source>
        <translation>保存 PNG…</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="44"/>
        <source>Saves the selected run: its samples, gains and metrics</source>
        <translation>保存所选测试：其采样数据、增益和指标</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="45"/>
        <source>Saves the chart as it is shown</source>
        <translation>按当前显示保存图表</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="46"/>
        <source>solid: speed · dotted: command · dash-dot: current (right axis) · dashed: predicted speed</source>
        <translation>实线：速度 · 点线：命令 · 点划线：电流（右轴） · 虚线：预测速度</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="220"/>
        <source>no run to save</source>
        <translation>没有可保存的测试</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="233"/>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="237"/>
        <source>Save run as CSV</source>
        <translation>将测试保存为 CSV</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="234"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="242"/>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="245"/>
        <source>Save chart as PNG</source>
        <translation>将图表保存为 PNG</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="243"/>
        <source>PNG images (*.png)</source>
        <translation>PNG 图片 (*.png)</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="245"/>
        <source>Could not write %1.</source>
        <translation>无法写入 %1。</translation>
    </message>
</context>
<context>
    <name>opentop::TuningSpec</name>
    <message>
        <location filename="../model/tuning/TuningSpec.cpp" line="23"/>
        <source>%1 has no speed loop to tune</source>
        <translation>%1 没有可整定的速度环</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningSpec.cpp" line="51"/>
        <source>%1: the profile&apos;s tuning needs the roles pidP, pidI, pidD, pidDPeriod, pidStore, speedMode, speedCommand, commLossTime, loadCurrent and output</source>
        <translation>%1：设备描述的整定需要以下角色：pidP、pidI、pidD、pidDPeriod、pidStore、speedMode、speedCommand、commLossTime、loadCurrent 和 output</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningSpec.cpp" line="61"/>
        <source>%1: the profile&apos;s tuning section needs periodMs ≥ 1, outputFullScale &gt; 0, openLoopMode and closedLoopModes with known feedback parameters</source>
        <translation>%1：设备描述的整定部分需要 periodMs ≥ 1、outputFullScale &gt; 0、openLoopMode，以及反馈参数已知的 closedLoopModes</translation>
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
        <translation>取消正在进行的测试：停止电机并确认已停止</translation>
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
        <translation>记录时间内未稳定</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningVerdict.cpp" line="20"/>
        <source>no step was measured to its end with these gains: %1</source>
        <translation>未能用此增益将阶跃测完：%1</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningVerdict.cpp" line="46"/>
        <source>the speed did not settle within %1 ms (±2 % of the step)</source>
        <translation>速度未在 %1 ms 内稳定（阶跃的 ±2 %）</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningVerdict.cpp" line="49"/>
        <source>it overshot by %1 % where %2 % was predicted (at most %3 points more are accepted)</source>
        <translation>超调为 %1 %，预测为 %2 %（最多只接受多出 %3 个百分点）</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningVerdict.cpp" line="60"/>
        <source>Measured: overshoot %1 % (predicted %2 %), settling time %3 (predicted %4), peak current %5 A.</source>
        <translation>实测：超调 %1 %（预测 %2 %），调节时间 %3（预测 %4），峰值电流 %5 A。</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningVerdict.cpp" line="70"/>
        <source>Check failed: %1.</source>
        <translation>检查未通过：%1。</translation>
    </message>
</context>
<context>
    <name>opentop::UnitLog</name>
    <message>
        <location filename="../ui/eol/UnitLog.cpp" line="19"/>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <location filename="../ui/eol/UnitLog.cpp" line="19"/>
        <source>Serial</source>
        <translation>序列号</translation>
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
        <translation>%1，未记录</translation>
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
        <translation>不是产品记录（format 不是 &quot;%1&quot;）</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitRecordJson.cpp" line="118"/>
        <source>unit record version %1 is not known to this program (it reads up to %2)</source>
        <translation>本程序不认识产品记录版本 %1（最高可读取 %2）</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitRecordJson.cpp" line="125"/>
        <source>the unit record has no serial number</source>
        <translation>产品记录没有序列号</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitRecordJson.cpp" line="139"/>
        <source>unknown unit status &quot;%1&quot;</source>
        <translation>未知的产品状态 &quot;%1&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitRecordJson.cpp" line="153"/>
        <source>unknown variant source &quot;%1&quot;</source>
        <translation>未知的机型来源“%1”</translation>
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
        <translation>开始前已取消</translation>
    </message>
    <message>
        <location filename="../model/station/UnitStartGate.cpp" line="80"/>
        <source>not connected to a bus</source>
        <translation>未连接总线</translation>
    </message>
    <message>
        <location filename="../model/station/UnitStartGate.cpp" line="85"/>
        <source>a drive of the station is not safe: %1</source>
        <translation>工作站有驱动器不安全：%1</translation>
    </message>
</context>
<context>
    <name>opentop::UnitValuesCsv</name>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="74"/>
        <source>the CSV file is larger than %1 MB</source>
        <translation>CSV 文件大于 %1 MB</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="76"/>
        <source>not a CSV text file (it holds NUL bytes)</source>
        <translation>不是 CSV 文本文件（含有 NUL 字节）</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="97"/>
        <source>line %1: a quoted field is not closed properly</source>
        <translation>第 %1 行：带引号的字段未正确结束</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="101"/>
        <source>line %1: the header must start with &quot;serial&quot;, not &quot;%2&quot;</source>
        <translation>第 %1 行：表头必须以 &quot;serial&quot; 开头，而不是 &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="105"/>
        <source>line %1: the header names no per-unit value</source>
        <translation>第 %1 行：表头中没有单台数值</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="107"/>
        <source>line %1: more than %2 columns</source>
        <translation>第 %1 行：超过 %2 列</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="111"/>
        <source>line %1: column %2 has no name</source>
        <translation>第 %1 行：第 %2 列没有名称</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="113"/>
        <source>line %1: column &quot;%2&quot; appears twice</source>
        <translation>第 %1 行：列 &quot;%2&quot; 出现了两次</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="122"/>
        <source>line %1: %2 fields, but the header has %3</source>
        <translation>第 %1 行：%2 个字段，但表头有 %3 个</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="128"/>
        <source>line %1: no serial number</source>
        <translation>第 %1 行：没有序列号</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="130"/>
        <source>line %1: serial number &quot;%2&quot; is already on line %3</source>
        <translation>第 %1 行：序列号 &quot;%2&quot; 已在第 %3 行出现</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="137"/>
        <source>the CSV file is empty; it needs a header &quot;serial,&lt;parameter&gt;,...&quot;</source>
        <translation>CSV 文件为空；需要表头 &quot;serial,&lt;parameter&gt;,...&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="151"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="193"/>
        <source>serial number &quot;%1&quot; is not in the CSV file</source>
        <translation>序列号 &quot;%1&quot; 不在 CSV 文件中</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="206"/>
        <source>%1: column &quot;%2&quot; is ambiguous, several positions have this per-unit value; name the column &quot;%3:%2&quot;</source>
        <translation>%1：列 &quot;%2&quot; 有歧义，多个位置都有该单台数值；请将列命名为 &quot;%3:%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="210"/>
        <source>%1: the CSV file has no column &quot;%2&quot; (or &quot;%3:%2&quot;) for this per-unit value</source>
        <translation>%1：CSV 文件中没有该单台数值的列 &quot;%2&quot;（或 &quot;%3:%2&quot;）</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="215"/>
        <source>line %1, column &quot;%2&quot;: no value for serial number &quot;%3&quot;</source>
        <translation>第 %1 行，列 &quot;%2&quot;：序列号 &quot;%3&quot; 没有值</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="225"/>
        <source>line %1, column &quot;%2&quot;: &quot;%3&quot; is not a number</source>
        <translation>第 %1 行，列 &quot;%2&quot;：&quot;%3&quot; 不是数字</translation>
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
        <translation>OpenTOP 用户指南</translation>
    </message>
    <message>
        <location filename="../ui/help/UserGuideDialog.cpp" line="28"/>
        <source> or </source>
        <translation> 或 </translation>
    </message>
    <message>
        <location filename="../ui/help/UserGuideDialog.cpp" line="31"/>
        <source>&lt;h2&gt;Commissioning a drive with OpenTOP&lt;/h2&gt;&lt;ol&gt;&lt;li&gt;&lt;b&gt;Connect.&lt;/b&gt; Bus ▸ Connect… chooses the serial port (or USB to RS-485 adapter), a Modbus TCP gateway or a simulated bus, with the bus&apos;s baud rate, parity and stop bits. The status bar says what the program is connected to; a simulated bus is marked as such.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Find the drives.&lt;/b&gt; Bus ▸ Scan bus (F5) asks every machine number 1–247; the drives that answer are identified and listed on the left with their state and control priority.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Select a drive.&lt;/b&gt; Its pages open on the right: Monitor (live values), the parameter pages of its profile, Test run and Alarms.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Edit settings.&lt;/b&gt; An edited field is marked as pending until it is written. Write page (or Drive ▸ Write all pending, Ctrl+W) writes and reads every value back to verify it; Revert drops the edits; Re-read (Ctrl+R) reads the drive again. A value the drive would refuse is never sent: the field says why.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Test-run the motor.&lt;/b&gt; The Test run page starts, stops and reverses the drive in communication priority and asks before the first start of each drive. Return the drive to I/O priority when done, so that the machine&apos;s own inputs control it again.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Stop.&lt;/b&gt; STOP ALL on the toolbar, or %1, stops every drive on the bus at once, from any window of the program.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Watch.&lt;/b&gt; View ▸ Trends (Ctrl+G) charts speeds and loads; View ▸ Bus overview shows every drive at a glance; View ▸ Traffic log (Ctrl+T) shows each frame on the bus with its meaning.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Keep the settings.&lt;/b&gt; Files ▸ Back up saves the settings of one drive or the whole bus to a file; Files ▸ Compare shows differences between drives, files and factory defaults; Files ▸ Restore writes a backup back after a preview.&lt;/li&gt;&lt;/ol&gt;&lt;p&gt;Every keyboard shortcut is listed in Help ▸ Keyboard shortcuts.&lt;/p&gt;&lt;h3&gt;More documentation&lt;/h3&gt;&lt;p&gt;The command line and the simulator: &lt;code&gt;man opentop&lt;/code&gt;, &lt;code&gt;man opentop-cli&lt;/code&gt;, &lt;code&gt;man opentop-sim&lt;/code&gt;.&lt;/p&gt;</source>
        <translation>&lt;h2&gt;用 OpenTOP 调试驱动器&lt;/h2&gt;&lt;ol&gt;&lt;li&gt;&lt;b&gt;连接。&lt;/b&gt;总线 ▸ 连接… 选择串口（或 USB 转 RS-485 适配器）、Modbus TCP 网关或模拟总线，并设定总线的波特率、校验位和停止位。状态栏显示程序当前的连接；模拟总线会明确标示。&lt;/li&gt;&lt;li&gt;&lt;b&gt;查找驱动器。&lt;/b&gt;总线 ▸ 扫描总线（F5）逐个询问站号 1–247；应答的驱动器会被识别，并与其状态和控制优先级一起列在左侧。&lt;/li&gt;&lt;li&gt;&lt;b&gt;选择驱动器。&lt;/b&gt;其页面在右侧打开：监视（实时值）、其设备描述中的各参数页面、试运行和报警。&lt;/li&gt;&lt;li&gt;&lt;b&gt;编辑设定。&lt;/b&gt;编辑过的字段在写入前标记为待写入。写入本页（或 驱动器 ▸ 写入全部待写入项，Ctrl+W）会写入每个值并回读校验；还原会放弃修改；重新读取（Ctrl+R）会重新读取驱动器。驱动器会拒绝的值绝不会发送：字段会说明原因。&lt;/li&gt;&lt;li&gt;&lt;b&gt;试运行电机。&lt;/b&gt;试运行页面在通信优先级下启动、停止驱动器并切换其方向，每台驱动器首次启动前会先确认。完成后请将驱动器恢复为 I/O 优先级，使设备自身的输入端子重新控制它。&lt;/li&gt;&lt;li&gt;&lt;b&gt;停止。&lt;/b&gt;工具栏上的“全部停止”或 %1 可在程序的任何窗口中立即停止总线上的所有驱动器。&lt;/li&gt;&lt;li&gt;&lt;b&gt;观察。&lt;/b&gt;视图 ▸ 趋势（Ctrl+G）绘制速度和负载曲线；视图 ▸ 总线总览 一目了然地显示每台驱动器；视图 ▸ 报文日志（Ctrl+T）显示总线上的每一帧及其含义。&lt;/li&gt;&lt;li&gt;&lt;b&gt;保存设定。&lt;/b&gt;文件 ▸ 备份 将一台驱动器或整条总线的设定保存到文件；文件 ▸ 比较 显示驱动器、文件和出厂默认值之间的差异；文件 ▸ 恢复 在预览后将备份写回。&lt;/li&gt;&lt;/ol&gt;&lt;p&gt;所有键盘快捷键都列在 帮助 ▸ 键盘快捷键 中。&lt;/p&gt;&lt;h3&gt;更多文档&lt;/h3&gt;&lt;p&gt;命令行和模拟器：&lt;code&gt;man opentop&lt;/code&gt;、&lt;code&gt;man opentop-cli&lt;/code&gt;、&lt;code&gt;man opentop-sim&lt;/code&gt;。&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../ui/help/UserGuideDialog.cpp" line="66"/>
        <source>&lt;h3&gt;Leaving a bus, and coming back after the link drops&lt;/h3&gt;&lt;p&gt;&lt;b&gt;Leaving.&lt;/b&gt; Quitting, Bus ▸ Disconnect or connecting elsewhere while drives run or are in communication priority names each of them and what will happen to it. The default stops every running drive, reads it back to confirm the stop, and then gives each drive back to its own inputs (I/O priority, read back), so that the machine works without OpenTOP. You may instead give control back only, leave the drives as they are, or stay.&lt;/p&gt;&lt;p&gt;&lt;b&gt;A lost link.&lt;/b&gt; When the adapter is pulled out or the gateway goes, every live value turns grey and a message says which drives were running or in communication priority when the link dropped, with the age of what is known. OpenTOP cannot stop them over a lost link: check the drive&apos;s STOP input, the emergency stop and the power on the machine. Bus ▸ Reconnect (Ctrl+R, also in the message and in the red bar) opens the same port again with the same drives, selected drive and page, reads every drive again and says at once if one is running. While connected, Ctrl+R re-reads the drive&apos;s pages.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;离开总线，以及连接丢失后重新连接&lt;/h3&gt;&lt;p&gt;&lt;b&gt;离开。&lt;/b&gt;在驱动器运行或处于通信优先级时退出、执行 总线 ▸ 断开连接 或连接到其他位置，会列出每台驱动器以及将对其执行的操作。默认会停止每台正在运行的驱动器、回读以确认已停止，然后将每台驱动器交还其自身的输入端子（I/O 优先级，回读确认），使设备无需 OpenTOP 也能运行。也可以选择仅交还控制权、保持驱动器现状，或留在当前连接。&lt;/p&gt;&lt;p&gt;&lt;b&gt;连接丢失。&lt;/b&gt;当适配器被拔出或网关消失时，所有实时数值都会变灰，并有消息说明连接丢失时哪些驱动器正在运行或处于通信优先级，以及已知数据的时间。OpenTOP 无法通过丢失的连接停止它们：请在设备上检查驱动器的停止输入端子、急停和电源。总线 ▸ 重新连接（Ctrl+R，消息和红色提示栏中也有）会以相同的驱动器、所选驱动器和页面重新打开同一个端口，重新读取所有驱动器，并立即告知是否有驱动器在运行。连接期间，Ctrl+R 会重新读取驱动器的页面。&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../ui/help/UserGuideDialog.cpp" line="86"/>
        <source>&lt;p&gt;The full description of the program: &lt;a href=&quot;%1&quot;&gt;%2&lt;/a&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;程序的完整说明：&lt;a href=&quot;%1&quot;&gt;%2&lt;/a&gt;&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>opentop::UserStore</name>
    <message>
        <location filename="../model/access/UserStore.cpp" line="43"/>
        <source>a user name is 1 to 64 letters, digits or . _ @ - (no spaces): &quot;%1&quot;</source>
        <translation>用户名为 1 至 64 个字母、数字或 . _ @ -（不能有空格）：“%1”</translation>
    </message>
</context>
<context>
    <name>opentop::ValueCodec</name>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="63"/>
        <source>%1: %2 is outside the recommended range %3; it is allowed and will be written</source>
        <translation>%1：%2 超出建议范围 %3；该值仍允许，将会写入</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="80"/>
        <source> (the variant is not known, so the value must suit %1; name the variant to use its own range)</source>
        <translation> （机型未知，因此该值必须适用于 %1；指定机型以使用其自身范围）</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="90"/>
        <source>%1: the allowed values depend on %2, which has not been read</source>
        <translation>%1：允许值取决于 %2，但该项尚未读取</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="95"/>
        <source>%1: value out of the register&apos;s range; allowed: %2</source>
        <translation>%1：值超出寄存器范围；允许：%2</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="107"/>
        <source>%1: %2 is not allowed; allowed: %3</source>
        <translation>%1：不允许 %2；允许：%3</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="119"/>
        <source>%1: expected %2 registers, got %3</source>
        <translation>%1：预期 %2 个寄存器，实际为 %3 个</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="149"/>
        <source>%1 is text, not a number</source>
        <translation>%1 是文本，不是数字</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="162"/>
        <source>%1: %2 is finer than the step of %3 %4; allowed: %5</source>
        <translation>%1：%2 比步长 %3 %4 更精细；允许：%5</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="195"/>
        <source>%1: at most %2 characters</source>
        <translation>%1：最多 %2 个字符</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="200"/>
        <source>%1: only printable ASCII characters are allowed</source>
        <translation>%1：只允许可打印的 ASCII 字符</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="210"/>
        <source>%1: no value given; allowed: %2</source>
        <translation>%1：未给出值；允许：%2</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="250"/>
        <source>%1: &quot;%2&quot; is only available when %3 is %4; allowed now: %5</source>
        <translation>%1：&quot;%2&quot; 仅在 %3 为 %4 时可用；当前允许：%5</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="263"/>
        <location filename="../model/profile/ValueCodec.cpp" line="283"/>
        <source>%1: &quot;%2&quot; is not a valid value; allowed: %3</source>
        <translation>%1：&quot;%2&quot; 不是有效值；允许：%3</translation>
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
        <translation>取决于 %1，但该项尚未知</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueFormat.cpp" line="67"/>
        <source>text of up to %1 characters</source>
        <translation>最多 %1 个字符的文本</translation>
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
        <translation>（无效）</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueFormat.cpp" line="92"/>
        <source>unknown code %1</source>
        <translation>未知代码 %1</translation>
    </message>
</context>
<context>
    <name>opentop::VariantCheck</name>
    <message>
        <location filename="../model/eol/VariantCheck.cpp" line="23"/>
        <source>proving the variant (%1)</source>
        <translation>正在证实机型（%1）</translation>
    </message>
</context>
<context>
    <name>opentop::VariantDecision</name>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="39"/>
        <source>the variant probe left the drive changed: %1</source>
        <translation>机型探测使驱动器留下改动：%1</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="44"/>
        <source>reported by the drive</source>
        <translation>由驱动器报告</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="53"/>
        <source>%1; named by %2</source>
        <translation>%1；由 %2 指定</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="57"/>
        <source>given for the unit by %1 (eol run --variant)</source>
        <translation>由 %1 为此产品指定（eol run --variant）</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="62"/>
        <source>confirmed by the operator %1 (the recipe asks the operator)</source>
        <translation>由操作员 %1 确认（配方要求操作员确认）</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="67"/>
        <source>the recipe&apos;s only variant, not proven on the bus</source>
        <translation>配方唯一的机型，未在总线上证实</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="74"/>
        <source>the family has no variant probe</source>
        <translation>此系列没有机型探测</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="76"/>
        <source>the probe leaves %1 (%2)</source>
        <translation>探测结果仍为 %1（%2）</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="81"/>
        <source>the drive does not report its variant and it was not proven (%1)</source>
        <translation>驱动器不报告机型，也未能证实（%1）</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="82"/>
        <source>the drive does not report its variant and it was not proven (%1); the recipe allows %2 and needs proof</source>
        <translation>驱动器不报告机型，也未能证实（%1）；配方允许 %2，且需要证实</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="90"/>
        <source>the drive is a %1 (%2), but %3 was given for it</source>
        <translation>驱动器是 %1（%2），但指定的是 %3</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="93"/>
        <source>a %1 (%2), the recipe allows %3</source>
        <translation>是 %1（%2），配方允许 %3</translation>
    </message>
</context>
<context>
    <name>opentop::VariantNeed</name>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="19"/>
        <source>%1 and %2 more</source>
        <translation>%1 及另外 %2 项</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="69"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="77"/>
        <source>Allowed %1 — %2</source>
        <translation>允许值 %1 — %2</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="94"/>
        <source>The allowed values of the settings you are changing depend on it.</source>
        <translation>您正在更改的设定，其允许值取决于机型。</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="97"/>
        <source>The backup file records it, and a restore checks the values against it.</source>
        <translation>备份文件会记录机型，恢复时会按机型检查数值。</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="100"/>
        <source>The speeds the motor may run at depend on it.</source>
        <translation>电机允许的运行速度取决于机型。</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="104"/>
        <source>Which drive is %1? It reports only &quot;%2&quot;, not whether it is a %3.</source>
        <translation>%1 是哪种驱动器？它只报告“%2”，不报告是否为 %3。</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="105"/>
        <source> or </source>
        <translation> 或 </translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="108"/>
        <source>Read it on the drive&apos;s rating plate. It is kept for this bus and asked once; without it every value must suit all of them.</source>
        <translation>请查看驱动器的铭牌。此设定会保存在此总线中，只询问一次；若不指定，每个值都必须符合所有机型。</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="112"/>
        <source>Last time on this bus it was set as %1.</source>
        <translation>上次在此总线上设为 %1。</translation>
    </message>
</context>
<context>
    <name>opentop::VariantProbe</name>
    <message>
        <location filename="../model/profile/VariantProbe.cpp" line="51"/>
        <source>unknown key &quot;%1&quot;</source>
        <translation>未知的键“%1”</translation>
    </message>
    <message>
        <location filename="../model/profile/VariantProbe.cpp" line="58"/>
        <source>needs &quot;parameter&quot;, a number &quot;value&quot; and &quot;refusedCode&quot;</source>
        <translation>需要 &quot;parameter&quot;、数值 &quot;value&quot; 和 &quot;refusedCode&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/VariantProbe.cpp" line="63"/>
        <source>no parameter &quot;%1&quot;</source>
        <translation>没有参数“%1”</translation>
    </message>
    <message>
        <location filename="../model/profile/VariantProbe.cpp" line="67"/>
        <source>%1 must be a readable, writable setting that no role names (never a command or a motion register)</source>
        <translation>%1 必须是可读写、且未被任何角色使用的设定（绝不能是命令或运转寄存器）</translation>
    </message>
    <message>
        <location filename="../model/profile/VariantProbe.cpp" line="77"/>
        <source>%1 = %2 must be allowed on some variants and refused on others</source>
        <translation>%1 = %2 必须在部分机型允许、在其他机型拒绝</translation>
    </message>
</context>
<context>
    <name>opentop::VariantProber</name>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="47"/>
        <location filename="../model/session/VariantProber.cpp" line="85"/>
        <source>%1 cannot be read: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="63"/>
        <source>%1 still holds %2 from a variant probe that was interrupted, and cannot be set back to %3 (%4): set it to %3 before this drive is used</source>
        <translation>%1 仍保留中断的机型探测写入的 %2，且无法改回 %3（%4）：使用此驱动器前请将其设为 %3</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="71"/>
        <source>%1 set back from %2 to %3, left by a variant probe that was interrupted</source>
        <translation>%1 已由 %2 改回 %3（之前中断的机型探测所留下）</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="102"/>
        <source>not probed: the original value cannot be kept while it is (%1)</source>
        <translation>未探测：探测期间无法保存原值（%1）</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="123"/>
        <source>the probe %1 was not answered as the manual says: %2</source>
        <translation>机型探测 %1 的应答与手册所述不符：%2</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="147"/>
        <source>%1 could not be set back to %2 after the variant probe (%3): set it to %2 before this drive is used</source>
        <translation>机型探测后无法将 %1 改回 %2（%3）：使用此驱动器前请将其设为 %2</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="152"/>
        <source>%1 accepted, %2 written back</source>
        <translation>%1 被接受，已写回 %2</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="160"/>
        <source>%1 refused (%2)</source>
        <translation>%1 被拒绝（%2）</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="171"/>
        <source>%1 does not read back as %2 after the variant probe (%3): set it to %2 before this drive is used</source>
        <translation>机型探测后 %1 读回不是 %2（%3）：使用此驱动器前请将其设为 %2</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="181"/>
        <source>the probe did not decide</source>
        <translation>探测无法判定</translation>
    </message>
</context>
<context>
    <name>opentop::VariantQuestion</name>
    <message>
        <location filename="../ui/bus/VariantQuestion.cpp" line="29"/>
        <source>Which drive is it?</source>
        <translation>这是哪种驱动器？</translation>
    </message>
    <message>
        <location filename="../ui/bus/VariantQuestion.cpp" line="42"/>
        <source>Not known: check against every variant</source>
        <translation>不确定：按所有机型检查</translation>
    </message>
    <message>
        <location filename="../ui/bus/VariantQuestion.cpp" line="65"/>
        <source>the variant of %1 was not given</source>
        <translation>未指定 %1 的机型</translation>
    </message>
</context>
<context>
    <name>opentop::VerdictLook</name>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="16"/>
        <source>READY</source>
        <translation>就绪</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="17"/>
        <source>TESTING</source>
        <translation>测试中</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="18"/>
        <source>NOT STARTED</source>
        <translation>未开始</translation>
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
        <translation>工位错误</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="24"/>
        <source>ABORTED</source>
        <translation>已中止</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="25"/>
        <source>NOT RECORDED</source>
        <translation>未记录</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="66"/>
        <source>Unit %1</source>
        <translation>产品 %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="69"/>
        <source>%1
Not a verdict on the unit: fix the cause and test it again.</source>
        <translation>%1
这不是对产品的判定：请排除原因后重新测试。</translation>
    </message>
</context>
<context>
    <name>opentop::YieldReport</name>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="100"/>
        <source>%1 rev. %2</source>
        <translation>%1 版本 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="105"/>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="111"/>
        <source>first-pass yield – (no serial tested yet)</source>
        <translation>直通率 –（尚未测试任何序列号）</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="112"/>
        <source>first-pass yield %1 (%2 of %3 serials) · second-pass %4 · last-pass %5</source>
        <translation>直通率 %1（%3 个序列号中 %2 个）· 二次合格率 %4 · 最终合格率 %5</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="125"/>
        <source>still running (or its station has not restarted since it stopped)</source>
        <translation>仍在进行中（或其工位停止后尚未重新启动）</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="127"/>
        <source>interrupted</source>
        <translation>已中断</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="129"/>
        <source>aborted</source>
        <translation>已中止</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="131"/>
        <source>station error, no reason recorded</source>
        <translation>工位错误，未记录原因</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="133"/>
        <source>failed, no reason recorded</source>
        <translation>不合格，未记录原因</translation>
    </message>
</context>
</TS>
