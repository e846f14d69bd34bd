<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ja">
<context>
    <name>Freshness</name>
    <message>
        <location filename="../model/session/Freshness.cpp" line="29"/>
        <location filename="../model/session/Freshness.cpp" line="31"/>
        <source>%1 s old</source>
        <translation>%1 s前</translation>
    </message>
    <message>
        <location filename="../model/session/Freshness.cpp" line="33"/>
        <source>%1 min old</source>
        <translation>%1 min前</translation>
    </message>
    <message>
        <location filename="../model/session/Freshness.cpp" line="34"/>
        <source>%1 h old</source>
        <translation>%1 h前</translation>
    </message>
    <message>
        <location filename="../model/session/Freshness.cpp" line="40"/>
        <source>never read</source>
        <translation>未読出し</translation>
    </message>
    <message>
        <location filename="../model/session/Freshness.cpp" line="41"/>
        <source>last answer %1 (%2)</source>
        <translation>最終応答 %1 (%2)</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/main.cpp" line="60"/>
        <source>Commissioning tool for RS-485 Modbus-RTU motor drives.</source>
        <translation>RS-485 Modbus-RTU モータドライバ用立上げツール。</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="64"/>
        <source>Language of the program: %1 (default: the language menu&apos;s choice, else the system&apos;s).</source>
        <translation>プログラムの言語: %1 (既定: 言語メニューでの選択、なければシステムの言語)。</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="79"/>
        <source>Open the bus overview and the trends of every drive.</source>
        <translation>バス一覧と全ドライバのトレンドを開きます。</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="80"/>
        <source>Monitoring poll interval in milliseconds.</source>
        <translation>モニタのポーリング周期（ミリ秒）。</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="83"/>
        <source>Quit after this many seconds and print the monitoring statistics (for measurements).</source>
        <translation>指定した秒数の後に終了し、モニタ統計を出力します（測定用）。</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="87"/>
        <source>Print the monitoring totals every this many seconds (for measurements).</source>
        <translation>指定した秒数ごとにモニタの合計を出力します（測定用）。</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="97"/>
        <source>--poll-ms needs a number of milliseconds</source>
        <translation>--poll-ms にはミリ秒数を指定してください</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="102"/>
        <source>--quit-after needs a number of seconds</source>
        <translation>--quit-after には秒数を指定してください</translation>
    </message>
    <message>
        <location filename="../app/gui/MonitorOptions.cpp" line="107"/>
        <source>--stats-every needs a number of seconds</source>
        <translation>--stats-every には秒数を指定してください</translation>
    </message>
    <message>
        <location filename="../app/gui/StartupProbe.cpp" line="23"/>
        <source>Print how long the start took once the window shows the bus&apos;s drives, then quit (for measurements).</source>
        <translation>ウィンドウにバスのドライバが表示された時点で起動にかかった時間を出力し、終了します（測定用）。</translation>
    </message>
</context>
<context>
    <name>opentop</name>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="71"/>
        <source>not read</source>
        <translation>未読出し</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="91"/>
        <source>No alarm is active.</source>
        <translation>アラームは発生していません。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="93"/>
        <source>Alarm active: %1 %2.</source>
        <translation>アラーム発生中: %1 %2。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="96"/>
        <source>An alarm is active.</source>
        <translation>アラームが発生しています。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="99"/>
        <source>This drive is set to clear alarms by a power restart only (%1): Alarm-Reset clears none of them.</source>
        <translation>このドライバはアラームを電源再投入でのみ解除する設定です (%1)。Alarm-Reset では解除できません。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="106"/>
        <source>%1: could not be read: %2</source>
        <translation>%1: 読み出せません: %2</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="110"/>
        <source>%1: no records.</source>
        <translation>%1: 履歴なし。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="113"/>
        <source>%1: %2 of %3 records, newest first</source>
        <translation>%1: %3 件中 %2 件（新しい順）</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="118"/>
        <source>#</source>
        <translation>No.</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="118"/>
        <source>Code</source>
        <translation>コード</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="118"/>
        <source>Panel</source>
        <translation>パネル表示</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="118"/>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="118"/>
        <source>Cleared by</source>
        <translation>解除方法</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="125"/>
        <source>unknown code</source>
        <translation>不明なコード</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="132"/>
        <source>Cause: %1</source>
        <translation>原因: %1</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="134"/>
        <source>Remedy: %1</source>
        <translation>対策: %1</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="136"/>
        <source>To clear: %1</source>
        <translation>解除方法: %1</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="142"/>
        <source>Communication error register (%1): could not be read.</source>
        <translation>通信エラーレジスタ (%1): 読み出せません。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="146"/>
        <source>Communication error register (%1): none (0).</source>
        <translation>通信エラーレジスタ (%1): なし (0)。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="149"/>
        <source>Communication error register (%1): %2, not a known code.</source>
        <translation>通信エラーレジスタ (%1): %2（既知のコードではありません）。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="153"/>
        <source>Communication error register (%1): %2 %3
  Cause: %4
  Remedy: %5</source>
        <translation>通信エラーレジスタ (%1): %2 %3
  原因: %4
  対策: %5</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="27"/>
        <source>Machine-readable JSON on standard output.</source>
        <translation>機械可読な JSON を標準出力に出力します。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="28"/>
        <source>Print every frame sent and received on standard error.</source>
        <translation>送受信したすべてのフレームを標準エラー出力に表示します。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="30"/>
        <source>Drive variant where the drive does not report it: VARIANT, or ID=VARIANT,... (e.g. dbu400, 150=dbu400).</source>
        <translation>機種を通知しないドライバの機種: VARIANT、または ID=VARIANT,...（例: dbu400、150=dbu400）。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="32"/>
        <source>VARIANT</source>
        <translation>VARIANT</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="34"/>
        <source>The drives on the bus, e.g. 1,3,5-7 (default: OPENTOP_BUS_DRIVES, else the drives the last scan of this connection found): before a write or command, their communication group is read to name every drive it also reaches.</source>
        <translation>バス上のドライバ。例: 1,3,5-7（既定: OPENTOP_BUS_DRIVES、なければこの接続の前回のスキャンで見つかったドライバ）。書込みやコマンドの前に通信グループを読み出し、同時に届くすべてのドライバを示します。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="37"/>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="39"/>
        <source>Write or command a drive that can be a communication group parent although the drives on the bus are not known (no --bus-drives and no scan of this connection): drives in its group execute it too, unnamed.</source>
        <translation>バス上のドライバが不明でも（--bus-drives なし、この接続のスキャンなし）、通信グループの親になりうるドライバに書込み・コマンドを行います。グループ内のドライバも名前を示されないまま実行します。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="43"/>
        <source>Show this help, or a command&apos;s help after the command.</source>
        <translation>このヘルプを表示します。コマンドの後に付けるとそのコマンドのヘルプを表示します。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="44"/>
        <source>Show the version.</source>
        <translation>バージョンを表示します。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="48"/>
        <source>Language of the human output: en, zh_TW, zh_CN, ko, ja (default: the system&apos;s). --json output is the same in every language.</source>
        <translation>人が読む出力の言語: en、zh_TW、zh_CN、ko、ja (既定: システムの言語)。--json の出力はどの言語でも同じです。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="50"/>
        <source>CODE</source>
        <translation>CODE</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="28"/>
        <source>stopped</source>
        <translation>停止</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="30"/>
        <source>STILL RUNNING</source>
        <translation>まだ運転中</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="32"/>
        <source>no answer</source>
        <translation>応答なし</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="38"/>
        <source>top level</source>
        <translation>最上位</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="41"/>
        <source>&quot;schema&quot; must be 1</source>
        <translation>&quot;schema&quot; は 1 でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="52"/>
        <source>&quot;family&quot; must be a lower-case id</source>
        <translation>&quot;family&quot; は小文字の ID でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="60"/>
        <source>serial.parity must be N, E or O</source>
        <translation>serial.parity は N、E、O のいずれかでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="64"/>
        <source>serial: baud must be 1200–115200 and stopBits 1 or 2</source>
        <translation>serial: baud は 1200–115200、stopBits は 1 または 2 でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="76"/>
        <source>serial.formats: &quot;%1&quot; is not a format such as 8N1 or 8E1</source>
        <translation>serial.formats: &quot;%1&quot; は 8N1 や 8E1 のような形式ではありません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="80"/>
        <source>serial.formats must hold the default format %1</source>
        <translation>serial.formats には既定の形式 %1 が含まれている必要があります</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="84"/>
        <source>serial.powerOnDelayMs must be 0–60000</source>
        <translation>serial.powerOnDelayMs は 0–60000 でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="97"/>
        <source>limits: maxReadRegisters 1–125, maxWriteRegisters 1–123</source>
        <translation>limits: maxReadRegisters は 1–125、maxWriteRegisters は 1–123 です</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="99"/>
        <source>limits: slaves must lie in 1–247</source>
        <translation>limits: slaves は 1–247 の範囲でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="114"/>
        <source>variants[%1] needs id, model and label</source>
        <translation>variants[%1] には id、model、label が必要です</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="116"/>
        <source>variants[%1]: id &quot;%2&quot; repeated</source>
        <translation>variants[%1]: id &quot;%2&quot; が重複しています</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="127"/>
        <source>groups[%1] needs a unique id and a label</source>
        <translation>groups[%1] には一意の id と label が必要です</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="138"/>
        <source>readBlocks[%1] needs function 3 or 4 and first ≤ last</source>
        <translation>readBlocks[%1] には function 3 または 4 と first ≤ last が必要です</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="182"/>
        <source>%1 has no name</source>
        <translation>%1 に名前がありません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="184"/>
        <source>%1: reset must be one of %2</source>
        <translation>%1: reset は %2 のいずれかでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="187"/>
        <source>%1: code %2 repeated</source>
        <translation>%1: コード %2 が重複しています</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="203"/>
        <source>%1: unknown parameter &quot;%2&quot;</source>
        <translation>%1: 不明なパラメータ &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="231"/>
        <source>%1 must be a parameter name, a list of names or an object</source>
        <translation>%1 はパラメータ名、名前のリスト、またはオブジェクトでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="240"/>
        <source>%1: &quot;%2&quot; has no bit field &quot;%3&quot;</source>
        <translation>%1: &quot;%2&quot; にビットフィールド &quot;%3&quot; はありません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="246"/>
        <source>%1: %2 is not a value &quot;%3&quot; can be written with</source>
        <translation>%1: %2 は &quot;%3&quot; で書き込める値ではありません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="264"/>
        <source>decelerationKnobs need the &quot;selected&quot; role</source>
        <translation>decelerationKnobs には &quot;selected&quot; ロールが必要です</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="280"/>
        <source>%1 needs &quot;selected&quot; and &quot;maxSeconds&quot;</source>
        <translation>%1 には &quot;selected&quot; と &quot;maxSeconds&quot; が必要です</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="283"/>
        <source>%1: &quot;selected&quot; %2 is not a value of the &quot;selected&quot; role, or repeated</source>
        <translation>%1: &quot;selected&quot; %2 は &quot;selected&quot; ロールの値ではないか、重複しています</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="288"/>
        <source>%1: &quot;maxSeconds&quot; must be more than 0 and at most 600</source>
        <translation>%1: &quot;maxSeconds&quot; は 0 より大きく 600 以下でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="320"/>
        <source>%1: &quot;light&quot; must be one of %2, each once</source>
        <translation>%1: &quot;light&quot; は %2 のいずれかで、それぞれ 1 回だけでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="323"/>
        <source>%1: &quot;colour&quot; must be #rrggbb</source>
        <translation>%1: &quot;colour&quot; は #rrggbb でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="325"/>
        <source>%1: &quot;label&quot; and &quot;meaning&quot; must not be empty</source>
        <translation>%1: &quot;label&quot; と &quot;meaning&quot; は空にできません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="57"/>
        <source> and %1 more</source>
        <translation> ほか %1 件</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="28"/>
        <source>not reached</source>
        <translation>未到達</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="35"/>
        <source>error: %1</source>
        <translation>エラー: %1</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="36"/>
        <source>nothing was written</source>
        <translation>何も書き込んでいません</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="60"/>
        <source>NOT RECORDED (%1)</source>
        <translation>未記録（%1）</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="62"/>
        <source>%1 (kept on this station)</source>
        <translation>%1（このステーションに保管）</translation>
    </message>
</context>
<context>
    <name>opentop::AboutDialog</name>
    <message>
        <location filename="../ui/help/AboutDialog.cpp" line="20"/>
        <source>About OpenTOP</source>
        <translation>OpenTOP について</translation>
    </message>
    <message>
        <location filename="../ui/help/AboutDialog.cpp" line="22"/>
        <source>&lt;h2&gt;OpenTOP %1&lt;/h2&gt;&lt;p&gt;Commissioning tool for RS-485 Modbus-RTU motor drives: TROY DBU brushless drives and a DC motor PID controller.&lt;/p&gt;&lt;p&gt;Copyright © the OpenTOP developers.&lt;br&gt;Licence: GNU General Public License, version 3 or any later version (GPL-3.0-or-later). This program comes with ABSOLUTELY NO WARRANTY; it is free software, and you are welcome to redistribute it under the terms of that licence.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Built with&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;Qt %2 (run time; built with %3): GNU Lesser General Public License, version 3 (LGPL-3.0-only); Qt Charts: GNU General Public License, version 3 (GPL-3.0-only)&lt;/li&gt;&lt;li&gt;libmodbus %4: GNU Lesser General Public License, version 2.1 or later (LGPL-2.1-or-later)&lt;/li&gt;&lt;li&gt;GoogleTest (tests only): BSD 3-Clause licence&lt;/li&gt;&lt;/ul&gt;</source>
        <translation>&lt;h2&gt;OpenTOP %1&lt;/h2&gt;&lt;p&gt;RS-485 Modbus-RTU モータドライバ用立上げツール: TROY DBU ブラシレスドライバおよび DC モータ PID コントローラに対応。&lt;/p&gt;&lt;p&gt;Copyright © the OpenTOP developers.&lt;br&gt;ライセンス: GNU General Public License バージョン 3 またはそれ以降のバージョン (GPL-3.0-or-later)。本プログラムは一切無保証です (ABSOLUTELY NO WARRANTY)。本プログラムはフリーソフトウェアであり、このライセンスの条件のもとで再配布できます。&lt;/p&gt;&lt;p&gt;&lt;b&gt;使用ソフトウェア&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;Qt %2（実行時。ビルド時は %3）: GNU Lesser General Public License バージョン 3 (LGPL-3.0-only)、Qt Charts: GNU General Public License バージョン 3 (GPL-3.0-only)&lt;/li&gt;&lt;li&gt;libmodbus %4: GNU Lesser General Public License バージョン 2.1 以降 (LGPL-2.1-or-later)&lt;/li&gt;&lt;li&gt;GoogleTest（テストのみ）: BSD 3-Clause ライセンス&lt;/li&gt;&lt;/ul&gt;</translation>
    </message>
    <message>
        <location filename="../ui/help/AboutDialog.cpp" line="45"/>
        <source>About &amp;Qt</source>
        <translation>Qt について(&amp;Q)</translation>
    </message>
</context>
<context>
    <name>opentop::AccessCheck</name>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="27"/>
        <source>%1 (%2) may not %3: it needs the %4 role or higher</source>
        <translation>%1 (%2) は%3ことができません: %4 以上のロールが必要です</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="39"/>
        <location filename="../model/access/AccessCheck.cpp" line="49"/>
        <location filename="../model/access/AccessCheck.cpp" line="122"/>
        <source>the users cannot be read from the results database: %1</source>
        <translation>結果データベースからユーザーを読み込めません: %1</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="54"/>
        <source>wrong user name or password</source>
        <translation>ユーザー名またはパスワードが違います</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="56"/>
        <source>user &quot;%1&quot;: wrong user name or password</source>
        <translation>ユーザー &quot;%1&quot;: ユーザー名またはパスワードが違います</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="60"/>
        <source>user %1 is disabled</source>
        <translation>ユーザー %1 は無効です</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="98"/>
        <source>logged in as %1</source>
        <translation>%1 としてログイン</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="123"/>
        <source>user %1 is not an active user</source>
        <translation>ユーザー %1 は有効なユーザーではありません</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="136"/>
        <source>recipe %1 rev. %2, checksum %3</source>
        <translation>レシピ %1 rev. %2、チェックサム %3</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="142"/>
        <source>this station has no users yet: an approval names its approver, so add users first (opentop-cli eol user add)</source>
        <translation>このステーションにはまだユーザーがいません: 承認には承認者が記録されるため、先にユーザーを追加してください (opentop-cli eol user add)</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="151"/>
        <source>the approval was not recorded: %1</source>
        <translation>承認は記録されませんでした: %1</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="155"/>
        <source>%1; approval %2</source>
        <translation>%1; 承認 %2</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="184"/>
        <source>the first user must be an administrator (--role administrator): they add everyone else</source>
        <translation>最初のユーザーは管理者でなければなりません (--role administrator): 他の全員は管理者が追加します</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="189"/>
        <source>add user %1</source>
        <translation>ユーザー %1 の追加</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="196"/>
        <source>user %1 exists already</source>
        <translation>ユーザー %1 はすでに存在します</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="202"/>
        <source>user %1 (%2) added as %3</source>
        <translation>ユーザー %1 (%2) を %3 として追加しました</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="214"/>
        <source>enable user %1</source>
        <translation>ユーザー %1 の有効化</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="214"/>
        <source>disable user %1</source>
        <translation>ユーザー %1 の無効化</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="216"/>
        <location filename="../model/access/AccessCheck.cpp" line="256"/>
        <source>there are no users yet</source>
        <translation>ユーザーはまだいません</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="223"/>
        <location filename="../model/access/AccessCheck.cpp" line="262"/>
        <source>no user %1</source>
        <translation>ユーザー %1 はいません</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="228"/>
        <source>%1 is the last active administrator: add another first</source>
        <translation>%1 は最後の有効な管理者です: 先に別の管理者を追加してください</translation>
    </message>
    <message>
        <location filename="../model/access/AccessCheck.cpp" line="254"/>
        <source>set the password of %1</source>
        <translation>%1 のパスワード設定</translation>
    </message>
</context>
<context>
    <name>opentop::AccessPolicy</name>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="76"/>
        <source>operator</source>
        <translation>作業者</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="78"/>
        <source>technician</source>
        <translation>技術者</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="80"/>
        <source>engineer</source>
        <translation>エンジニア</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="84"/>
        <source>administrator</source>
        <translation>管理者</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="96"/>
        <source>test units</source>
        <translation>製品を検査する</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="98"/>
        <source>reset an alarm and retry</source>
        <translation>アラームをリセットして再試行する</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="100"/>
        <source>override a retest limit</source>
        <translation>再検査回数の上限を解除する</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="102"/>
        <source>leave production mode</source>
        <translation>生産モードを終了する</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="104"/>
        <source>open or edit a recipe</source>
        <translation>レシピを開く・編集する</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="106"/>
        <source>approve a recipe</source>
        <translation>レシピを承認する</translation>
    </message>
    <message>
        <location filename="../model/access/AccessPolicy.cpp" line="110"/>
        <source>manage users</source>
        <translation>ユーザーを管理する</translation>
    </message>
</context>
<context>
    <name>opentop::AddressSwitches</name>
    <message>
        <location filename="../model/profile/AddressSwitches.cpp" line="66"/>
        <source>address.names: every switch needs a name</source>
        <translation>address.names: すべてのスイッチに名前が必要です</translation>
    </message>
    <message>
        <location filename="../model/profile/AddressSwitches.cpp" line="74"/>
        <source>address.switches must be &quot;hex-rotary&quot; or &quot;binary-dip&quot;</source>
        <translation>address.switches は &quot;hex-rotary&quot; または &quot;binary-dip&quot; でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/AddressSwitches.cpp" line="78"/>
        <source>address.names: 1–%1 switches for this notation</source>
        <translation>address.names: この表記ではスイッチは 1–%1 個です</translation>
    </message>
    <message>
        <location filename="../model/profile/AddressSwitches.cpp" line="81"/>
        <source>address: the switches (%1) cannot set machine number %2</source>
        <translation>address: このスイッチ (%1) では局番 %2 を設定できません</translation>
    </message>
</context>
<context>
    <name>opentop::AlarmBanner</name>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="16"/>
        <source>Show</source>
        <translation>表示</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="17"/>
        <source>Dismiss</source>
        <translation>閉じる</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="24"/>
        <source>Open the drive&apos;s alarm history</source>
        <translation>ドライバのアラーム履歴を開きます</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="25"/>
        <source>Hide this alarm until it is cleared; a new alarm shows again</source>
        <translation>解除されるまでこのアラームを非表示にします。新しいアラームは再び表示されます</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="85"/>
        <source>Machine %1: %2 %3 — %4</source>
        <translation>局番 %1: %2 %3 — %4</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="89"/>
        <source>Machine %1: %2 %3</source>
        <translation>局番 %1: %2 %3</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="91"/>
        <source>Machine %1: alarm %2h (not in the alarm table)</source>
        <translation>局番 %1: アラーム %2h（アラーム表にありません）</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmBanner.cpp" line="95"/>
        <source>Machine %1: an alarm is active</source>
        <translation>局番 %1: アラーム発生中</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/alarms/AlarmBanner.cpp" line="98"/>
        <source>(%n more drive(s) with an alarm)</source>
        <translation>
            <numerusform>（他に %n 台のドライバでアラーム発生中）</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::AlarmExport</name>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="50"/>
        <source>Machine</source>
        <translation>局番</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="50"/>
        <source>Model</source>
        <translation>型式</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="50"/>
        <source>Kind</source>
        <translation>種別</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="50"/>
        <source>Record</source>
        <translation>履歴</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="50"/>
        <source>Code</source>
        <translation>コード</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="50"/>
        <source>Machine name</source>
        <translation>機械名</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="51"/>
        <source>Panel code</source>
        <translation>パネル表示コード</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="51"/>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="51"/>
        <source>Cleared by</source>
        <translation>解除方法</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="51"/>
        <source>Cause</source>
        <translation>原因</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="51"/>
        <source>Remedy</source>
        <translation>対策</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="54"/>
        <source>alarm</source>
        <translation>アラーム</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="55"/>
        <source>warning</source>
        <translation>警告</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="63"/>
        <source>unknown code</source>
        <translation>不明なコード</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="109"/>
        <source>machine %1: %2</source>
        <translation>局番 %1: %2</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/alarms/AlarmExport.cpp" line="132"/>
        <source>%n record(s) of %1 drive(s) written to %2.</source>
        <translation>
            <numerusform>%1 台のドライバの履歴 %n 件を %2 に書き込みました。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmExport.cpp" line="137"/>
        <source>Not everything could be read: %1</source>
        <translation>一部を読み出せませんでした: %1</translation>
    </message>
</context>
<context>
    <name>opentop::AlarmHistory</name>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="68"/>
        <source>%1: erases the %2</source>
        <translation>%1: %2を消去します</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="107"/>
        <source>%1 drives have no alarm reset command</source>
        <translation>%1 ドライバにはアラームリセットコマンドがありません</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="182"/>
        <source>The alarm</source>
        <translation>アラーム</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="184"/>
        <source>%1 is cleared.</source>
        <translation>%1 は解除されました。</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="185"/>
        <source>No alarm was active; nothing to clear.</source>
        <translation>発生中のアラームはありません。解除するものはありません。</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="188"/>
        <source>%1 is still active: only a power cycle clears it. %2</source>
        <translation>%1 はまだ発生中です: 電源再投入でのみ解除できます。%2</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="193"/>
        <source>%1 is still active: the drive is set to clear alarms by a power restart only (%2). Remove the cause, turn the power off, wait 5 s and turn it on again; or change that setting to allow the reset command.</source>
        <translation>%1 はまだ発生中です: このドライバはアラームを電源再投入でのみ解除する設定です (%2)。原因を取り除き、電源を切って 5 s 待ってから再投入してください。または、リセットコマンドで解除できるように設定を変更してください。</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="199"/>
        <source>%1 is still active: its cause is still present%2. Remove the cause and turn off the start signal, then reset again.</source>
        <translation>%1 はまだ発生中です: 原因が残っています%2。原因を取り除き、運転信号をオフにしてから再度リセットしてください。</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="205"/>
        <source>The reset was accepted; whether an alarm is still active could not be read.</source>
        <translation>リセットは受け付けられましたが、アラームがまだ発生中かどうかを読み出せませんでした。</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="207"/>
        <source>The reset failed: %1</source>
        <translation>リセットに失敗しました: %1</translation>
    </message>
    <message>
        <location filename="../model/alarms/AlarmHistory.cpp" line="210"/>
        <source>(The drive refused the reset: %1)</source>
        <translation>（ドライバがリセットを拒否しました: %1）</translation>
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
        <translation>No.</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="50"/>
        <source>Code</source>
        <translation>コード</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="50"/>
        <source>Panel</source>
        <translation>パネル表示</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="50"/>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="50"/>
        <source>Cleared by</source>
        <translation>解除方法</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="67"/>
        <source>Cause and remedy</source>
        <translation>原因と対策</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="68"/>
        <source>Communication error register</source>
        <translation>通信エラーレジスタ</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="75"/>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="115"/>
        <source>Select a record to see its cause and remedy.</source>
        <translation>履歴を選択すると原因と対策を表示します。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="76"/>
        <source>Not read yet.</source>
        <translation>未読出しです。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="126"/>
        <source>This drive has no communication error register.</source>
        <translation>このドライバには通信エラーレジスタがありません。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="128"/>
        <source>%1: could not be read.</source>
        <translation>%1: 読み出せません。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="130"/>
        <source>%1: no error (0).</source>
        <translation>%1: エラーなし (0)。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="133"/>
        <source>%1: %2, not a known code.</source>
        <translation>%1: %2（既知のコードではありません）。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="135"/>
        <source>%1: %2 %3
Cause: %4
Remedy: %5</source>
        <translation>%1: %2 %3
原因: %4
対策: %5</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="147"/>
        <source>No alarm records</source>
        <translation>アラーム履歴なし</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="147"/>
        <source>No warning records</source>
        <translation>警告履歴なし</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="153"/>
        <source>%1: could not be read: %2</source>
        <translation>%1: 読み出せません: %2</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="156"/>
        <source>%1: %2 of %3 records, newest first</source>
        <translation>%1: %3 件中 %2 件（新しい順）</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="167"/>
        <source>unknown code</source>
        <translation>不明なコード</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="196"/>
        <source>Record %1: code %2 is not in the %3 table.</source>
        <translation>履歴 %1: コード %2 は %3 表にありません。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="201"/>
        <source>%1 %2 (record %3)</source>
        <translation>%1 %2（履歴 %3）</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="203"/>
        <source>Cause: %1</source>
        <translation>原因: %1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="205"/>
        <source>Remedy: %1</source>
        <translation>対策: %1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmRecordsView.cpp" line="207"/>
        <source>To clear: %1</source>
        <translation>解除方法: %1</translation>
    </message>
</context>
<context>
    <name>opentop::AlarmsCommand</name>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="165"/>
        <source>Show alarm and warning histories with causes and remedies; reset, erase</source>
        <translation>アラーム・警告履歴を原因・対策とともに表示、リセット、消去</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="172"/>
        <source>Send the alarm reset command, then tell whether the alarm is cleared or needs a power cycle (needs --yes; exit 4 when it stays active).</source>
        <translation>アラームリセットコマンドを送信し、アラームが解除されたか電源再投入が必要かを表示します（--yes が必要。解除されない場合は終了コード 4）。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="174"/>
        <source>Erase the alarm and warning records (needs --yes).</source>
        <translation>アラーム履歴と警告履歴を消去します（--yes が必要）。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="175"/>
        <source>Confirm --reset and --clear-records.</source>
        <translation>--reset と --clear-records を確定します。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="186"/>
        <source>error: usage: %1 (one machine number)</source>
        <translation>エラー: 使い方: %1（局番を 1 つ指定）</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="194"/>
        <source>error: %1</source>
        <translation>エラー: %1</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="200"/>
        <source>error: machine number %1 (%2) keeps no alarm or warning records</source>
        <translation>エラー: 局番 %1 (%2) はアラーム・警告履歴を保持していません</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="207"/>
        <source>error: %1 drives have no %2 command</source>
        <translation>エラー: %1 ドライバには %2 コマンドがありません</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="209"/>
        <source>alarm reset</source>
        <translation>アラームリセット</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="209"/>
        <source>record erase</source>
        <translation>履歴消去</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="220"/>
        <source>These change machine number %1; add --yes to send them:</source>
        <translation>以下の操作は局番 %1 のドライバを変更します。送信するには --yes を付けてください:</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="224"/>
        <source>— clears the active alarm if its cause is gone and it is not one that only a power cycle clears</source>
        <translation>— 原因が取り除かれ、かつ電源再投入でのみ解除されるアラームでなければ、発生中のアラームを解除します</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="249"/>
        <source>Machine number %1 (%2)</source>
        <translation>局番 %1 (%2)</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="277"/>
        <source>Alarm reset: %1</source>
        <translation>アラームリセット: %1</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="300"/>
        <source>Erased: %1 (%2 records); %3</source>
        <translation>消去: %1（%2 件）。%3</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="303"/>
        <source>read back empty.</source>
        <translation>読み戻し結果は空です。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="304"/>
        <source>NOT empty when read back.</source>
        <translation>読み戻し結果が空ではありません。</translation>
    </message>
    <message>
        <location filename="../cli/AlarmsCommand.cpp" line="307"/>
        <source>Erasing failed: %1</source>
        <translation>消去に失敗しました: %1</translation>
    </message>
</context>
<context>
    <name>opentop::AlarmsPage</name>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="35"/>
        <source>&amp;Re-read</source>
        <translation>再読出し(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="36"/>
        <source>Reset &amp;alarm…</source>
        <translation>アラームリセット(&amp;A)…</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="37"/>
        <source>&amp;Clear records…</source>
        <translation>履歴消去(&amp;C)…</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="41"/>
        <source>Alarms and warnings of machine %1 (%2)</source>
        <translation>局番 %1 (%2) のアラームと警告</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="67"/>
        <source>Send the alarm reset command; tells whether the alarm is cleared or only a power cycle clears it</source>
        <translation>アラームリセットコマンドを送信し、アラームが解除されたか、電源再投入でのみ解除できるかを表示します</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="69"/>
        <source>Erase the alarm and warning records kept by the drive</source>
        <translation>ドライバが保持しているアラーム履歴・警告履歴を消去します</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="75"/>
        <source>This drive keeps no alarm or warning records.</source>
        <translation>このドライバはアラーム・警告履歴を保持しません。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="105"/>
        <source>Alarm state: %1</source>
        <translation>アラーム状態: %1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="187"/>
        <source>Reading the records…</source>
        <translation>履歴を読出し中…</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="203"/>
        <source>No alarm is active.</source>
        <translation>アラームは発生していません。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="205"/>
        <source>Alarm active: %1 %2.</source>
        <translation>アラーム発生中: %1 %2。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="207"/>
        <source>An alarm is active.</source>
        <translation>アラームが発生しています。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="210"/>
        <source>This drive is set to clear alarms by a power restart only (%1): Alarm-Reset clears none of them.</source>
        <translation>このドライバはアラームを電源再投入でのみ解除する設定です (%1)。Alarm-Reset では解除できません。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="214"/>
        <source>Could not be read: %1</source>
        <translation>読み出せません: %1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="252"/>
        <source>Writes: %1</source>
        <translation>書込み: %1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="253"/>
        <source>This clears the active alarm if its cause is gone. Some alarms are cleared only by a power cycle; the result tells.</source>
        <translation>原因が取り除かれていれば、発生中のアラームを解除します。電源再投入でのみ解除できるアラームもあります。結果に表示されます。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="256"/>
        <source>This drive is set to clear alarms by a power restart only (%1).</source>
        <translation>このドライバはアラームを電源再投入でのみ解除する設定です (%1)。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="258"/>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="260"/>
        <source>Reset alarm</source>
        <translation>アラームリセット</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="259"/>
        <source>Send the alarm reset command to machine %1?</source>
        <translation>局番 %1 にアラームリセットコマンドを送信しますか？</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="267"/>
        <source>Sending the alarm reset…</source>
        <translation>アラームリセットを送信中…</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="273"/>
        <source>Alarm reset: %1</source>
        <translation>アラームリセット: %1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="276"/>
        <source>Turn the drive&apos;s power off, wait 5 s and turn it on again.</source>
        <translation>ドライバの電源を切り、5 s 待ってから再投入してください。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="287"/>
        <source>%1 (%2 records)</source>
        <translation>%1（%2 件）</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="289"/>
        <source>the alarm and warning records</source>
        <translation>アラーム履歴と警告履歴</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="291"/>
        <source>Clear records</source>
        <translation>履歴消去</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="292"/>
        <source>Erase %1 of machine %2?</source>
        <translation>局番 %2 の%1を消去しますか？</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="292"/>
        <source> and </source>
        <translation> と </translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="293"/>
        <source>The records cannot be restored. Writes: %1</source>
        <translation>履歴は復元できません。書込み: %1</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="295"/>
        <source>Erase</source>
        <translation>消去</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="302"/>
        <source>Erasing the records…</source>
        <translation>履歴を消去中…</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="310"/>
        <source>Erased: %1 (%2 records); %3</source>
        <translation>消去: %1（%2 件）。%3</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="313"/>
        <source>read back empty.</source>
        <translation>読み戻し結果は空です。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="314"/>
        <source>NOT empty when read back.</source>
        <translation>読み戻し結果が空ではありません。</translation>
    </message>
    <message>
        <location filename="../ui/alarms/AlarmsPage.cpp" line="316"/>
        <source>Erasing failed: %1</source>
        <translation>消去に失敗しました: %1</translation>
    </message>
</context>
<context>
    <name>opentop::AutotunePanel</name>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="24"/>
        <source>Autotune…</source>
        <translation>オートチューニング…</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="28"/>
        <source>Accept</source>
        <translation>採用</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="29"/>
        <source>Reject</source>
        <translation>不採用</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="30"/>
        <source>Store in the drive</source>
        <translation>ドライバに保存</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="48"/>
        <source>Writes the proposed gains to the drive (temporary until stored) and offers a step test to compare with the prediction</source>
        <translation>提案ゲインをドライバに書き込み（保存するまでは一時的）、予測と比較するためのステップ試験を提示します</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="50"/>
        <source>Writes back the gains the drive had before</source>
        <translation>ドライバの以前のゲインを書き戻します</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="51"/>
        <source>Stores the gains in the drive so that they survive a power cycle; asks first unless the step after Accept passed the check</source>
        <translation>電源再投入後も残るよう、ゲインをドライバに保存します。採用後のステップが確認に合格していなければ、先に確認を求めます</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="57"/>
        <source>Operating speed:</source>
        <translation>運転速度:</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="58"/>
        <source>Relay amplitude:</source>
        <translation>リレー振幅:</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="59"/>
        <source>%</source>
        <translation>%</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="60"/>
        <source>Rule:</source>
        <translation>チューニングルール:</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="64"/>
        <source>Present</source>
        <translation>現在</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="65"/>
        <source>Proposed</source>
        <translation>提案</translation>
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
        <translation>0 %1 より大きい運転速度を入力してください。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="117"/>
        <source>Enter a relay amplitude of 1–50 %.</source>
        <translation>リレー振幅を 1–50 % で入力してください。</translation>
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
        <translation>オートチューニング結果はまだありません。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="153"/>
        <source>Autotune failed: %1</source>
        <translation>オートチューニング失敗: %1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="155"/>
        <source>What to change: %1</source>
        <translation>変更すべき点: %1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="165"/>
        <source>Relay: Ku %1 %/%2, Tu %3 ms measured, %4 readings per period (one every %5 ms)</source>
        <translation>リレー: Ku %1 %/%2、Tu %3 ms（実測）、1 周期あたり読出し %4 回（%5 ms ごと）</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="175"/>
        <source>The drive&apos;s own loop (model): Ku %1 %/%2, Tu %3 ms</source>
        <translation>ドライバ自身のループ（モデル）: Ku %1 %/%2、Tu %3 ms</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="180"/>
        <source>Proposal: the rule&apos;s P × %1, Ti × %2; predicted overshoot %3 %, settling %4</source>
        <translation>提案: ルールの P × %1、Ti × %2。予測オーバーシュート %3 %、整定 %4</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="184"/>
        <source>not within the record</source>
        <translation>記録時間内になし</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="208"/>
        <source>Check after Accept: passed.</source>
        <translation>採用後の確認: 合格。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="209"/>
        <source>Check after Accept: FAILED. Reject writes back the gains the drive had.</source>
        <translation>採用後の確認: 不合格。「不採用」でドライバの元のゲインを書き戻します。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/AutotunePanel.cpp" line="171"/>
        <source>Model: K %1 %2/%, τ %3 ms, dead time %4 ms</source>
        <translation>モデル: K %1 %2/%、τ %3 ms、むだ時間 %4 ms</translation>
    </message>
</context>
<context>
    <name>opentop::BackupCommand</name>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="37"/>
        <source>Save every setting of drives to a backup file (written only when all were read)</source>
        <translation>ドライバの全設定をバックアップファイルに保存します（すべて読み出せた場合のみ書き込みます）</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="43"/>
        <source>The backup file to write (replaced atomically).</source>
        <translation>書き込むバックアップファイル（アトミックに置き換えます）。</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="44"/>
        <source>FILE</source>
        <translation>FILE</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="46"/>
        <source>Every drive the connection knows (a simulated bus), or every drive a scan finds.</source>
        <translation>接続先が把握しているすべてのドライバ（シミュレーションバス）、またはスキャンで見つかったすべてのドライバ。</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="54"/>
        <source>error: name the machine numbers, or give --all: backup ID... -o FILE</source>
        <translation>エラー: 局番を指定するか、--all を指定してください: backup ID... -o FILE</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="63"/>
        <location filename="../cli/BackupCommand.cpp" line="245"/>
        <location filename="../cli/BackupCommand.cpp" line="251"/>
        <source>error: %1</source>
        <translation>エラー: %1</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="72"/>
        <source>scanning the bus for drives…</source>
        <translation>バスのドライバをスキャン中…</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="87"/>
        <source>warning: machine number %1 answered, but its identification failed: it is not backed up; name it to try again (backup %1 -o FILE).</source>
        <translation>警告: 局番 %1 は応答しましたが、識別に失敗しました: バックアップしていません。この局番を指定して再試行してください (backup %1 -o FILE)。</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="108"/>
        <source>error: the port %1 was lost while reading %2 (%3)</source>
        <translation>エラー: %2 の読出し中にポート %1 が失われました (%3)</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="112"/>
        <location filename="../cli/BackupCommand.cpp" line="247"/>
        <source>nothing written to %1</source>
        <translation>%1 には何も書き込んでいません</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="120"/>
        <source>error: give the file to write: backup ID... -o FILE</source>
        <translation>エラー: 書き込むファイルを指定してください: backup ID... -o FILE</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="124"/>
        <source>error: %1; nothing read</source>
        <translation>エラー: %1。何も読み出していません</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="136"/>
        <source>interrupted: nothing written</source>
        <translation>中断: 何も書き込んでいません</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="140"/>
        <source>error: no drive answers on %1; nothing written</source>
        <translation>エラー: %1 で応答するドライバがありません。何も書き込んでいません</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="166"/>
        <source>machine number %1</source>
        <translation>局番 %1</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="226"/>
        <source>interrupted while reading machine number %1: nothing written</source>
        <translation>局番 %1 の読出し中に中断: 何も書き込んでいません</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="188"/>
        <source>%1: %2 settings read in %3 requests, %4 ms</source>
        <translation>%1: %2 個の設定を %3 回の要求で読出し、%4 ms</translation>
    </message>
    <message>
        <location filename="../cli/BackupCommand.cpp" line="196"/>
        <source>%1: reading failed, %2 of %3 settings read (%4 requests, %5 ms)</source>
        <translation>%1: 読出し失敗、%3 個中 %2 個の設定を読出し（%4 回の要求、%5 ms）</translation>
    </message>
</context>
<context>
    <name>opentop::BackupDialog</name>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="29"/>
        <source>&amp;Cancel</source>
        <translation>キャンセル(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="30"/>
        <source>&amp;Save the drives read</source>
        <translation>読み出したドライバを保存(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="31"/>
        <source>C&amp;lose</source>
        <translation>閉じる(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="44"/>
        <source>Back up drives</source>
        <translation>ドライバのバックアップ</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="46"/>
        <source>Machine number</source>
        <translation>局番</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="46"/>
        <source>Model</source>
        <translation>型式</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="46"/>
        <source>Progress</source>
        <translation>進捗</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="46"/>
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="54"/>
        <source>Save only the drives that were read; the others are left out</source>
        <translation>読み出せたドライバのみ保存します。その他は除外されます</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="56"/>
        <source>Stop after the drive being read</source>
        <translation>読出し中のドライバが終わったら停止します</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="84"/>
        <source>Nothing was read: %1.</source>
        <translation>何も読み出していません：%1。</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="107"/>
        <source>Waiting</source>
        <translation>待機中</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="111"/>
        <source>%v of %m drives</source>
        <translation>%v / %m 台</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/BackupDialog.cpp" line="112"/>
        <source>Reading the settings of %n drive(s)…</source>
        <translation>
            <numerusform>%n 台のドライバの設定を読出し中…</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="123"/>
        <source>Stopping after the drive being read…</source>
        <translation>読出し中のドライバが終わったら停止します…</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="161"/>
        <source>Not read (cancelled)</source>
        <translation>未読出し（キャンセル）</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="37"/>
        <source>drive %1: not identified, nothing read</source>
        <translation>ドライバ %1: 識別できません。何も読み出していません</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="166"/>
        <source>Not identified</source>
        <translation>識別不可</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="139"/>
        <source>Reading…</source>
        <translation>読出し中…</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/BackupDialog.cpp" line="153"/>
        <source>%n setting(s) read in %1 ms</source>
        <translation>
            <numerusform>%n 個の設定を %1 ms で読出し</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="167"/>
        <source>Value not allowed</source>
        <translation>許可されていない値</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="168"/>
        <source>Read failed</source>
        <translation>読出し失敗</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="184"/>
        <source>Not read: drive(s) %1. Nothing has been saved yet.</source>
        <translation>未読出し: ドライバ %1。まだ何も保存していません。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/BackupDialog.cpp" line="190"/>
        <source>Save the %n drive(s) that were read?</source>
        <translation>
            <numerusform>読み出した %n 台のドライバを保存しますか？</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/BackupDialog.cpp" line="214"/>
        <source>Saved %n drive(s) to %1.</source>
        <translation>
            <numerusform>%n 台のドライバを %1 に保存しました。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="220"/>
        <source>Left out (not read): drive(s) %1.</source>
        <translation>除外（未読出し）: ドライバ %1。</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupDialog.cpp" line="224"/>
        <source>Could not save %1: %2</source>
        <translation>%1 を保存できませんでした: %2</translation>
    </message>
</context>
<context>
    <name>opentop::BackupFile</name>
    <message>
        <location filename="../model/files/BackupFile.cpp" line="309"/>
        <source>%1 is larger than %2 MB, the most a backup file may hold (a backup of 247 drives is far smaller); not a backup file</source>
        <translation>%1 は %2 MB を超えています。これはバックアップファイルの上限です（247 台分のバックアップでもはるかに小さくなります）。バックアップファイルではありません</translation>
    </message>
</context>
<context>
    <name>opentop::BackupFileParser</name>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="49"/>
        <source>not a JSON file: %1 at byte %2</source>
        <translation>JSON ファイルではありません: %2 バイト目で %1</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="53"/>
        <source>not an OpenTOP backup file: the JSON is not an object</source>
        <translation>OpenTOP のバックアップファイルではありません: JSON がオブジェクトではありません</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="63"/>
        <source>&quot;created&quot; is not an ISO 8601 date and time</source>
        <translation>&quot;created&quot; が ISO 8601 形式の日時ではありません</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="75"/>
        <source>the file holds no drives (&quot;devices&quot; must be a non-empty list)</source>
        <translation>ドライバが含まれていません（&quot;devices&quot; は空でないリストでなければなりません）</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="82"/>
        <source>%1: not a drive</source>
        <translation>%1: ドライバではありません</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="84"/>
        <source>machine number %1 appears twice</source>
        <translation>局番 %1 が 2 回出現しています</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="98"/>
        <source>not an OpenTOP backup file (&quot;format&quot; is &quot;%1&quot;, not &quot;%2&quot;)</source>
        <translation>OpenTOP のバックアップファイルではありません（&quot;format&quot; が &quot;%2&quot; ではなく &quot;%1&quot; です）</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="100"/>
        <source>not an OpenTOP backup file (no &quot;format&quot;: &quot;%1&quot;)</source>
        <translation>OpenTOP のバックアップファイルではありません（&quot;format&quot;: &quot;%1&quot; がありません）</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="105"/>
        <source>&quot;formatVersion&quot; must be a whole number from 1</source>
        <translation>&quot;formatVersion&quot; は 1 以上の整数でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="107"/>
        <source>written by a newer OpenTOP (format version %1); this version reads format version %2</source>
        <translation>新しい OpenTOP で書き込まれています（フォーマットバージョン %1）。このバージョンが読み込めるのはフォーマットバージョン %2 です</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="113"/>
        <source>the file has no checksum (&quot;checksum&quot;: &quot;sha256:…&quot;); it was not written by OpenTOP or was changed afterwards</source>
        <translation>チェックサムがありません（&quot;checksum&quot;: &quot;sha256:…&quot;）。OpenTOP で書き込まれていないか、書込み後に変更されています</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="118"/>
        <source>the file was changed after it was written (checksum mismatch)</source>
        <translation>書込み後にファイルが変更されています（チェックサム不一致）</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="128"/>
        <source>%1: &quot;slave&quot; must be a machine number 1–247</source>
        <translation>%1: &quot;slave&quot; は局番 1–247 でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="129"/>
        <source>%1 (machine number %2)</source>
        <translation>%1（局番 %2）</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="133"/>
        <source>%1: unknown family &quot;%2&quot;; known: %3</source>
        <translation>%1: 不明なファミリ &quot;%2&quot;。既知: %3</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="138"/>
        <source>%1: &quot;variant&quot; must be text or null</source>
        <translation>%1: &quot;variant&quot; はテキストまたは null でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="143"/>
        <source>%1: unknown variant &quot;%2&quot; of family %3; known: %4</source>
        <translation>%1: ファミリ %3 の不明な機種 &quot;%2&quot;。既知: %4</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="145"/>
        <source>none</source>
        <translation>なし</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="153"/>
        <source>%1: &quot;machineName&quot; must be text</source>
        <translation>%1: &quot;machineName&quot; はテキストでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="155"/>
        <source>%1: &quot;machineName&quot;: %2</source>
        <translation>%1: &quot;machineName&quot;: %2</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="160"/>
        <source>%1: &quot;parameters&quot; must be a list</source>
        <translation>%1: &quot;parameters&quot; はリストでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="180"/>
        <source>%1: no &quot;name&quot;</source>
        <translation>%1: &quot;name&quot; がありません</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="183"/>
        <source>%1 %2: &quot;registers&quot; must be a list</source>
        <translation>%1 %2: &quot;registers&quot; はリストでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="187"/>
        <source>%1 %2: registers must be numbers 0–65535</source>
        <translation>%1 %2: registers は 0–65535 の数値でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="193"/>
        <source>%1 %2: address &quot;%3&quot;, but the %4 profile has it at %5</source>
        <translation>%1 %2: アドレスが &quot;%3&quot; ですが、%4 プロファイルでは %5 です</translation>
    </message>
    <message>
        <location filename="../model/files/BackupFileParser.cpp" line="218"/>
        <source>%1: %2: &quot;value&quot; %3 does not match its registers (%4)</source>
        <translation>%1: %2: &quot;value&quot; %3 がレジスタ値 (%4) と一致しません</translation>
    </message>
</context>
<context>
    <name>opentop::BackupValidator</name>
    <message>
        <location filename="../model/files/BackupValidator.cpp" line="16"/>
        <source>unknown parameter &quot;%1&quot;: the %2 profile has no such setting</source>
        <translation>不明なパラメータ &quot;%1&quot;: %2 プロファイルにこの設定はありません</translation>
    </message>
    <message>
        <location filename="../model/files/BackupValidator.cpp" line="21"/>
        <source>&quot;%1&quot; is not a setting that backups hold</source>
        <translation>&quot;%1&quot; はバックアップに含まれる設定ではありません</translation>
    </message>
    <message>
        <location filename="../model/files/BackupValidator.cpp" line="25"/>
        <source>&quot;%1&quot; appears twice</source>
        <translation>&quot;%1&quot; が 2 回出現しています</translation>
    </message>
    <message>
        <location filename="../model/files/BackupValidator.cpp" line="28"/>
        <source>%1: %2 registers, but the parameter has %3</source>
        <translation>%1: レジスタ数が %2 ですが、パラメータは %3 です</translation>
    </message>
    <message>
        <location filename="../model/files/BackupValidator.cpp" line="53"/>
        <source>%1: its allowed values depend on %2, which the file does not hold</source>
        <translation>%1: 許容値は %2 に依存しますが、ファイルに含まれていません</translation>
    </message>
</context>
<context>
    <name>opentop::BackupViewer</name>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="24"/>
        <source>Backup file</source>
        <translation>バックアップファイル</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="35"/>
        <source>Parameter</source>
        <translation>パラメータ</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="35"/>
        <source>Label</source>
        <translation>ラベル</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="35"/>
        <source>Value</source>
        <translation>値</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="35"/>
        <source>Registers</source>
        <translation>レジスタ</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="39"/>
        <source>&amp;Open…</source>
        <translation>開く(&amp;O)…</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="40"/>
        <source>Open another backup file</source>
        <translation>別のバックアップファイルを開きます</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="41"/>
        <source>C&amp;lose</source>
        <translation>閉じる(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="62"/>
        <source>%1: no such file</source>
        <translation>%1: ファイルがありません</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="68"/>
        <source>the file could not be read</source>
        <translation>ファイルを読み込めませんでした</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="69"/>
        <source>Backup file %1</source>
        <translation>バックアップファイル %1</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="77"/>
        <source>Open backup file</source>
        <translation>バックアップファイルを開く</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="78"/>
        <source>OpenTOP backups (*.json);;All files (*)</source>
        <translation>OpenTOP バックアップ (*.json);;すべてのファイル (*)</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="100"/>
        <source>File: %1</source>
        <translation>ファイル: %1</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="101"/>
        <source>Refused: %1</source>
        <translation>拒否: %1</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="116"/>
        <source>, %1 bit/s, parity %2, %3 stop bit(s)</source>
        <translation>、%1 bit/s、パリティ %2、ストップビット %3</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="118"/>
        <source>File: %1
Written by %2 on %3 (UTC)
Read from: %4
Drives: %5</source>
        <translation>ファイル: %1
作成: %2、%3 (UTC)
読出し元: %4
ドライバ: %5</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="127"/>
        <source>%1 %2, firmware %3</source>
        <translation>%1 %2、ファームウェア %3</translation>
    </message>
    <message>
        <location filename="../ui/files/BackupViewer.cpp" line="130"/>
        <source>(variant unknown)</source>
        <translation>（機種不明）</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/BackupViewer.cpp" line="133"/>
        <source>%n setting(s)</source>
        <translation>
            <numerusform>%n 個の設定</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::BarHideButton</name>
    <message>
        <location filename="../ui/widgets/BarHideButton.cpp" line="9"/>
        <source>Hide this bar</source>
        <translation>このバーを非表示にします</translation>
    </message>
    <message>
        <location filename="../ui/widgets/BarHideButton.cpp" line="10"/>
        <source>Hide</source>
        <translation>非表示</translation>
    </message>
</context>
<context>
    <name>opentop::BusDocks</name>
    <message>
        <location filename="../ui/main/BusDocks.cpp" line="28"/>
        <source>Traffic log</source>
        <translation>通信ログ</translation>
    </message>
    <message>
        <location filename="../ui/main/BusDocks.cpp" line="35"/>
        <source>Bus overview</source>
        <translation>バス一覧</translation>
    </message>
    <message>
        <location filename="../ui/main/BusDocks.cpp" line="36"/>
        <source>Trends</source>
        <translation>トレンド</translation>
    </message>
    <message>
        <location filename="../ui/main/BusDocks.cpp" line="37"/>
        <source>Communication groups</source>
        <translation>通信グループ</translation>
    </message>
    <message>
        <location filename="../ui/main/BusDocks.cpp" line="40"/>
        <location filename="../ui/main/BusDocks.cpp" line="110"/>
        <source>Not connected</source>
        <translation>未接続</translation>
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
        <translation>%1 分前</translation>
    </message>
    <message>
        <location filename="../cli/BusDriveList.cpp" line="15"/>
        <source>%1 h ago</source>
        <translation>%1 時間前</translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/BusDriveList.cpp" line="16"/>
        <source>%n day(s) ago</source>
        <translation>
            <numerusform>%n 日前</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../cli/BusDriveList.cpp" line="27"/>
        <source>the simulated bus&apos;s drives</source>
        <translation>シミュレーションバスのドライバ</translation>
    </message>
    <message>
        <location filename="../cli/BusDriveList.cpp" line="30"/>
        <source>the drives last seen on %1</source>
        <translation>%1 で前回見つかったドライバ</translation>
    </message>
    <message>
        <location filename="../cli/BusDriveList.cpp" line="31"/>
        <source>the drives the last scan of %1 found (%2, %3)</source>
        <translation>%1 の前回のスキャンで見つかったドライバ（%2、%3）</translation>
    </message>
    <message>
        <location filename="../cli/BusDriveList.cpp" line="38"/>
        <source>no list of the drives on the bus</source>
        <translation>バス上のドライバの一覧なし</translation>
    </message>
</context>
<context>
    <name>opentop::BusGroups</name>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="109"/>
        <source>machine number %1 is the parent of communication group %1: what is sent to it is also executed by %2 (children do not reply)</source>
        <translation>局番 %1 は通信グループ %1 の親局です: 親局に送信した内容は %2 でも実行されます（子局は応答しません）</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="127"/>
        <location filename="../model/bus/BusGroups.cpp" line="136"/>
        <source>%1 and %2</source>
        <translation>%1 と %2</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="145"/>
        <source>This also reaches machine number %1 (the child of communication group %2; it executes it without replying).</source>
        <translation>この操作は局番 %1（通信グループ %2 の子局。応答せずに実行します）にも届きます。</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="149"/>
        <source>This also reaches machine numbers %1 (the children of communication group %2; they execute it without replying).</source>
        <translation>この操作は局番 %1（通信グループ %2 の子局。応答せずに実行します）にも届きます。</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="159"/>
        <source>child of %1</source>
        <translation>%1 の子局</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="162"/>
        <source>parent of %1</source>
        <translation>%1 の親局</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="170"/>
        <source>machine number %1 is a child of %2 and itself a parent: a child must not be a group parent</source>
        <translation>局番 %1 は %2 の子局であり、自身も親局です: 子局をグループ親局にすることはできません</translation>
    </message>
    <message>
        <location filename="../model/bus/BusGroups.cpp" line="175"/>
        <source>machine number %1 is in communication group %2, but no drive %2 is known: frames to %2 reach %1 although nothing answers</source>
        <translation>局番 %1 は通信グループ %2 に属していますが、ドライバ %2 が見つかりません: %2 宛のフレームは、応答はありませんが %1 に届きます</translation>
    </message>
</context>
<context>
    <name>opentop::BusLeaving</name>
    <message>
        <location filename="../ui/main/BusLeaving.cpp" line="68"/>
        <location filename="../ui/main/BusLeaving.cpp" line="88"/>
        <source>quit</source>
        <translation>終了</translation>
    </message>
    <message>
        <location filename="../ui/main/BusLeaving.cpp" line="77"/>
        <source>Unwritten changes</source>
        <translation>未書込みの変更</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/main/BusLeaving.cpp" line="78"/>
        <source>%n edit(s) have not been written to the drives. Quit and discard them?</source>
        <translation>
            <numerusform>%n 件の編集がドライバに書き込まれていません。破棄して終了しますか？</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::BusListMenu</name>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="30"/>
        <source>&amp;Name this machine…</source>
        <translation>この機械に名前を付ける(&amp;N)…</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="36"/>
        <source>&amp;Identify again</source>
        <translation>再識別(&amp;I)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="47"/>
        <source>&amp;Remove from list</source>
        <translation>リストから削除(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="62"/>
        <source>Name of %1 (up to %2 characters; empty removes the name):</source>
        <translation>%1 の名前 (最大 %2 文字。空にすると名前を削除)：</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="69"/>
        <source>Name this machine</source>
        <translation>この機械に名前を付ける</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="76"/>
        <source>Machine number %1 has no name now.</source>
        <translation>局番 %1 の名前は削除されました。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListMenu.cpp" line="77"/>
        <source>Machine number %1 is now named %2.</source>
        <translation>局番 %1 の名前は %2 になりました。</translation>
    </message>
</context>
<context>
    <name>opentop::BusListModel</name>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="76"/>
        <source>Machine number: the drive&apos;s address on the bus (1–247)</source>
        <translation>局番：バス上のドライブのアドレス（1～247）</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="78"/>
        <source>The drive&apos;s MONITOR LED: red alarm, green ready, orange CW, sky blue CCW, purple external interrupt, blue memory or communication error, grey no answer</source>
        <translation>ドライバの MONITOR LED: 赤 アラーム、緑 準備完了、橙 CW、水色 CCW、紫 外部停止、青 メモリまたは通信異常、灰 応答なし</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="85"/>
        <source>LED</source>
        <translation>LED</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="87"/>
        <source>No.</source>
        <translation>局番</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="91"/>
        <source>Family</source>
        <translation>ファミリ</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="93"/>
        <source>Model</source>
        <translation>型式</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="95"/>
        <source>Firmware</source>
        <translation>ファームウェア</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="97"/>
        <source>State</source>
        <translation>状態</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="99"/>
        <source>Control priority</source>
        <translation>制御優先</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="73"/>
        <source>How each drive&apos;s machine number is set on its switches:
%1</source>
        <translation>各ドライバの局番をスイッチで設定する方法：
%1</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="89"/>
        <source>Switches</source>
        <translation>スイッチ</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="101"/>
        <source>Name</source>
        <translation>名前</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="113"/>
        <source>Two drives may share machine number %1 (%2): check the address switches of every drive on the line, give each drive its own number and restart its power; a bad termination or a swapped A/B pair also corrupts replies.</source>
        <translation>2 台のドライバが局番 %1 (%2) を共有している可能性があります：ライン上のすべてのドライバのアドレススイッチを確認し、各ドライバに別の局番を設定して電源を入れ直してください。終端抵抗の不良や A/B の逆接続でも応答が壊れます。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="134"/>
        <source>%1 at %2</source>
        <translation>%1、%2</translation>
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
        <translation>%1 — 機種不明</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="142"/>
        <source>V%1</source>
        <translation>V%1</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="171"/>
        <source>Status light %1: %2 (%3)</source>
        <translation>ステータスランプ %1: %2 (%3)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="175"/>
        <source>The drive&apos;s manual: %1</source>
        <translation>ドライバのマニュアル: %1</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="178"/>
        <source>Status light grey: not live — %1</source>
        <translation>ステータスランプ 灰: 更新停止 — %1</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="186"/>
        <source>No name yet: Name… in the context menu (F2) names this machine</source>
        <translation>まだ名前がありません：コンテキストメニューの「名前を付ける…」(F2) でこの機械に名前を付けます</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="187"/>
        <source>%1: the name given to this machine (F2 changes it)</source>
        <translation>%1：この機械に付けた名前 (F2 で変更)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="190"/>
        <source>Requests to this drive go out at %1, its own line format, not the port&apos;s: the line is switched to it and back between transactions. Change it with Line format… in the context menu.</source>
        <translation>このドライブへの要求は、ポートの形式ではなくドライブ自身の通信フォーマット %1 で送信されます。回線はトランザクションの合間にその形式へ切り替わり、また戻ります。右クリックメニューの「通信フォーマット…」で変更します。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="197"/>
        <source>The drive does not report its variant. Choose it from the context menu (Variant) so that values are checked against the right limits.</source>
        <translation>ドライバが機種を通知しません。値が正しい範囲でチェックされるよう、コンテキストメニュー（機種）から選択してください。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusListModel.cpp" line="206"/>
        <source>The drive takes run commands from its I/O terminals; test runs over the bus need communication priority.</source>
        <translation>ドライバは I/O 端子から運転指令を受け付けています。バス経由の試運転には通信優先が必要です。</translation>
    </message>
</context>
<context>
    <name>opentop::BusMemory</name>
    <message>
        <location filename="../model/bus/BusMemory.cpp" line="79"/>
        <source>the simulated bus</source>
        <translation>シミュレーションバス</translation>
    </message>
</context>
<context>
    <name>opentop::BusOverview</name>
    <message>
        <location filename="../ui/bus/BusOverview.cpp" line="37"/>
        <source>Double-click a drive to open its pages.</source>
        <translation>ドライバをダブルクリックするとそのページを開きます。</translation>
    </message>
</context>
<context>
    <name>opentop::BusOverviewModel</name>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="133"/>
        <source>Drive</source>
        <translation>ドライバ</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="135"/>
        <source>State</source>
        <translation>状態</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="137"/>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="139"/>
        <source>Display</source>
        <translation>表示値</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="141"/>
        <source>Target</source>
        <translation>目標</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="143"/>
        <source>Load</source>
        <translation>負荷</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="145"/>
        <source>Alarm</source>
        <translation>アラーム</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="147"/>
        <source>Last answer</source>
        <translation>最終応答</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="174"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="164"/>
        <source>connection lost; %1</source>
        <translation>接続断。%1</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="166"/>
        <source>no answer: %1; %2</source>
        <translation>応答なし: %1。%2</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="203"/>
        <source>none</source>
        <translation>なし</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusOverviewModel.cpp" line="206"/>
        <source>active</source>
        <translation>発生中</translation>
    </message>
</context>
<context>
    <name>opentop::BusPanel</name>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="35"/>
        <source>&amp;Scan</source>
        <translation>スキャン(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="38"/>
        <source>A&amp;dd drive…</source>
        <translation>ドライバ追加(&amp;D)…</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="40"/>
        <source>Ca&amp;ncel</source>
        <translation>キャンセル(&amp;N)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="50"/>
        <source>Ask every machine number of the range who answers</source>
        <translation>範囲内の各局番に応答を問い合わせます</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="52"/>
        <source>&amp;from</source>
        <translation>開始局番(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="54"/>
        <source>&amp;to</source>
        <translation>終了局番(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="77"/>
        <source>Identify one machine number and add it to the list</source>
        <translation>局番を 1 つ識別してリストに追加します</translation>
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
        <translation>スキャン進捗</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="85"/>
        <source>Stop the scan after the request on the wire</source>
        <translation>送信中の要求が終わったらスキャンを停止します</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="95"/>
        <source>Rescan at %1</source>
        <translation>%1 で再スキャン</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="135"/>
        <source>Drives on the bus</source>
        <translation>バス上のドライバ</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="151"/>
        <source>Name this machine…</source>
        <translation>この機械に名前を付ける…</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="207"/>
        <source>%v of %m (machine number %1)</source>
        <translation>%v / %m（局番 %1）</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="211"/>
        <source>Machine number %1 answered, identification failed: retrying (%2 of %3)… Polling waits until the scan is over.</source>
        <translation>局番 %1 は応答しましたが、識別に失敗しました: 再試行中 (%3 回中 %2 回目)… ポーリングはスキャン終了まで待機します。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="223"/>
        <source>Scanning machine numbers %1–%2 on %3, %4 ms each… Polling waits until the scan is over.</source>
        <translation>%3 で局番 %1–%2 をスキャン中（各 %4 ms）… ポーリングはスキャン終了まで待機します。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="295"/>
        <source>If one is on this bus, add it with Add drive and its line format.</source>
        <translation>このバスにそのようなドライブがある場合は、「ドライブ追加」で通信フォーマットとともに追加してください。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="300"/>
        <source>Machine number %1 answered, but its identification failed, also when asked again: add it by hand with Add drive…, or check its line settings and scan again.</source>
        <translation>局番 %1 は応答しましたが、再度問い合わせても識別に失敗しました:「ドライバ追加…」で手動で追加するか、通信設定を確認して再スキャンしてください。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="243"/>
        <source>Cancelling after the request on the wire…</source>
        <translation>送信中の要求が終わったらキャンセルします…</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="59"/>
        <source>Machine numbers 1–247, as set on each drive&apos;s switches:
%1</source>
        <translation>局番 1–247、各ドライバのスイッチの設定：
%1</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="261"/>
        <source>Did not answer the last scan.</source>
        <translation>前回のスキャンで応答しませんでした。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="267"/>
        <source>The scan stopped at machine number %1: %2</source>
        <translation>局番 %1 でスキャンが停止しました: %2</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/bus/BusPanel.cpp" line="272"/>
        <source>Scan cancelled after machine numbers %1–%2 (%3 of %4): %n drive(s) found.</source>
        <translation>
            <numerusform>局番 %1–%2 の後でスキャンをキャンセルしました（%4 中 %3）: %n 台のドライバが見つかりました。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/bus/BusPanel.cpp" line="280"/>
        <source>%n drive(s) found on machine numbers %1–%2 in %3 s.</source>
        <translation>
            <numerusform>局番 %1–%2 で %n 台のドライバが見つかりました（%3 s）。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="321"/>
        <source>Asking machine number %1…</source>
        <translation>局番 %1 に問い合わせ中…</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="326"/>
        <source>Machine number %1: %2 added.</source>
        <translation>局番 %1: %2 を追加しました。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusPanel.cpp" line="328"/>
        <source>Machine number %1: %2 %3</source>
        <translation>局番 %1: %2 %3</translation>
    </message>
    <message>
        <location filename="../ui/bus/VariantMenu.cpp" line="26"/>
        <source>&amp;Variant</source>
        <translation>機種(&amp;V)</translation>
    </message>
</context>
<context>
    <name>opentop::BusRecallBar</name>
    <message>
        <location filename="../ui/bus/BusRecallBar.cpp" line="21"/>
        <source>&amp;Scan the bus</source>
        <translation>バスをスキャン(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusRecallBar.cpp" line="44"/>
        <source>Last time on %1: %2.</source>
        <translation>前回 %1 では: %2。</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusRecallBar.cpp" line="46"/>
        <source>&amp;Restore the drive last seen</source>
        <translation>前回のドライバを呼び出し(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusRecallBar.cpp" line="47"/>
        <source>&amp;Restore the %1 drives last seen</source>
        <translation>前回の %1 台のドライバを呼び出し(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusRecallBar.cpp" line="48"/>
        <source>Identify the drives at these machine numbers again, with the variants set last time</source>
        <translation>前回設定した機種で、これらの局番のドライバを再識別します</translation>
    </message>
    <message>
        <location filename="../ui/bus/BusRecallBar.cpp" line="62"/>
        <source>No drive is known on %1 yet. Scan the bus to find the drives.</source>
        <translation>%1 ではまだドライバが登録されていません。バスをスキャンしてドライバを検出してください。</translation>
    </message>
</context>
<context>
    <name>opentop::BusRestore</name>
    <message>
        <location filename="../model/files/BusRestore.cpp" line="26"/>
        <source>machine number %1 is not a drive on the bus</source>
        <translation>局番 %1 はバス上のドライバではありません</translation>
    </message>
    <message>
        <location filename="../model/files/BusRestore.cpp" line="97"/>
        <source>not attempted</source>
        <translation>未実行</translation>
    </message>
</context>
<context>
    <name>opentop::BusScanner</name>
    <message>
        <location filename="../model/bus/BusScanner.cpp" line="152"/>
        <source>garbled replies twice (%1): two drives probably share machine number %2; check their address switches (%3)</source>
        <translation>応答が 2 回壊れていました (%1)：2 台のドライバが局番 %2 を共有している可能性があります。アドレススイッチを確認してください (%3)</translation>
    </message>
    <message>
        <location filename="../model/bus/BusScanner.cpp" line="158"/>
        <source>answers, but none of the device profiles matches (%1)</source>
        <translation>応答はありますが、一致するデバイスプロファイルがありません (%1)</translation>
    </message>
    <message>
        <location filename="../model/bus/BusScanner.cpp" line="171"/>
        <source>answered, but its identification read got no reply (%1), also when asked %2 more times: add it by hand, or scan with a longer wait</source>
        <translation>応答はありますが、識別の読出しに応答がありません (%1)。さらに %2 回問い合わせても同じです: 手動で追加するか、待ち時間を長くして再スキャンしてください</translation>
    </message>
    <message>
        <location filename="../model/bus/BusScanner.cpp" line="243"/>
        <source>answered late at first (after the %1 ms wait); a longer wait makes scans of this bus reliable</source>
        <translation>最初は応答が遅れました（%1 ms の待ち時間の後）。待ち時間を長くすると、このバスのスキャンが確実になります</translation>
    </message>
</context>
<context>
    <name>opentop::BusSpec</name>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="57"/>
        <source>&quot;%1&quot;: the braces do not pair; a drive&apos;s defects are written in braces after its number, e.g. dbu200@3{firmware=1.4,stall}</source>
        <translation>&quot;%1&quot;: 括弧 {} の対応が取れていません。ドライバの不具合は番号の後の {} 内に記述します。例: dbu200@3{firmware=1.4,stall}</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="62"/>
        <source>empty device list; write TYPE@ID[,TYPE@ID...], e.g. dbu200@1,dcpid@7 (types: %1)</source>
        <translation>デバイスリストが空です。TYPE@ID[,TYPE@ID...] の形式で記述してください。例: dbu200@1,dcpid@7（タイプ: %1）</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="70"/>
        <source>&quot;%1&quot;: the defects in braces end the item, e.g. dbu200@3{stall}</source>
        <translation>&quot;%1&quot;: {} 内の不具合は項目の最後に記述します。例: dbu200@3{stall}</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="78"/>
        <source>&quot;%1&quot;: write TYPE@ID or TYPE@FIRST-LAST, e.g. dbu200@1</source>
        <translation>&quot;%1&quot;: TYPE@ID または TYPE@FIRST-LAST の形式で記述してください。例: dbu200@1</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="83"/>
        <source>&quot;%1&quot;: unknown device type &quot;%2&quot;; known types: %3</source>
        <translation>&quot;%1&quot;: 不明なデバイスタイプ &quot;%2&quot;。既知のタイプ: %3</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="90"/>
        <source>&quot;%1&quot;: the machine number must be a number or a range such as 1-16</source>
        <translation>&quot;%1&quot;: 局番は数値または 1-16 のような範囲でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="94"/>
        <source>&quot;%1&quot;: machine number %2 is outside %3–%4 for %5</source>
        <translation>&quot;%1&quot;: 局番 %2 は %5 の範囲 %3–%4 外です</translation>
    </message>
    <message>
        <location filename="../model/bus/BusSpec.cpp" line="101"/>
        <source>machine number %1 is given twice</source>
        <translation>局番 %1 が 2 回指定されています</translation>
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
        <translation>中止</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="54"/>
        <source>STATION ERROR</source>
        <translation>ステーションエラー</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="56"/>
        <source>INTERRUPTED</source>
        <translation>中断</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="58"/>
        <source>NOT FINISHED</source>
        <translation>未完了</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="71"/>
        <source>none</source>
        <translation>なし</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="78"/>
        <source>End-of-line test certificate</source>
        <translation>出荷検査成績書</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="81"/>
        <source>Serial number</source>
        <translation>シリアル番号</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="82"/>
        <location filename="../model/eol/CertificateHtml.cpp" line="148"/>
        <source>Recipe</source>
        <translation>レシピ</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="82"/>
        <source>%1, revision %2</source>
        <translation>%1、リビジョン %2</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="83"/>
        <source>Recipe checksum</source>
        <translation>レシピのチェックサム</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="84"/>
        <source>Recipe approved by</source>
        <translation>レシピ承認者</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="85"/>
        <source>not approved (station without users)</source>
        <translation>未承認 (ユーザーのいないステーション)</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="86"/>
        <source>%1 (approval %2)</source>
        <translation>%1 (承認 %2)</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="87"/>
        <source>Station</source>
        <translation>ステーション</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="88"/>
        <source>Operator</source>
        <translation>作業者</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="89"/>
        <location filename="../model/eol/CertificateHtml.cpp" line="148"/>
        <source>Attempt</source>
        <translation>試験回数</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="90"/>
        <source>%1 (tests of this serial under this recipe)</source>
        <translation>%1 回目（このレシピでのこのシリアルの試験）</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="91"/>
        <source>not counted (recorded before attempts were)</source>
        <translation>カウントなし（試験回数の記録開始前の記録）</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="92"/>
        <location filename="../model/eol/CertificateHtml.cpp" line="148"/>
        <source>Started</source>
        <translation>開始</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="93"/>
        <source>Ended</source>
        <translation>終了</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="94"/>
        <source>Record</source>
        <translation>記録</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="103"/>
        <source>First failure:</source>
        <translation>最初の不合格:</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/eol/CertificateHtml.cpp" line="121"/>
        <source>This serial failed %n earlier test(s); they are listed below.</source>
        <translation>
            <numerusform>このシリアルは過去の試験で %n 回不合格になっています。以下に一覧を示します。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="124"/>
        <source>Drives</source>
        <translation>ドライバ</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="125"/>
        <source>Machine number</source>
        <translation>局番</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="125"/>
        <source>Model</source>
        <translation>型式</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="125"/>
        <source>Variant</source>
        <translation>機種</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="125"/>
        <source>Firmware</source>
        <translation>ファームウェア</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="125"/>
        <source>How known</source>
        <translation>確認方法</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="130"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
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
        <translation>ドライバ</translation>
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
        <translation>値</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="133"/>
        <source>Written</source>
        <translation>書込み</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="134"/>
        <source>Read back</source>
        <translation>読み戻し</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="134"/>
        <source>Verified</source>
        <translation>照合</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="137"/>
        <source>written</source>
        <translation>書込み済み</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="137"/>
        <source>already set</source>
        <translation>設定済み</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="138"/>
        <source>yes</source>
        <translation>はい</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="138"/>
        <source>NO</source>
        <translation>いいえ</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="140"/>
        <source>Measurements</source>
        <translation>測定</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="141"/>
        <source>Step</source>
        <translation>ステップ</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="141"/>
        <source>Quantity</source>
        <translation>測定項目</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="141"/>
        <source>Limits</source>
        <translation>規格値</translation>
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
        <translation>このシリアルの過去の試験</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="148"/>
        <source>Reason</source>
        <translation>理由</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="150"/>
        <source>%1 rev. %2</source>
        <translation>%1 rev. %2</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="151"/>
        <source>–</source>
        <translation>–</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="161"/>
        <source>Bus traffic around the failure</source>
        <translation>不合格前後のバス通信</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="176"/>
        <source>read from the drive</source>
        <translation>ドライバから読出し</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="178"/>
        <source>proven by the variant probe</source>
        <translation>機種判定で確認済み</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="180"/>
        <source>confirmed by a person</source>
        <translation>担当者が確認</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="182"/>
        <source>ASSUMED, not proven</source>
        <translation>推定（未確認）</translation>
    </message>
    <message>
        <location filename="../model/eol/CertificateHtml.cpp" line="186"/>
        <location filename="../model/eol/CertificateHtml.cpp" line="192"/>
        <source>not known</source>
        <translation>不明</translation>
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
        <translation>出荷検査成績書 %1</translation>
    </message>
    <message>
        <location filename="../report/CertificatePdf.cpp" line="57"/>
        <source>%1 · %2 · page %3 of %4</source>
        <translation>%1 · %2 · %3 / %4 ページ</translation>
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
        <translation>使い方: %1 [options] COMMAND [arguments]

RS-485 Modbus-RTU モータドライバ用立上げツール。

コマンド:
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
接続（ドライバと通信するすべてのコマンド）:
  --port PATH | --tcp HOST:PORT | --sim SPEC
  --family F  --baud N  --parity N|E|O  --stop-bits N  --timeout MS  --retries N
  既定値はファミリによります: dbu 19200 8N1、dcpid 9600 8E1。--timeout 200、
  --retries 3（回線にノイズが多い間は 2 回追加: 最近の要求で再送が必要だった場合）。
  シリアルポートのみ: --rs485 off|auto|kernel|rts（RS-485 の送受信方向を
  切り替えるもの。off: アダプタ）、--rts-polarity high|low、--rts-delay US、
  --low-latency on|off（既定 on）。scan でシリアルドライバが受け付けた設定を表示します。
出力: --json  --trace  --variant VARIANT  --lang CODE
グループ: 書込みやコマンドの前に、バス上のドライバの通信グループを読み出します: --bus-drives LIST
（または OPENTOP_BUS_DRIVES）、なければこの接続の前回のスキャンで見つかったドライバ（ここまたはウィンドウで）。
どちらもない場合、グループの親になりうるドライバへの書込みは --no-group-check がない限り拒否されます

終了コード: 0 成功、1 通信失敗、2 使い方の誤り、3 不正な値またはファイル
（何も書き込まない）、4 照合不一致または停止しなかったドライバあり、
5 eol run 不合格、6 eol run ステーションエラー（製品の判定なし）、
130 Ctrl-C、SIGTERM、SIGHUP による中断（実行済みの内容を報告）。

&quot;%1 help COMMAND&quot; でコマンドのオプションを表示します。
</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="125"/>
        <source>note: standard output could not be written (closed early, or the disk is full): what the command printed there is lost; the work itself ran to its end and exit status %1 says how it ended</source>
        <translation>注意: 標準出力に書き込めませんでした（早く閉じられたか、ディスクが満杯）。コマンドがそこに出力した内容は失われました。作業自体は最後まで実行され、終了ステータス %1 がその結果を示します</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="190"/>
        <location filename="../cli/CliApp.cpp" line="245"/>
        <source>Try &quot;%1 --help&quot;.</source>
        <translation>&quot;%1 --help&quot; を実行してください。</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="210"/>
        <source>%1: unknown command &quot;%2&quot;; commands: </source>
        <translation>%1: 不明なコマンド &quot;%2&quot;。コマンド: </translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="219"/>
        <source>Usage: %1 [options] %2
%3
</source>
        <translation>使い方: %1 [options] %2
%3
</translation>
    </message>
    <message>
        <location filename="../cli/CliApp.cpp" line="233"/>
        <source>%1 %2: --%3 is not an option of this command; see &quot;%1 help %2&quot;</source>
        <translation>%1 %2: --%3 はこのコマンドのオプションではありません。&quot;%1 help %2&quot; を参照してください</translation>
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
        <translation>エラー: %1</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="154"/>
        <source>serial line: %1</source>
        <translation>シリアル回線: %1</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="177"/>
        <source>%1 &quot;%2&quot;: %3</source>
        <translation>%1 &quot;%2&quot;: %3</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="289"/>
        <source>machine number %1: no connection</source>
        <translation>局番 %1: 接続なし</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="294"/>
        <source>machine number %1: %2%3</source>
        <translation>局番 %1: %2%3</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="352"/>
        <source>--variant %1: &quot;%2&quot; is not a machine number 1–247</source>
        <translation>--variant %1: &quot;%2&quot; は局番 1–247 ではありません</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="356"/>
        <source>--variant %1: &quot;%2&quot; is not a drive variant; use one of %3</source>
        <translation>--variant %1: &quot;%2&quot; はドライバの機種ではありません。%3 のいずれかを指定してください</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="374"/>
        <source>&quot;%1&quot; is not a machine number 1–247 or a range such as 3-8</source>
        <translation>&quot;%1&quot; は局番 1–247 でも 3-8 のような範囲でもありません</translation>
    </message>
    <message>
        <location filename="../cli/CliContext.cpp" line="384"/>
        <source>no machine number given</source>
        <translation>局番が指定されていません</translation>
    </message>
</context>
<context>
    <name>opentop::CliIdentity</name>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="73"/>
        <source>Who does it (a user of the results database); the password comes from OPENTOP_PASSWORD or is asked on the terminal.</source>
        <translation>実行する人 (結果データベースのユーザー)。パスワードは OPENTOP_PASSWORD から取るか、端末で尋ねます。</translation>
    </message>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="75"/>
        <source>NAME</source>
        <translation>名前</translation>
    </message>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="86"/>
        <source>error: no password: set %1 or run on a terminal</source>
        <translation>エラー: パスワードがありません: %1 を設定するか端末で実行してください</translation>
    </message>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="91"/>
        <source>Again: </source>
        <translation>もう一度: </translation>
    </message>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="93"/>
        <source>error: the passwords differ; nothing was changed</source>
        <translation>エラー: パスワードが一致しません。何も変更していません</translation>
    </message>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="104"/>
        <source>error: name who does it with --user NAME</source>
        <translation>エラー: --user NAME で実行する人を指定してください</translation>
    </message>
    <message>
        <location filename="../cli/CliIdentity.cpp" line="108"/>
        <source>Password for %1: </source>
        <translation>%1 のパスワード: </translation>
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
        <translation>電源再投入</translation>
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
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../model/profile/CodeTable.cpp" line="29"/>
        <source>What to do: %1</source>
        <translation>対処: %1</translation>
    </message>
</context>
<context>
    <name>opentop::CommLossArm</name>
    <message>
        <location filename="../model/eol/CommLossArm.cpp" line="29"/>
        <source>cannot read %1: %2</source>
        <translation>%1 を読み取れません: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/CommLossArm.cpp" line="40"/>
        <source>the communication-loss stop cannot be armed (%1 = %2 s): %3; the motor is not started without it</source>
        <translation>通信途絶停止を有効にできません（%1 = %2 s）: %3。これなしではモーターを起動しません</translation>
    </message>
</context>
<context>
    <name>opentop::CommandReadBack</name>
    <message>
        <location filename="../ui/run/CommandReadBack.cpp" line="43"/>
        <source>Read back after the command at %1:</source>
        <translation>%1 のコマンド後の読み戻し:</translation>
    </message>
    <message>
        <location filename="../ui/run/CommandReadBack.cpp" line="46"/>
        <source>The motor is running.</source>
        <translation>モータは運転中です。</translation>
    </message>
    <message>
        <location filename="../ui/run/CommandReadBack.cpp" line="46"/>
        <source>The motor is stopped.</source>
        <translation>モータは停止しています。</translation>
    </message>
    <message>
        <location filename="../ui/run/CommandReadBack.cpp" line="48"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../ui/run/CommandReadBack.cpp" line="50"/>
        <source>(not read: %1)</source>
        <translation>（未読出し: %1）</translation>
    </message>
    <message>
        <location filename="../ui/run/CommandReadBack.cpp" line="57"/>
        <source>The drives of its communication group, read after the command:</source>
        <translation>コマンド後に読み出した通信グループのドライバ:</translation>
    </message>
</context>
<context>
    <name>opentop::CompareCommand</name>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="36"/>
        <source>Show the settings that differ; A, B: a machine number, FILE or FILE:ID (exit 0 whether or not they differ)</source>
        <translation>異なる設定を表示します。A、B: 局番、FILE または FILE:ID（差異の有無にかかわらず終了コード 0）</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="43"/>
        <source>Compare A with the profile&apos;s factory defaults; settings the manual gives no default for are listed, never counted as differences.</source>
        <translation>A をプロファイルの工場出荷時設定と比較します。マニュアルに初期値の記載がない設定は一覧に表示しますが、差異としては数えません。</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="70"/>
        <location filename="../cli/CompareCommand.cpp" line="87"/>
        <location filename="../cli/CompareCommand.cpp" line="146"/>
        <source>error: %1</source>
        <translation>エラー: %1</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="64"/>
        <source>interrupted</source>
        <translation>中断</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="74"/>
        <source>drive %1</source>
        <translation>ドライバ %1</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="106"/>
        <source>error: %1 holds several drives (%2): name one as %1:ID</source>
        <translation>エラー: %1 には複数のドライバ (%2) が含まれています。%1:ID の形式で 1 台を指定してください</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="110"/>
        <source>error: %1 holds no drive with machine number %2; it holds %3</source>
        <translation>エラー: %1 に局番 %2 のドライバは含まれていません。含まれているのは %3 です</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="126"/>
        <source>error: compare A B, or compare A --defaults (A, B: a machine number, FILE or FILE:ID)</source>
        <translation>エラー: compare A B、または compare A --defaults（A、B: 局番、FILE または FILE:ID）</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="144"/>
        <source>factory defaults</source>
        <translation>工場出荷時設定</translation>
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
        <translation>パラメータ</translation>
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
        <translation>（含まれていません）</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="186"/>
        <source> in %1 settings compared</source>
        <translation> （比較した設定 %1 個）</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="188"/>
        <source>no differences (%1 settings compared)</source>
        <translation>差異なし（比較した設定 %1 個）</translation>
    </message>
    <message>
        <location filename="../cli/CompareCommand.cpp" line="195"/>
        <source>note: %1</source>
        <translation>注: %1</translation>
    </message>
</context>
<context>
    <name>opentop::CompareDialog</name>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="33"/>
        <source>&amp;Differences only</source>
        <translation>差異のみ(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="37"/>
        <source>Co&amp;mpare</source>
        <translation>比較(&amp;M)</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="39"/>
        <source>Compare settings</source>
        <translation>設定の比較</translation>
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
        <translation>パラメータ</translation>
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
        <translation>設定名またはパラメータ名で絞り込み</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="65"/>
        <source>Read the chosen sides and compare them (drives are read fresh)</source>
        <translation>選択した両側を読み出して比較します（ドライバは改めて読み出します）</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="78"/>
        <source>C&amp;lose</source>
        <translation>閉じる(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="111"/>
        <source>%1 refused: %2</source>
        <translation>%1 は使用できません: %2</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="125"/>
        <source>Reading…</source>
        <translation>読出し中…</translation>
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
        <translation>工場出荷時設定</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="161"/>
        <source>Choose a backup file and a drive in it for %1.</source>
        <translation>%1 のバックアップファイルと、その中のドライバを選択してください。</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="165"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="175"/>
        <source>Choose an identified drive on the bus for %1.</source>
        <translation>%1 にはバス上の識別済みドライバを選択してください。</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="183"/>
        <source>%1: cannot read %2</source>
        <translation>%1: %2 を読み出せません</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="208"/>
        <source>Unknown family %1</source>
        <translation>不明なファミリ %1</translation>
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
        <translation>工場出荷時設定 (%1)</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="239"/>
        <source>(no documented default)</source>
        <translation>（初期値の記載なし）</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="240"/>
        <location filename="../ui/files/CompareDialog.cpp" line="242"/>
        <source>(not held)</source>
        <translation>（含まれていません）</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/CompareDialog.cpp" line="258"/>
        <source>%n difference(s)</source>
        <translation>
            <numerusform>%n 件の差異</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="259"/>
        <source> in %1 settings compared</source>
        <translation> （比較した設定 %1 個）</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="262"/>
        <source>Note: %1</source>
        <translation>注: %1</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareDialog.cpp" line="269"/>
        <source>No factory default documented (never counted as a difference): %1</source>
        <translation>工場出荷時設定の記載なし（差異としては数えません）: %1</translation>
    </message>
</context>
<context>
    <name>opentop::CompareSide</name>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="23"/>
        <source>Browse…</source>
        <translation>参照…</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="27"/>
        <source>Drive on the bus</source>
        <translation>バス上のドライバ</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="28"/>
        <source>Drive in a backup file</source>
        <translation>バックアップファイル内のドライバ</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="30"/>
        <source>Factory defaults</source>
        <translation>工場出荷時設定</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="34"/>
        <source>Drive %1 (%2)</source>
        <translation>ドライバ %1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="41"/>
        <source>Backup file</source>
        <translation>バックアップファイル</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="46"/>
        <source>Source:</source>
        <translation>取得元:</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="47"/>
        <source>Drive:</source>
        <translation>ドライバ:</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="48"/>
        <source>File:</source>
        <translation>ファイル:</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="49"/>
        <source>Drive in file:</source>
        <translation>ファイル内のドライバ:</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="170"/>
        <source>Open backup file</source>
        <translation>バックアップファイルを開く</translation>
    </message>
    <message>
        <location filename="../ui/files/CompareSide.cpp" line="171"/>
        <source>OpenTOP backups (*.json);;All files (*)</source>
        <translation>OpenTOP バックアップ (*.json);;すべてのファイル (*)</translation>
    </message>
</context>
<context>
    <name>opentop::Comparer</name>
    <message>
        <location filename="../model/files/Comparer.cpp" line="15"/>
        <source>nothing to compare: %1 is a %2 drive, %3 a %4 drive</source>
        <translation>比較できません: %1 は %2 ドライバ、%3 は %4 ドライバです</translation>
    </message>
    <message>
        <location filename="../model/files/Comparer.cpp" line="20"/>
        <source>the variants differ: %1 and %2</source>
        <translation>機種が異なります: %1 と %2</translation>
    </message>
    <message>
        <location filename="../model/files/Comparer.cpp" line="55"/>
        <source>factory defaults</source>
        <translation>工場出荷時設定</translation>
    </message>
</context>
<context>
    <name>opentop::ConnectionDialog</name>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="63"/>
        <source>Connect to a bus</source>
        <translation>バスに接続</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="68"/>
        <source>&amp;Serial port</source>
        <translation>シリアルポート(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="68"/>
        <source>Modbus &amp;TCP gateway</source>
        <translation>Modbus TCP ゲートウェイ(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="69"/>
        <source>Si&amp;mulated bus</source>
        <translation>シミュレーションバス(&amp;M)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="85"/>
        <source>&amp;Advanced</source>
        <translation>詳細設定(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="108"/>
        <source>&amp;Connect</source>
        <translation>接続(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="129"/>
        <source>&amp;Refresh</source>
        <translation>更新(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="130"/>
        <source>List the serial ports again (after plugging in an adapter)</source>
        <translation>シリアルポートを再検索します（アダプタ接続後）</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="135"/>
        <source>&amp;Port:</source>
        <translation>ポート(&amp;P):</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="144"/>
        <source>Custom</source>
        <translation>カスタム</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="146"/>
        <source>%1 (%2 %3%4%5)</source>
        <translation>%1 (%2 %3%4%5)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="153"/>
        <source>Fills in the factory line settings of a drive family</source>
        <translation>ドライバファミリの工場出荷時の通信設定を入力します</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="156"/>
        <source>&amp;Family defaults:</source>
        <translation>ファミリ既定値(&amp;F):</translation>
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
        <translation>ボーレート(&amp;B):</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="163"/>
        <source>None (N)</source>
        <translation>なし (N)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="164"/>
        <source>Even (E)</source>
        <translation>偶数 (E)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="165"/>
        <source>Odd (O)</source>
        <translation>奇数 (O)</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="166"/>
        <source>P&amp;arity:</source>
        <translation>パリティ(&amp;A):</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="168"/>
        <source>1 bit</source>
        <translation>1 ビット</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="169"/>
        <source>2 bits</source>
        <translation>2 ビット</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="170"/>
        <source>S&amp;top bits:</source>
        <translation>ストップビット(&amp;T):</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="186"/>
        <source>e.g. 192.168.1.10</source>
        <translation>例: 192.168.1.10</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="187"/>
        <source>&amp;Host:</source>
        <translation>ホスト(&amp;H):</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="190"/>
        <source>Modbus TCP uses port 502</source>
        <translation>Modbus TCP はポート 502 を使用します</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="191"/>
        <source>TCP p&amp;ort:</source>
        <translation>TCP ポート(&amp;O):</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="203"/>
        <source>Device types and machine numbers: TYPE@NUMBER, comma separated. Types: %1</source>
        <translation>デバイスタイプと局番: TYPE@NUMBER をカンマ区切りで指定。タイプ: %1</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="206"/>
        <source>&amp;Devices:</source>
        <translation>デバイス(&amp;D):</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="220"/>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="221"/>
        <source>How long to wait for each reply</source>
        <translation>各応答の待ち時間</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="222"/>
        <source>Response &amp;timeout:</source>
        <translation>応答タイムアウト(&amp;T):</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="225"/>
        <source>Extra attempts after a request got no valid reply</source>
        <translation>有効な応答がなかった要求の再試行回数</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="226"/>
        <source>R&amp;etries:</source>
        <translation>リトライ(&amp;E):</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialog.cpp" line="333"/>
        <source>The device list is not valid.</source>
        <translation>デバイスリストが正しくありません。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="26"/>
        <source>The port is in use by another program (named above where the system tells it): a terminal program, ModemManager, another OpenTOP window or an opentop-cli command. Close it, or disconnect the other window, and connect again. Nothing was sent on the port.</source>
        <translation>ポートは他のプログラムが使用中です（システムが通知する場合は上に表示）: 端末プログラム、ModemManager、別の OpenTOP ウィンドウ、opentop-cli コマンドなど。そのプログラムを終了するか別のウィンドウで切断してから、再度接続してください。ポートには何も送信していません。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="33"/>
        <source>Your user may not open serial ports: add it to the dialout group with the command above, then log out and in again.</source>
        <translation>このユーザはシリアルポートを開けません: 上記のコマンドで dialout グループに追加し、ログアウトして再ログインしてください。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="36"/>
        <source>Your user may not open serial ports. Add it to the dialout group:
    sudo usermod -aG dialout $USER
then log out and in again (the group applies to new sessions only).</source>
        <translation>このユーザはシリアルポートを開けません。dialout グループに追加してください:
    sudo usermod -aG dialout $USER
その後、ログアウトして再ログインしてください（グループは新しいセッションにのみ適用されます）。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="41"/>
        <source>The port %1 does not exist: the USB adapter may be unplugged or have come back under another name, or the path is mistyped. Plug it in, press Refresh and pick it from the list; for a pseudo-terminal check that the program serving it (opentop-sim, socat) still runs.</source>
        <translation>ポート %1 が存在しません: USB アダプタが外れているか、別の名前で再接続されたか、パスの入力ミスです。アダプタを接続し、「更新」を押してリストから選択してください。疑似端末の場合は、それを提供するプログラム (opentop-sim、socat) が動作していることを確認してください。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="48"/>
        <source>The connection opened but no drive answered. Check that the baud rate, parity and stop bits (%1) match the drives&apos; settings (DBU: 19200 8N1, DC controller: 9600 8E1) — a framing mismatch looks like silence — that the machine number is right, and that the A and B (D+ and D−) wires are not swapped.</source>
        <translation>接続は開きましたが、応答したドライバはありません。ボーレート、パリティ、ストップビット (%1) がドライバの設定（DBU: 19200 8N1、DC コントローラ: 9600 8E1）と一致しているか（フレーム形式が違うと無応答に見えます）、局番が正しいか、A と B（D+ と D−）の線が入れ違っていないかを確認してください。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="56"/>
        <source>The gateway %1:%2 did not accept the connection: check the address and port (Modbus TCP uses 502), that the gateway is powered and on this network, and that no firewall blocks it.</source>
        <translation>ゲートウェイ %1:%2 が接続を受け付けませんでした: アドレスとポート（Modbus TCP は 502）、ゲートウェイの電源が入っていてこのネットワーク上にあるか、ファイアウォールでブロックされていないかを確認してください。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="63"/>
        <source>Check that the adapter is plugged in, that %1 is the right port, and that no other program uses it.</source>
        <translation>アダプタが接続されているか、%1 が正しいポートか、他のプログラムが使用していないかを確認してください。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="66"/>
        <source>Check the connection settings and try again.</source>
        <translation>接続設定を確認して、再度実行してください。</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="68"/>
        <source>Could not use %1: %2</source>
        <translation>%1 を使用できませんでした: %2</translation>
    </message>
    <message>
        <location filename="../ui/connection/ConnectionDialogExplain.cpp" line="69"/>
        <source>What to check:</source>
        <translation>確認事項:</translation>
    </message>
</context>
<context>
    <name>opentop::ConnectionOptions</name>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="30"/>
        <source>--rs485 %1: use off (the adapter switches direction itself), auto, kernel or rts</source>
        <translation>--rs485 %1: off（アダプタ自身が方向を切替）、auto、kernel、rts のいずれかを指定してください</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="36"/>
        <source>--rts-polarity %1: use high or low (the RTS level while sending)</source>
        <translation>--rts-polarity %1: high または low を指定してください（送信中の RTS レベル）</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="44"/>
        <source>--rts-delay %1: use 0–%2 µs (0: the driver&apos;s or libmodbus&apos; own delay)</source>
        <translation>--rts-delay %1: 0–%2 µs を指定してください（0: シリアルドライバまたは libmodbus 自身の遅延）</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="51"/>
        <source>--low-latency %1: use on or off</source>
        <translation>--low-latency %1: on または off を指定してください</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="61"/>
        <source>--%1 applies to a serial port (--port), not to a Modbus TCP gateway (--tcp)</source>
        <translation>--%1 はシリアルポート (--port) 用です。Modbus TCP ゲートウェイ (--tcp) には適用されません</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="65"/>
        <source>--%1 applies to a serial port (--port), not to a simulated bus</source>
        <translation>--%1 はシリアルポート (--port) 用です。シミュレーションバスには適用されません</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="66"/>
        <source>--%1 applies to a serial port only: give it with --port PATH</source>
        <translation>--%1 はシリアルポート専用です: --port PATH と一緒に指定してください</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="74"/>
        <source>Serial device (e.g. /dev/ttyUSB0 or a pty path).</source>
        <translation>シリアルデバイス（例: /dev/ttyUSB0 または pty のパス）。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="75"/>
        <source>PATH</source>
        <translation>PATH</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="76"/>
        <source>Modbus TCP gateway, HOST:PORT (port defaults to 502).</source>
        <translation>Modbus TCP ゲートウェイ、HOST:PORT（ポートの既定値は 502）。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="77"/>
        <source>HOST:PORT</source>
        <translation>HOST:PORT</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="78"/>
        <source>In-process simulated bus, e.g. dbu200@1,dbu400@150,dcpid@7.</source>
        <translation>プロセス内のシミュレーションバス。例: dbu200@1,dbu400@150,dcpid@7。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="79"/>
        <source>SPEC</source>
        <translation>SPEC</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="81"/>
        <source>Device family whose serial defaults apply (dbu: 19200 8N1, dcpid: 9600 8E1).</source>
        <translation>シリアル既定値を適用するデバイスファミリ（dbu: 19200 8N1、dcpid: 9600 8E1）。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="82"/>
        <source>FAMILY</source>
        <translation>FAMILY</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="83"/>
        <source>Baud rate, 1200–115200.</source>
        <translation>ボーレート、1200–115200。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="83"/>
        <source>BAUD</source>
        <translation>BAUD</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="84"/>
        <source>Parity: N, E or O.</source>
        <translation>パリティ: N、E、O。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="84"/>
        <source>N|E|O</source>
        <translation>N|E|O</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="85"/>
        <source>Stop bits: 1 or 2.</source>
        <translation>ストップビット: 1 または 2。</translation>
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
        <translation>ポートと異なる通信フォーマットのドライブ。トランザクションの合間に切り替えます: ID=[BAUD:]FORMAT,... 例: 7=9600:8E1 または 7=8N2（BAUD の既定はポートの速度）。DBU は 8N1 のみ、DC コントローラは 8E1、8O1、8N2。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="90"/>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="92"/>
        <source>Response timeout per attempt in ms, 10–10000 (default 200).</source>
        <translation>1 回あたりの応答タイムアウト (ms)、10–10000（既定値 200）。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="92"/>
        <source>MS</source>
        <translation>MS</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="94"/>
        <source>Extra attempts after no reply or a garbled one, 0–10 (default 3; 2 more while the line is noisy).</source>
        <translation>無応答または応答化けの後の再試行回数、0–10（既定値 3。回線にノイズが多い間は 2 回追加）。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="98"/>
        <source>Who switches the RS-485 direction (serial port only): off (default: the adapter itself, as USB–RS-485 adapters do), kernel (the driver&apos;s RS-485 mode), rts (RTS from the program) or auto (kernel where the driver has it, else rts).</source>
        <translation>RS-485 の送受信方向を切り替えるもの（シリアルポートのみ）: off（既定: USB–RS-485 アダプタのようにアダプタ自身が切替）、kernel（シリアルドライバの RS-485 モード）、rts（プログラムによる RTS 制御）、auto（シリアルドライバが対応していれば kernel、なければ rts）。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="101"/>
        <source>MODE</source>
        <translation>MODE</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="103"/>
        <source>RTS level while sending with --rs485 kernel, rts or auto: high (default) or low.</source>
        <translation>--rs485 kernel、rts、auto 使用時の送信中の RTS レベル: high（既定）または low。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="104"/>
        <source>high|low</source>
        <translation>high|low</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="106"/>
        <source>RTS delay before and after sending in µs, 0–100000 (default 0: the driver&apos;s, or libmodbus&apos; one character time; the kernel rounds up to whole ms).</source>
        <translation>送信前後の RTS 遅延 (µs)、0–100000（既定 0: シリアルドライバの遅延、または libmodbus の 1 文字時間。カーネルは ms 単位に切り上げます）。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="108"/>
        <source>US</source>
        <translation>US</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="110"/>
        <source>Ask the serial driver to pass received bytes on at once (USB adapters otherwise hold them up to 16 ms): on (default) or off.</source>
        <translation>受信したバイトをすぐに渡すようシリアルドライバに要求します（要求しないと USB アダプタは最大 16 ms 保持）: on（既定）または off。</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="112"/>
        <source>on|off</source>
        <translation>on|off</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="157"/>
        <source>give only one of --port, --tcp and --sim</source>
        <translation>--port、--tcp、--sim のいずれか 1 つだけを指定してください</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="159"/>
        <source>no bus given: use --port PATH, --tcp HOST:PORT or --sim SPEC</source>
        <translation>バスが指定されていません: --port PATH、--tcp HOST:PORT、--sim SPEC のいずれかを使用してください</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="168"/>
        <source>--family %1: unknown family; use one of %2</source>
        <translation>--family %1: 不明なファミリです。%2 のいずれかを使用してください</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="187"/>
        <source>--tcp: &quot;%1&quot; is not HOST:PORT</source>
        <translation>--tcp: &quot;%1&quot; は HOST:PORT ではありません</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="196"/>
        <source>--sim: %1</source>
        <translation>--sim: %1</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="209"/>
        <source>--baud %1: use a baud rate 1200–115200 (e.g. 9600, 19200, 38400)</source>
        <translation>--baud %1: ボーレートは 1200–115200 を指定してください（例: 9600、19200、38400）</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="213"/>
        <source>--stop-bits %1: use 1 or 2</source>
        <translation>--stop-bits %1: 1 または 2 を指定してください</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="215"/>
        <source>--timeout %1: use a response timeout of 10–10000 ms</source>
        <translation>--timeout %1: 応答タイムアウトは 10–10000 ms を指定してください</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="218"/>
        <source>--retries %1: use 0–10 extra attempts</source>
        <translation>--retries %1: 再試行回数は 0–10 を指定してください</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="223"/>
        <source>--parity %1: use N (none), E (even) or O (odd)</source>
        <translation>--parity %1: N（なし）、E（偶数）、O（奇数）を指定してください</translation>
    </message>
    <message>
        <location filename="../connection/ConnectionOptions.cpp" line="229"/>
        <source>--drive-format applies to a serial port (--port) or a simulated bus, not to a Modbus TCP gateway (--tcp): the gateway sets its line itself</source>
        <translation>--drive-format はシリアルポート（--port）またはシミュレーションバスに適用され、Modbus TCP ゲートウェイ（--tcp）には適用されません。ゲートウェイは回線を自分で設定します</translation>
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
        <translation>シミュレーションバス — ハードウェアなし</translation>
    </message>
    <message>
        <location filename="../ui/main/ConnectionStatus.cpp" line="22"/>
        <source>These drives exist only in this program; nothing moves.</source>
        <translation>これらのドライバはこのプログラム内にのみ存在します。何も動きません。</translation>
    </message>
    <message>
        <location filename="../ui/main/ConnectionStatus.cpp" line="27"/>
        <location filename="../ui/main/ConnectionStatus.cpp" line="76"/>
        <source>Not connected</source>
        <translation>未接続</translation>
    </message>
    <message>
        <location filename="../ui/main/ConnectionStatus.cpp" line="54"/>
        <source>Connected: %1</source>
        <translation>接続済み: %1</translation>
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
        <translation>通信グループ: %1（バス › 通信グループ）</translation>
    </message>
</context>
<context>
    <name>opentop::DbuSimDevice</name>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="340"/>
        <source>alarm 0x%1</source>
        <translation>アラーム 0x%1</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="341"/>
        <source>running</source>
        <translation>運転中</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="342"/>
        <source>stopped</source>
        <translation>停止</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="343"/>
        <source>%1 %2 r/min (target %3) SPno%4 load %5 % %6, %7 priority, %8%9</source>
        <translation>%1 %2 r/min（目標 %3）SPno%4 負荷 %5 % %6、%7優先、%8%9</translation>
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
        <translation>オフライン</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="348"/>
        <source>online</source>
        <translation>オンライン</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="349"/>
        <source>, ignoring stop</source>
        <translation>、停止を無視</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="357"/>
        <source>usage: %1 ID CODE</source>
        <translation>使い方: %1 ID CODE</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="360"/>
        <source>warning cleared</source>
        <translation>警告を解除しました</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="365"/>
        <source>unknown %1 code %2; allowed: %3</source>
        <translation>不明な %1 コード %2。使用可能: %3</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="373"/>
        <source>%1 0x%2 raised</source>
        <translation>%1 0x%2 を発生させました</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="384"/>
        <source>usage: ignore-stop ID on|off</source>
        <translation>使い方: ignore-stop ID on|off</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="386"/>
        <source>stop commands are acknowledged and ignored</source>
        <translation>停止コマンドに応答しますが、無視します</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="387"/>
        <source>stop commands are obeyed</source>
        <translation>停止コマンドに従います</translation>
    </message>
    <message>
        <location filename="../sim/DbuSimDevice.cpp" line="403"/>
        <source>usage: %1 ID VALUE with VALUE %2..%3</source>
        <translation>使い方: %1 ID VALUE（VALUE は %2..%3）</translation>
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
        <translation>DC コントローラ</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="46"/>
        <source>Re&amp;load stored configuration</source>
        <translation>保存済み設定を再読込み(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="68"/>
        <source>Store &amp;configuration</source>
        <translation>設定を保存(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="69"/>
        <source>Store P&amp;ID</source>
        <translation>PID を保存(&amp;I)</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="70"/>
        <source>Store pre&amp;set</source>
        <translation>設定速度を保存(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="73"/>
        <source>Writes %1 = 1: %2</source>
        <translation>%1 = 1 を書込み: %2</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="78"/>
        <source>Writes store.config = 0: the controller reloads the stored configuration; unstored configuration changes are discarded</source>
        <translation>store.config = 0 を書込み: コントローラは保存済みの設定を再読込みします。保存していない設定変更は破棄されます</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="85"/>
        <source>Speed mode and motor currents</source>
        <translation>速度モードとモータ電流</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="86"/>
        <source>Speed &amp;mode:</source>
        <translation>速度モード(&amp;M):</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="87"/>
        <source>Rated current:</source>
        <translation>定格電流:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="88"/>
        <source>Maximum start/load current:</source>
        <translation>最大起動/負荷電流:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="89"/>
        <source>Brake current:</source>
        <translation>ブレーキ電流:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="91"/>
        <source>Limit switches</source>
        <translation>リミットスイッチ</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="92"/>
        <source>Limits:</source>
        <translation>リミット:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="93"/>
        <source>SQ1 active level (forward):</source>
        <translation>SQ1 アクティブレベル（正転）:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="94"/>
        <source>SQ2 active level (reverse):</source>
        <translation>SQ2 アクティブレベル（逆転）:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="96"/>
        <source>Protective stops (0 = off)</source>
        <translation>保護停止（0 = 無効）</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="97"/>
        <source>S&amp;tall stop time:</source>
        <translation>ストール停止時間(&amp;T):</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="98"/>
        <source>Communication loss stop time:</source>
        <translation>通信断停止時間:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="106"/>
        <source>Serial port (used from the next power-up)</source>
        <translation>シリアルポート（次回の電源投入から有効）</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="111"/>
        <source>Baud rate and parity are written as one 15-register block from 0x0080 that also stores the configuration; the controller uses them from the next power-up on: switch it off and on, then reconnect with them. The lock is lost at power-off until stored (Store configuration).</source>
        <translation>ボーレートとパリティは 0x0080 からの 15 レジスタの一括書込みで書き込まれ、この書込みで設定も保存されます。コントローラは次回の電源投入からこれらを使用します: 電源を入れ直し、新しい設定で再接続してください。シリアル設定ロックは保存（設定を保存）するまで電源オフで失われます。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="133"/>
        <source>Takes effect now and is kept over power-off: each change is written as one 5-register block from 0x0050 that also stores the port states.</source>
        <translation>即時に有効になり、電源オフ後も保持されます: 変更のたびに 0x0050 からの 5 レジスタの一括書込みで書き込まれ、この書込みでポート状態も保存されます。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="175"/>
        <source>The communication loss stop time is 0 s (%1): the manual does not say what 0 does, and OpenTOP assumes the stop is then off: if the connection is lost while the motor runs, the controller keeps it running at the last speed command. Set a time so that it brakes when the bus goes quiet.</source>
        <translation>通信断停止時間が 0 s です (%1): マニュアルは 0 の意味を記載しておらず、OpenTOP はこの場合停止が無効になると仮定しています: モータ運転中に接続が切れると、コントローラは最後の速度指令で運転を続けます。バスが無通信になったときにブレーキがかかるよう、時間を設定してください。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="107"/>
        <source>Baud rate:</source>
        <translation>ボーレート:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="108"/>
        <source>Parity and stop bits:</source>
        <translation>パリティとストップビット:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="109"/>
        <source>Configuration over serial:</source>
        <translation>シリアル経由の設定:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="115"/>
        <source>Speed loop PID</source>
        <translation>速度ループ PID</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="116"/>
        <source>&amp;P coefficient:</source>
        <translation>P 係数(&amp;P):</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="117"/>
        <source>I coefficient:</source>
        <translation>I 係数:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="118"/>
        <source>&amp;D coefficient:</source>
        <translation>D 係数(&amp;D):</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="119"/>
        <source>D period:</source>
        <translation>D 周期:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="121"/>
        <source>Preset speed (potentiometer/analog control)</source>
        <translation>設定速度（ボリューム/アナログ制御）</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="122"/>
        <source>Preset speed mo&amp;de:</source>
        <translation>設定速度モード(&amp;D):</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="123"/>
        <source>Trigger:</source>
        <translation>トリガ:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="124"/>
        <source>&amp;Forward speed:</source>
        <translation>正転速度(&amp;F):</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="125"/>
        <source>Reverse speed:</source>
        <translation>逆転速度:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="127"/>
        <source>AI1/AI2 as digital ports</source>
        <translation>AI1/AI2 をデジタルポートとして使用</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="128"/>
        <source>AI1 direction:</source>
        <translation>AI1 方向:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="129"/>
        <source>AI2 direction:</source>
        <translation>AI2 方向:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="130"/>
        <source>AI1 level:</source>
        <translation>AI1 レベル:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="131"/>
        <source>AI2 level:</source>
        <translation>AI2 レベル:</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="191"/>
        <source>Takes effect now, lost at power-off until stored (%1).</source>
        <translation>即時に有効。保存 (%1) するまでは電源オフで失われます。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="252"/>
        <source>Set it anyway?</source>
        <translation>それでも設定しますか？</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="268"/>
        <source>Forward and reverse speed in this mode (%1): %2</source>
        <translation>このモード (%1) での正転速度と逆転速度: %2</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="270"/>
        <source>The unit and range of the speeds follow the preset speed mode (not read yet).</source>
        <translation>速度の単位と範囲は設定速度モードによります（未読出し）。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="294"/>
        <source>&lt;b&gt;Written but not stored:&lt;/b&gt; %1. These values act now and are lost when the controller is switched off.</source>
        <translation>&lt;b&gt;書込み済み・未保存:&lt;/b&gt; %1。これらの値は現在有効ですが、コントローラの電源を切ると失われます。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="316"/>
        <source>%1: the controller writes the values now in effect to its memory and uses them from the next power-up on.

Stored: %2.</source>
        <translation>%1: コントローラは現在有効な値をメモリに書き込み、次回の電源投入から使用します。

保存: %2。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="327"/>
        <source>Not written yet, so not stored: %1.</source>
        <translation>未書込みのため保存されていません: %1。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="330"/>
        <source>%1: done, kept over power-off.</source>
        <translation>%1: 完了。電源オフ後も保持されます。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="338"/>
        <source>The controller replaces its configuration (%1) with the one stored in its memory.

Configuration changes written but not stored are discarded.</source>
        <translation>コントローラは設定 (%1) をメモリに保存されているものに置き換えます。

書込み済みで未保存の設定変更は破棄されます。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="344"/>
        <source>Stored configuration reloaded.</source>
        <translation>保存済み設定を再読込みしました。</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="352"/>
        <source>Writing %1 = %2…</source>
        <translation>%1 = %2 を書込み中…</translation>
    </message>
    <message>
        <location filename="../ui/pages/DcControllerPage.cpp" line="362"/>
        <source>%1 = %2 failed: %3</source>
        <translation>%1 = %2 失敗: %3</translation>
    </message>
</context>
<context>
    <name>opentop::DcMotor</name>
    <message>
        <location filename="../sim/DcMotor.cpp" line="64"/>
        <source>unknown motor setting &apos;%1&apos;; settings: %2</source>
        <translation>不明なモータ設定 &apos;%1&apos;。設定: %2</translation>
    </message>
    <message>
        <location filename="../sim/DcMotor.cpp" line="71"/>
        <source>motor setting %1 must be a number %2..%3, got &apos;%4&apos;</source>
        <translation>モータ設定 %1 は %2..%3 の数値でなければなりません（指定値 &apos;%4&apos;）</translation>
    </message>
</context>
<context>
    <name>opentop::DcPidSimDevice</name>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="366"/>
        <source>%1 %2%3, output %4 %, command %5, line %6 %7</source>
        <translation>%1 %2%3、出力 %4 %、指令 %5、回線 %6 %7</translation>
    </message>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="368"/>
        <source> (stall stop)</source>
        <translation> (ストール停止)</translation>
    </message>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="384"/>
        <source>usage: %1 ID VALUE with VALUE %2..%3 %4</source>
        <translation>使い方: %1 ID VALUE（VALUE は %2..%3 %4）</translation>
    </message>
    <message>
        <location filename="../sim/DcPidSimDevice.cpp" line="388"/>
        <source>(bit0 SQ1, bit1 SQ2, bit2 DE)</source>
        <translation>(bit0 SQ1、bit1 SQ2、bit2 DE)</translation>
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
        <translation>モータ %1、速度 %2 1/s、電流 %3 A</translation>
    </message>
</context>
<context>
    <name>opentop::DcRunCommands</name>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="26"/>
        <source>Set s&amp;peed</source>
        <translation>速度設定(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="31"/>
        <source>set point, e.g. 50 or -20</source>
        <translation>設定値。例: 50 または -20</translation>
    </message>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="39"/>
        <source>Speed command:</source>
        <translation>速度指令:</translation>
    </message>
    <message>
        <location filename="../ui/run/DcRunCommands.cpp" line="54"/>
        <source>&amp;Brake (speed 0)</source>
        <translation>ブレーキ（速度 0）(&amp;B)</translation>
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
        <translation>（%1 を読出し中…）</translation>
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
        <translation>%1 = %2 とすると %3 が有効な値でなくなります（許容値がこの値に依存するため）。それらの新しい値を選択し、一緒に書き込んでください。</translation>
    </message>
    <message>
        <location filename="../model/session/DependentValues.cpp" line="57"/>
        <source>%1 cannot be checked: the values of %2 depend on it and could not be read</source>
        <translation>%1 はチェックできません: これに依存する %2 の値を読み出せませんでした</translation>
    </message>
</context>
<context>
    <name>opentop::DeviceIdentifier</name>
    <message>
        <location filename="../model/session/DeviceIdentifier.cpp" line="31"/>
        <source>answers, but none of the device profiles matches</source>
        <translation>応答はありますが、一致するデバイスプロファイルがありません</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceIdentifier.cpp" line="96"/>
        <source>device name &quot;%1&quot; is not a %2</source>
        <translation>デバイス名 &quot;%1&quot; は %2 ではありません</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceIdentifier.cpp" line="116"/>
        <source>the variant cannot be read from the device; choose it</source>
        <translation>デバイスから機種を読み出せません。選択してください</translation>
    </message>
</context>
<context>
    <name>opentop::DeviceInfo</name>
    <message>
        <location filename="../model/session/DeviceInfo.cpp" line="59"/>
        <source>not checked</source>
        <translation>未確認</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceInfo.cpp" line="61"/>
        <source>online</source>
        <translation>オンライン</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceInfo.cpp" line="63"/>
        <source>no answer</source>
        <translation>応答なし</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceInfo.cpp" line="65"/>
        <source>garbled replies (duplicate machine number?)</source>
        <translation>応答化け（局番の重複？）</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceInfo.cpp" line="68"/>
        <source>unknown device</source>
        <translation>不明なデバイス</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceInfo.cpp" line="70"/>
        <source>answered, identification failed</source>
        <translation>応答あり、識別失敗</translation>
    </message>
</context>
<context>
    <name>opentop::DeviceMonitor</name>
    <message>
        <location filename="../model/monitor/DeviceMonitor.cpp" line="66"/>
        <source>Stopped</source>
        <translation>停止中</translation>
    </message>
    <message>
        <location filename="../model/monitor/DeviceMonitor.cpp" line="68"/>
        <source>Running</source>
        <translation>運転中</translation>
    </message>
    <message>
        <location filename="../model/monitor/DeviceMonitor.cpp" line="69"/>
        <source>Running CCW</source>
        <translation>CCW 運転中</translation>
    </message>
    <message>
        <location filename="../model/monitor/DeviceMonitor.cpp" line="69"/>
        <source>Running CW</source>
        <translation>CW 運転中</translation>
    </message>
    <message>
        <location filename="../model/monitor/DeviceMonitor.cpp" line="212"/>
        <source>machine number %1: %2</source>
        <translation>局番 %1: %2</translation>
    </message>
</context>
<context>
    <name>opentop::DeviceParameters</name>
    <message>
        <location filename="../model/session/DeviceParameters.cpp" line="92"/>
        <source>%1 has no parameter &quot;%2&quot;</source>
        <translation>%1 にはパラメータ &quot;%2&quot; がありません</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceParameters.cpp" line="94"/>
        <source>%1 is read-only</source>
        <translation>%1 は読出し専用です</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceParameters.cpp" line="96"/>
        <source>%1 is a command, not a setting; commands are sent one by one on request</source>
        <translation>%1 は設定ではなくコマンドです。コマンドは要求に応じて 1 つずつ送信します</translation>
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
            <numerusform>%n 件の書込みに失敗しました: %1</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/session/DeviceParameters.cpp" line="289"/>
        <source>Written, but not verified on every drive it reached: %1</source>
        <translation>書き込みましたが、届いたすべてのドライバでは確認できていません: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/session/DeviceParameters.cpp" line="292"/>
        <source>%n value(s) written and verified</source>
        <translation>
            <numerusform>%n 個の値を書込み・照合しました</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::DeviceSession</name>
    <message>
        <location filename="../model/session/DeviceSession.cpp" line="83"/>
        <source>%1 has no parameter &quot;%2&quot;</source>
        <translation>%1 にはパラメータ &quot;%2&quot; がありません</translation>
    </message>
    <message>
        <location filename="../model/session/BlockReader.cpp" line="50"/>
        <location filename="../model/session/DeviceSession.cpp" line="92"/>
        <source>%1 cannot be read (it is a write-only command)</source>
        <translation>%1 は読み出せません（書込み専用コマンド）</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceSession.cpp" line="137"/>
        <source>%1 is read-only</source>
        <translation>%1 は読出し専用です</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceSession.cpp" line="143"/>
        <source>%1 is a %2 command; it is only sent when explicitly requested</source>
        <translation>%1 は %2 コマンドです。明示的に要求した場合にのみ送信します</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceSession.cpp" line="173"/>
        <source>%1 cannot be checked: %2</source>
        <translation>%1 はチェックできません: %2</translation>
    </message>
    <message>
        <location filename="../model/session/BlockWriter.cpp" line="28"/>
        <source>not written: %1 is written together with 0x%2–0x%3, and reading those first failed: %4</source>
        <translation>未書込み: %1 は 0x%2–0x%3 と一緒に書き込まれますが、それらの事前読出しに失敗しました: %4</translation>
    </message>
    <message>
        <location filename="../model/session/BlockWriter.cpp" line="33"/>
        <source>short reply</source>
        <translation>応答が短すぎます</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceSession.cpp" line="254"/>
        <source>written, but reading it back failed: %1</source>
        <translation>書き込みましたが、読み戻しに失敗しました: %1</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceSession.cpp" line="263"/>
        <source>verification failed: wrote %1, the device holds %2</source>
        <translation>照合失敗: %1 を書き込みましたが、デバイスの値は %2 です</translation>
    </message>
    <message>
        <location filename="../model/session/DeviceRefusal.cpp" line="67"/>
        <source>error code %1</source>
        <translation>エラーコード %1</translation>
    </message>
</context>
<context>
    <name>opentop::DriveBatchReader</name>
    <message>
        <location filename="../model/files/DriveBatchReader.cpp" line="13"/>
        <source>machine number %1: not read</source>
        <translation>局番 %1: 読み出していません</translation>
    </message>
    <message>
        <location filename="../model/files/DriveBatchReader.cpp" line="22"/>
        <source>%1: cannot read %2</source>
        <translation>%1: %2 を読み出せません</translation>
    </message>
    <message>
        <location filename="../model/files/DriveBatchReader.cpp" line="24"/>
        <source>%1 holds a value its profile does not allow, so the backup could not be restored: %2</source>
        <translation>%1 にプロファイルで許可されていない値があるため、このバックアップは復元できません: %2</translation>
    </message>
    <message>
        <location filename="../model/files/DriveBatchReader.cpp" line="89"/>
        <source>machine number %1 is not a drive on the bus</source>
        <translation>局番 %1 はバス上のドライバではありません</translation>
    </message>
</context>
<context>
    <name>opentop::DriveFormatsField</name>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="28"/>
        <source>none: every drive at the port&apos;s format</source>
        <translation>なし: すべてのドライブがポートの形式</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="30"/>
        <source>Drives set to another line format than the port&apos;s, e.g. 7=9600:8E1 or 7=8N2 (the baud rate may be left out): requests to them switch the line to their format and back between transactions. A DBU works only at 8N1; a DC controller at 8E1, 8O1 or 8N2. The bus list&apos;s context menu sets them too.</source>
        <translation>ポートと異なる通信フォーマットに設定されたドライブ。例: 7=9600:8E1 または 7=8N2（ボーレートは省略可）。これらへの要求は、トランザクションの合間に回線をその形式へ切り替え、また戻します。DBU は 8N1 のみ、DC コントローラは 8E1、8O1、8N2。バス一覧の右クリックメニューでも設定できます。</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="36"/>
        <source>&amp;Mixed bus…</source>
        <translation>混在バス(&amp;M)…</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="37"/>
        <source>How a drive of another format joins this bus</source>
        <translation>別の形式のドライブをこのバスに加える方法</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="39"/>
        <source>Drives of different line formats</source>
        <translation>通信フォーマットの異なるドライブ</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="47"/>
        <source>Drive f&amp;ormats:</source>
        <translation>ドライブの形式(&amp;O):</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="68"/>
        <source>Drive formats: %1</source>
        <translation>ドライブの形式: %1</translation>
    </message>
    <message>
        <location filename="../ui/connection/DriveFormatsField.cpp" line="74"/>
        <source>Every drive hears only frames sent in its own line format: a DBU works only at 8N1 (19200 bit/s from the factory), a DC controller at 8E1 (9600 bit/s from the factory), 8O1 or 8N2. OpenTOP can talk to drives of different formats on one port: give each drive that is not at the port&apos;s format its own (Drive formats here, or Line format… in the bus list&apos;s context menu); the port is switched between transactions. To put all drives at one format for good, change the drives:</source>
        <translation>各ドライブは自分の通信フォーマットで送られたフレームしか受信しません。DBU は 8N1 のみ（工場出荷時 19200 bit/s）、DC コントローラは 8E1（工場出荷時 9600 bit/s）、8O1、8N2 です。OpenTOP は 1 つのポートで形式の異なるドライブと通信できます。ポートの形式でないドライブにはそれぞれ自分の形式を設定してください（ここの「ドライブの形式」、またはバス一覧の右クリックメニューの「通信フォーマット…」）。ポートはトランザクションの合間に切り替わります。すべてのドライブを恒久的に 1 つの形式にするには、ドライブの設定を変更します:</translation>
    </message>
</context>
<context>
    <name>opentop::DriveLineDialog</name>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="29"/>
        <source>Line format of machine number %1</source>
        <translation>局番 %1 の通信フォーマット</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="29"/>
        <source>Add drive</source>
        <translation>ドライブ追加</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="37"/>
        <source>&amp;Machine number:</source>
        <translation>局番(&amp;M):</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="51"/>
        <source>The port&apos;s (%1)</source>
        <translation>ポートの形式（%1）</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="63"/>
        <source>The baud rate and format the drive is set to: requests to it switch the port to it and back between transactions. Type another as 38400 8E1.</source>
        <translation>ドライブに設定されたボーレートと形式。このドライブへの要求は、トランザクションの合間にポートをその形式へ切り替え、また戻します。ほかの形式は 38400 8E1 のように入力します。</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="66"/>
        <source>&amp;Line format:</source>
        <translation>通信フォーマット(&amp;L):</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="74"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="147"/>
        <source>Line &amp;format…</source>
        <translation>通信フォーマット(&amp;F)…</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="152"/>
        <source>Machine number %1 talks %2, not the port&apos;s %3</source>
        <translation>局番 %1 はポートの %3 ではなく %2 で通信します</translation>
    </message>
    <message>
        <location filename="../ui/bus/DriveLineDialog.cpp" line="155"/>
        <source>Machine number %1 talks the port&apos;s %2</source>
        <translation>局番 %1 はポートの %2 で通信します</translation>
    </message>
</context>
<context>
    <name>opentop::DriveName</name>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="19"/>
        <source>A machine&apos;s name has at most %1 characters; &quot;%2&quot; has %3.</source>
        <translation>機械名は最大 %1 文字です。「%2」は %3 文字あります。</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="30"/>
        <source>A machine&apos;s name may not hold control characters or line breaks (U+%1).</source>
        <translation>機械名に制御文字や改行は使えません (U+%1)。</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="38"/>
        <source>A machine&apos;s name may not hold %1 (a percent sign directly before a digit).</source>
        <translation>機械名に %1（パーセント記号の直後に数字）は使えません。</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="47"/>
        <source>machine number %1</source>
        <translation>局番 %1</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="48"/>
        <source>machine number %1 (%2)</source>
        <translation>局番 %1 (%2)</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="53"/>
        <source>Machine number %1</source>
        <translation>局番 %1</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="54"/>
        <source>Machine number %1 (%2)</source>
        <translation>局番 %1 (%2)</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveName.cpp" line="72"/>
        <source>drive %1 (%2)</source>
        <translation>ドライバ %1 (%2)</translation>
    </message>
</context>
<context>
    <name>opentop::DrivePages</name>
    <message>
        <location filename="../ui/main/DrivePages.cpp" line="102"/>
        <source>Monitor</source>
        <translation>モニタ</translation>
    </message>
    <message>
        <location filename="../ui/main/DrivePages.cpp" line="115"/>
        <source>Test run</source>
        <translation>試運転</translation>
    </message>
    <message>
        <location filename="../ui/main/DrivePages.cpp" line="139"/>
        <source>%1 — %2, firmware V%3, switches %4</source>
        <translation>%1 — %2、ファームウェア V%3、スイッチ %4</translation>
    </message>
    <message>
        <location filename="../ui/main/DrivePages.cpp" line="123"/>
        <source>Speed loop tuning</source>
        <translation>速度ループチューニング</translation>
    </message>
    <message>
        <location filename="../ui/main/DrivePages.cpp" line="129"/>
        <source>Alarms</source>
        <translation>アラーム</translation>
    </message>
</context>
<context>
    <name>opentop::DriveStatus</name>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="8"/>
        <source>not polled yet</source>
        <translation>未ポーリング</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="10"/>
        <source>online</source>
        <translation>オンライン</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/bus/DriveStatus.cpp" line="12"/>
        <source>no answer (%n poll(s) in a row)</source>
        <translation>
            <numerusform>応答なし（%n 回連続）</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../model/bus/DriveStatus.cpp" line="13"/>
        <source>communication error (%n in a row)</source>
        <translation>
            <numerusform>通信エラー（%n 回連続）</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="19"/>
        <location filename="../model/bus/DriveStatus.cpp" line="31"/>
        <source>Status not known yet</source>
        <translation>状態不明</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="21"/>
        <source>No answer: %1</source>
        <translation>応答なし: %1</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="24"/>
        <source>Communication error: %1</source>
        <translation>通信エラー: %1</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="34"/>
        <source>Alarm %1 %2</source>
        <translation>アラーム %1 %2</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="36"/>
        <source>Alarm %1h (not in the alarm table)</source>
        <translation>アラーム %1h（アラーム表にありません）</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="38"/>
        <source>Alarm active</source>
        <translation>アラーム発生中</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="42"/>
        <source>Running</source>
        <translation>運転中</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="43"/>
        <source>Running CCW</source>
        <translation>CCW 運転中</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="43"/>
        <source>Running CW</source>
        <translation>CW 運転中</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="45"/>
        <source>Stopped, no alarm</source>
        <translation>停止中、アラームなし</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="52"/>
        <source>grey</source>
        <translation>灰</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="54"/>
        <source>green</source>
        <translation>緑</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="56"/>
        <source>orange</source>
        <translation>橙</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="58"/>
        <source>sky blue</source>
        <translation>水色</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="60"/>
        <source>red</source>
        <translation>赤</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="62"/>
        <source>purple</source>
        <translation>紫</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="64"/>
        <source>blue</source>
        <translation>青</translation>
    </message>
    <message>
        <location filename="../model/bus/DriveStatus.cpp" line="101"/>
        <source>%1; %2</source>
        <translation>%1、%2</translation>
    </message>
</context>
<context>
    <name>opentop::DriveWorkspace</name>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="35"/>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="169"/>
        <source>Write &amp;all pending</source>
        <translation>未書込みをすべて書込み(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="36"/>
        <source>Revert all</source>
        <translation>すべて元に戻す</translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="37"/>
        <source>Re-read all</source>
        <translation>すべて再読出し</translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="55"/>
        <source>Write every pending edit of this drive, on all pages, and verify</source>
        <translation>このドライバの全ページの未書込みの編集をすべて書き込み、照合します</translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="88"/>
        <source>Select a drive in the bus list to set it up.</source>
        <translation>設定するドライバをバスリストで選択してください。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="152"/>
        <source>Every edit is accepted now. Nothing has been written yet: Write all pending sends %n value(s).</source>
        <translation>
            <numerusform>すべての編集が受け付けられました。まだ何も書き込んでいません：「未書込みをすべて書込み」で %n 個の値を送信します。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="168"/>
        <source>Write &amp;all pending (%1)</source>
        <translation>未書込みをすべて書込み(&amp;A) (%1)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="190"/>
        <source>Reading the drive…</source>
        <translation>ドライバを読出し中…</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="192"/>
        <source>%n value(s) could not be read</source>
        <translation>
            <numerusform>%n 個の値を読み出せませんでした</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="147"/>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="210"/>
        <source>Nothing was written: %1</source>
        <translation>何も書き込んでいません: %1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="144"/>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="224"/>
        <source>%1: %2 Nothing was written.</source>
        <translation>%1: %2 何も書き込んでいません。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="233"/>
        <source>Write %n pending value(s) to machine number %1</source>
        <translation>
            <numerusform>未書込みの %n 個の値を局番 %1 に書込み</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="205"/>
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="235"/>
        <source>Nothing was written.</source>
        <translation>何も書き込んでいません。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/DriveWorkspace.cpp" line="238"/>
        <source>Writing %n value(s)…</source>
        <translation>
            <numerusform>%n 個の値を書込み中…</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::EolAuditCommand</name>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="34"/>
        <source>Show the audit trail: who logged in, approved, used or was refused a privilege</source>
        <translation>監査証跡を表示: 誰がログイン・承認し、権限を使用または拒否されたか</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="40"/>
        <source>Results database: an SQLite file or postgresql://user@host/db.</source>
        <translation>結果データベース: SQLite ファイルまたは postgresql://user@host/db。</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="41"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="42"/>
        <source>audit: at or after T (2026-11-24, 8h, 2d, today).</source>
        <translation>audit: T 以降 (2026-11-24、8h、2d、today)。</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="42"/>
        <source>T</source>
        <translation>T</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="43"/>
        <source>audit: only this user.</source>
        <translation>audit: このユーザーのみ。</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="43"/>
        <location filename="../cli/EolAuditCommand.cpp" line="44"/>
        <source>NAME</source>
        <translation>名前</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="44"/>
        <source>audit: only this station.</source>
        <translation>audit: このステーションのみ。</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="53"/>
        <source>usage: opentop-cli eol %1</source>
        <translation>使い方: opentop-cli eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="62"/>
        <source>error: --since: %1</source>
        <translation>エラー: --since: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="74"/>
        <source>error: %1</source>
        <translation>エラー: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="89"/>
        <source>no audit entry matches</source>
        <translation>該当する監査記録はありません</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="92"/>
        <source>time</source>
        <translation>時刻</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="92"/>
        <source>station</source>
        <translation>ステーション</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="92"/>
        <source>user</source>
        <translation>ユーザー</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="92"/>
        <source>action</source>
        <translation>操作</translation>
    </message>
    <message>
        <location filename="../cli/EolAuditCommand.cpp" line="92"/>
        <source>detail</source>
        <translation>内容</translation>
    </message>
</context>
<context>
    <name>opentop::EolCertificateCommand</name>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="31"/>
        <source>A unit&apos;s certificate: its newest record as a PDF, or as JSON with --json</source>
        <translation>製品の検査成績書: 最新の記録を PDF で、または --json で JSON として出力</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="37"/>
        <source>The results database (see results).</source>
        <translation>結果データベース（results を参照）。</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="37"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="38"/>
        <source>certificate: the record with this id instead of the newest.</source>
        <translation>certificate: 最新ではなく、この ID の記録を使用します。</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="39"/>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="59"/>
        <source>error: name one serial number, or a record with --id ID; usage: eol %1</source>
        <translation>エラー: シリアル番号を 1 つ、または --id ID で記録を指定してください。使い方: eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="67"/>
        <source>error: the serial number is empty</source>
        <translation>エラー: シリアル番号が空です</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="73"/>
        <location filename="../cli/EolCertificateCommand.cpp" line="138"/>
        <location filename="../cli/EolCertificateCommand.cpp" line="154"/>
        <source>error: %1</source>
        <translation>エラー: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="80"/>
        <source>error: this program cannot draw a PDF (no Qt GUI application); use --json</source>
        <translation>エラー: このプログラムは PDF を作成できません（Qt GUI アプリケーションなし）。--json を使用してください</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="96"/>
        <source>error: no record %1 in %2 (%3)</source>
        <translation>エラー: %2 に記録 %1 がありません (%3)</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="104"/>
        <source>error: record %1 is of serial number %2, not %3</source>
        <translation>エラー: 記録 %1 はシリアル番号 %2 のもので、%3 ではありません</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="114"/>
        <location filename="../cli/EolCertificateCommand.cpp" line="147"/>
        <source>error: %1: %2</source>
        <translation>エラー: %1: %2</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="121"/>
        <source>error: no record of serial number %1 in %2</source>
        <translation>エラー: %2 にシリアル番号 %1 の記録がありません</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="141"/>
        <source>wrote %1</source>
        <translation>%1 を書き込みました</translation>
    </message>
    <message>
        <location filename="../cli/EolCertificateCommand.cpp" line="157"/>
        <source>wrote %1: serial number %2, %3, recorded %4</source>
        <translation>%1 を書き込みました: シリアル番号 %2、%3、記録日時 %4</translation>
    </message>
</context>
<context>
    <name>opentop::EolCommand</name>
    <message>
        <location filename="../cli/EolCommand.cpp" line="36"/>
        <source>End-of-line station: recipes, the results database, unit certificates</source>
        <translation>出荷検査ステーション: レシピ、結果データベース、製品の検査成績書</translation>
    </message>
    <message>
        <location filename="../cli/EolCommand.cpp" line="41"/>
        <source>Subcommands:
</source>
        <translation>サブコマンド:
</translation>
    </message>
    <message>
        <location filename="../cli/EolCommand.cpp" line="44"/>
        <source>Results database: --db URL, else OPENTOP_EOL_DB, else the SQLite file
$XDG_DATA_HOME/opentop/results.db (~/.local/share/opentop/results.db).
&quot;opentop-cli help eol&quot; lists every option; each subcommand takes only its own.</source>
        <translation>結果データベース: --db URL、なければ OPENTOP_EOL_DB、なければ SQLite ファイル
$XDG_DATA_HOME/opentop/results.db (~/.local/share/opentop/results.db)。
&quot;opentop-cli help eol&quot; で全オプションを表示します。各サブコマンドは自身のオプションのみ受け付けます。</translation>
    </message>
    <message>
        <location filename="../cli/EolCommand.cpp" line="92"/>
        <source>error: name a subcommand: eol %1</source>
        <translation>エラー: サブコマンドを指定してください: eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolCommand.cpp" line="94"/>
        <source>error: unknown subcommand &quot;eol %1&quot;; subcommands: %2</source>
        <translation>エラー: 不明なサブコマンド &quot;eol %1&quot;。サブコマンド: %2</translation>
    </message>
    <message>
        <location filename="../cli/EolCommand.cpp" line="98"/>
        <source>See &quot;opentop-cli help eol&quot;.</source>
        <translation>&quot;opentop-cli help eol&quot; を参照してください。</translation>
    </message>
    <message>
        <location filename="../cli/EolCommand.cpp" line="114"/>
        <source>error: eol %1: --%2 is not an option of this subcommand; usage: eol %3</source>
        <translation>エラー: eol %1: --%2 はこのサブコマンドのオプションではありません。使い方: eol %3</translation>
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
        <translation>局番 %1 で応答するドライバがありません</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="85"/>
        <source>the drive at machine number %1 is not identified: %2</source>
        <translation>局番 %1 のドライバを識別できません: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="99"/>
        <source>a %1 drive, the recipe needs a %2 drive</source>
        <translation>%1 ドライバですが、レシピには %2 ドライバが必要です</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="103"/>
        <source>firmware %1, the recipe allows %2</source>
        <translation>ファームウェア %1、レシピで許可されているのは %2 です</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="104"/>
        <source>unknown</source>
        <translation>不明</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="110"/>
        <source>no profile for the family %1</source>
        <translation>ファミリ %1 のプロファイルがありません</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="193"/>
        <source>cannot read whether the motor runs or an alarm is active: %1</source>
        <translation>モータが運転中か、アラームが発生しているかを読み出せません: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="194"/>
        <source>no answer</source>
        <translation>応答なし</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="201"/>
        <source>its motor was running before the test</source>
        <translation>試験前からモータが運転していました</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="202"/>
        <source>the motor is already running before the test (left by an interrupted run?); nothing was written: stop it first (STOP ALL, or at the drive)</source>
        <translation>試験前にモータがすでに運転しています（中断された実行の残り？）。何も書き込んでいません: 先に停止してください（全停止、またはドライバ側で）</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="209"/>
        <source>an alarm is active before the test (left by the last unit?); nothing was written: reset the alarm and test again</source>
        <translation>試験前からアラームが発生しています（前の製品の残り？）。何も書き込んでいません: アラームをリセットして再試験してください</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="219"/>
        <source>writing the settings</source>
        <translation>設定を書込み中</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="224"/>
        <source>writing the settings: %1</source>
        <translation>設定の書込み: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="233"/>
        <source>reading every setting back</source>
        <translation>全設定を読み戻し中</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="238"/>
        <source>verifying the settings: %1</source>
        <translation>設定の照合: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="252"/>
        <source>arming the communication-loss stop</source>
        <translation>通信途絶停止を有効化中</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="266"/>
        <source>testing</source>
        <translation>試験中</translation>
    </message>
    <message>
        <location filename="../model/eol/EolDriveRun.cpp" line="270"/>
        <source>step %1 of %2: %3</source>
        <translation>ステップ %1/%2: %3</translation>
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
        <translation>レシピエディタ(&amp;R)…</translation>
    </message>
    <message>
        <location filename="../ui/eol/EolMenu.cpp" line="51"/>
        <source>the recipe editor</source>
        <translation>レシピエディタ</translation>
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
        <translation>署名済みレシピをライン用に承認 (エンジニア): 以後ステーションで実行できます</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeApproveCommand.cpp" line="41"/>
        <source>Results database: an SQLite file or postgresql://user@host/db.</source>
        <translation>結果データベース: SQLite ファイルまたは postgresql://user@host/db。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeApproveCommand.cpp" line="41"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeApproveCommand.cpp" line="49"/>
        <source>usage: opentop-cli eol %1</source>
        <translation>使い方: opentop-cli eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeApproveCommand.cpp" line="61"/>
        <source>%1: the recipe is not valid, so it cannot be approved:</source>
        <translation>%1: レシピが無効なため承認できません:</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeApproveCommand.cpp" line="80"/>
        <source>error: %1; the recipe was not approved</source>
        <translation>エラー: %1。レシピは承認されていません</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeApproveCommand.cpp" line="98"/>
        <source>%1 rev. %2 approved by %3 (approval %4, checksum %5)</source>
        <translation>%1 rev. %2 を %3 が承認しました (承認 %4、チェックサム %5)</translation>
    </message>
</context>
<context>
    <name>opentop::EolRecipeCheckCommand</name>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="27"/>
        <source>Check a recipe against the drive profiles (and per-unit values of a CSV file)</source>
        <translation>レシピをドライバプロファイル（および CSV ファイルの個別値）と照合してチェックします</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="33"/>
        <source>recipe check: also check every unit&apos;s per-unit values in this CSV file.</source>
        <translation>recipe check: この CSV ファイル内の各製品の個別値もチェックします。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="34"/>
        <source>CSV</source>
        <translation>CSV</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="55"/>
        <source>error: %1 refused: %2</source>
        <translation>エラー: %1 は使用できません: %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="65"/>
        <source>%1, serial %2</source>
        <translation>%1、シリアル %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="91"/>
        <source>error: %1</source>
        <translation>エラー: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="93"/>
        <source>%1 is not valid: %n problem(s); nothing may be run with it</source>
        <translation>
            <numerusform>%1 は無効です: %n 件の問題。このレシピでは実行できません</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="102"/>
        <source>valid: %1 revision %2: %3</source>
        <translation>有効: %1 リビジョン %2: %3</translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolRecipeCheckCommand.cpp" line="107"/>
        <source>; %n unit(s) of %1 checked</source>
        <translation>
            <numerusform>、%1 の製品 %n 台をチェックしました</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::EolRecipeCreateCommand</name>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="39"/>
        <source>Make a recipe from a golden unit: a backup file or drives on the bus</source>
        <translation>マスター品からレシピを作成します: バックアップファイルまたはバス上のドライバ</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="45"/>
        <source>recipe create: the golden unit&apos;s backup file.</source>
        <translation>recipe create: マスター品のバックアップファイル。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="46"/>
        <source>FILE</source>
        <translation>FILE</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="48"/>
        <source>recipe create: the golden unit&apos;s drives on the bus, e.g. 1,2 (with the connection options).</source>
        <translation>recipe create: バス上のマスター品のドライバ。例: 1,2（接続オプションと併用）。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="50"/>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="51"/>
        <source>recipe create: the product&apos;s name.</source>
        <translation>recipe create: 製品名。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="51"/>
        <source>NAME</source>
        <translation>NAME</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="52"/>
        <source>recipe create: the recipe&apos;s revision.</source>
        <translation>recipe create: レシピのリビジョン。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="52"/>
        <source>REV</source>
        <translation>REV</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="54"/>
        <source>recipe create: replace an existing recipe file.</source>
        <translation>recipe create: 既存のレシピファイルを置き換えます。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="56"/>
        <source>recipe create --drives: run the golden unit through the recipe&apos;s steps once (its motors turn) and take the hold limits from what it measured.</source>
        <translation>recipe create --drives: マスター品をレシピのステップどおりに一度運転し (モータが回転します)、測定値から保持ステップの判定値を決めます。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="59"/>
        <source>recipe create --measure: the margin around a measured value, in % of it (default 25; at least 5 % of the parameter&apos;s full scale).</source>
        <translation>recipe create --measure: 測定値の前後に取る余裕。測定値に対する % (既定 25、最小でもパラメータのフルスケールの 5 %)。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="61"/>
        <source>PERCENT</source>
        <translation>パーセント</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="62"/>
        <source>recipe create --measure: run the motors.</source>
        <translation>recipe create --measure: モータの運転を確認します。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="76"/>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="177"/>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="282"/>
        <source>error: %1; nothing written</source>
        <translation>エラー: %1。何も書き込んでいません</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="118"/>
        <source>nothing written</source>
        <translation>何も書き込んでいません</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="91"/>
        <source>%1: %2 settings read</source>
        <translation>%1: %2 個の設定を読出し</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="106"/>
        <source>interrupted while reading the golden unit: nothing written</source>
        <translation>マスター品の読み出し中に中断: 何も書き込んでいません</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="112"/>
        <source>note: %1</source>
        <translation>注: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="117"/>
        <source>give its variant with --variant %1=VARIANT</source>
        <translation>--variant %1=機種 で機種を指定してください</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="133"/>
        <source>Would run the golden unit through the recipe&apos;s steps:</source>
        <translation>マスター品をレシピのステップどおりに運転します:</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="136"/>
        <source>This turns motors: add --yes to run them. Nothing was run; nothing written.</source>
        <translation>モータが回転します。運転するには --yes を付けてください。何も運転せず、何も書き込んでいません。</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="141"/>
        <source>measuring the golden unit (Ctrl-C stops every motor):</source>
        <translation>マスター品を測定中 (Ctrl-C で全モータ停止):</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="150"/>
        <source>drive %1: %2</source>
        <translation>ドライバ %1: %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="162"/>
        <source>interrupted</source>
        <translation>中断</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="175"/>
        <source>WARNING: %1 is not confirmed stopped</source>
        <translation>警告: %1 の停止を確認できていません</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="185"/>
        <source>limits from the golden unit:</source>
        <translation>マスター品から決めた判定値:</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="189"/>
        <source>  drive %1, step %2: %3</source>
        <translation>  ドライバ %1、ステップ %2: %3</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="213"/>
        <source>error: %1; usage: eol %2</source>
        <translation>エラー: %1。使い方: eol %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="218"/>
        <source>unexpected argument &quot;%1&quot;</source>
        <translation>予期しない引数 &quot;%1&quot;</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="222"/>
        <source>give either --from-backup FILE or --drives LIST</source>
        <translation>--from-backup FILE または --drives LIST のいずれかを指定してください</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="225"/>
        <source>--measure needs the golden unit on the bus: give --drives LIST</source>
        <translation>--measure にはバス上のマスター品が必要です: --drives で一覧を指定してください</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="231"/>
        <source>--margin is for --measure</source>
        <translation>--margin は --measure と併用します</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="233"/>
        <source>--margin %1: give a percentage from 1 to 100</source>
        <translation>--margin %1: 1 から 100 のパーセントを指定してください</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="239"/>
        <source>give the product&apos;s name with --product NAME</source>
        <translation>--product NAME で製品名を指定してください</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="241"/>
        <source>give the recipe&apos;s revision with --revision REV</source>
        <translation>--revision REV でレシピのリビジョンを指定してください</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="244"/>
        <source>give the recipe file to write with -o RECIPE</source>
        <translation>-o RECIPE で書き込むレシピファイルを指定してください</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="248"/>
        <source>error: %1 exists; give --force to replace it</source>
        <translation>エラー: %1 は既に存在します。置き換えるには --force を指定してください</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="253"/>
        <source>error: %1; nothing read</source>
        <translation>エラー: %1。何も読み出していません</translation>
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
        <translation>エラー: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="308"/>
        <source>wrote %1: %2 revision %3, %4</source>
        <translation>%1 を書き込みました: %2 リビジョン %3、%4</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeCreateCommand.cpp" line="316"/>
        <source>error: the recipe does not pass &quot;eol recipe check&quot;: fix it, then sign it with &quot;opentop-cli eol recipe sign %1&quot;</source>
        <translation>エラー: レシピが &quot;eol recipe check&quot; に合格しません: 修正してから &quot;opentop-cli eol recipe sign %1&quot; で署名してください</translation>
    </message>
</context>
<context>
    <name>opentop::EolRecipeShowCommand</name>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="61"/>
        <source>Show a recipe: positions, settings by label with units, steps and limits</source>
        <translation>レシピを表示します: 位置、単位付きのラベル別設定、ステップ、規格値</translation>
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
        <translation>  設定なし</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="90"/>
        <source>  setting</source>
        <translation>  設定</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="90"/>
        <source>value</source>
        <translation>値</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="90"/>
        <source>unit</source>
        <translation>単位</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="100"/>
        <source>  per-unit value</source>
        <translation>  個別値</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="100"/>
        <source>range</source>
        <translation>範囲</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="100"/>
        <source>from</source>
        <translation>入力元</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="103"/>
        <source>%1 … %2</source>
        <translation>%1 … %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="106"/>
        <source>CSV file by serial</source>
        <translation>シリアル番号別 CSV ファイル</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="107"/>
        <source>typed by the operator</source>
        <translation>作業者が入力</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="112"/>
        <source>  no test steps</source>
        <translation>  試験ステップなし</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="115"/>
        <source>  steps:</source>
        <translation>  ステップ:</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="174"/>
        <source>%1, revision %2</source>
        <translation>%1、リビジョン %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="180"/>
        <source>serial numbers: %1</source>
        <translation>シリアル番号: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="181"/>
        <source>checksum %1</source>
        <translation>チェックサム %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="182"/>
        <source>position</source>
        <translation>位置</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="182"/>
        <source>machine number</source>
        <translation>局番</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="182"/>
        <source>name</source>
        <translation>名称</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="182"/>
        <source>family</source>
        <translation>ファミリ</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="183"/>
        <source>variants</source>
        <translation>機種</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeShowCommand.cpp" line="183"/>
        <source>firmware</source>
        <translation>ファームウェア</translation>
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
        <translation>手で編集したレシピを承認します: チェックに合格した場合のみ新しいチェックサムを付けます</translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolRecipeSignCommand.cpp" line="49"/>
        <source>error: %1 does not pass check (%n problem(s)); not signed</source>
        <translation>
            <numerusform>エラー: %1 はチェックに合格しません（%n 件の問題）。署名していません</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeSignCommand.cpp" line="57"/>
        <source>error: %1; not signed</source>
        <translation>エラー: %1。署名していません</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeSignCommand.cpp" line="70"/>
        <source>%1 is signed already (%2); nothing changed</source>
        <translation>%1 は署名済みです (%2)。何も変更していません</translation>
    </message>
    <message>
        <location filename="../cli/EolRecipeSignCommand.cpp" line="74"/>
        <source>signed %1: %2 revision %3, %4</source>
        <translation>%1 に署名しました: %2 リビジョン %3、%4</translation>
    </message>
</context>
<context>
    <name>opentop::EolResultsCommand</name>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="74"/>
        <source>List units of the results database, their first-pass yield, or export them as CSV</source>
        <translation>結果データベースの製品と直行率を一覧表示、または CSV でエクスポートします</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="81"/>
        <source>The results database: a SQLite file, sqlite:PATH or postgresql://user@host/db (default: OPENTOP_EOL_DB, else ~/.local/share/opentop/results.db).</source>
        <translation>結果データベース: SQLite ファイル、sqlite:PATH、または postgresql://user@host/db（既定: OPENTOP_EOL_DB、なければ ~/.local/share/opentop/results.db）。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="83"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="85"/>
        <source>results: only this serial number; with * or ? a pattern that ignores case (&quot;SN-10*&quot;).</source>
        <translation>results: このシリアル番号のみ。* または ? を含むと大文字小文字を区別しないパターン（&quot;SN-10*&quot;）。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="87"/>
        <source>S</source>
        <translation>S</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="89"/>
        <source>results: started at or after T (2026-11-24, 2026-11-24T06:00, 8h, 2d, today).</source>
        <translation>results: T 以降に開始したもの（2026-11-24、2026-11-24T06:00、8h、2d、today）。</translation>
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
        <translation>results: T より前に開始したもの。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="92"/>
        <source>results: only this recipe (product name).</source>
        <translation>results: このレシピ（製品名）のみ。</translation>
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
        <translation>results: このステーションのみ。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="101"/>
        <source>results: only the newest N units.</source>
        <translation>results: 最新の N 台のみ。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="101"/>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="103"/>
        <source>results: CSV (RFC 4180) on standard output or to -o FILE.</source>
        <translation>results: CSV (RFC 4180) を標準出力または -o FILE に出力します。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="108"/>
        <source>results --yield: the shifts&apos; start times in local time (default 06:00,14:00,22:00).</source>
        <translation>results --yield: シフトの開始時刻（ローカル時刻、既定 06:00,14:00,22:00）。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="109"/>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="141"/>
        <source>&quot;%1&quot; is not a time; give 2026-11-24, 2026-11-24T06:00 (local, or with Z or +01:00), 8h, 2d, today or yesterday</source>
        <translation>&quot;%1&quot; は時刻ではありません。2026-11-24、2026-11-24T06:00（ローカル時刻、または Z や +01:00 付き）、8h、2d、today、yesterday のいずれかを指定してください</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="151"/>
        <location filename="../cli/EolResultsCommand.cpp" line="297"/>
        <source>error: %1</source>
        <translation>エラー: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="167"/>
        <source>--%1: %2</source>
        <translation>--%1: %2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="172"/>
        <source>--since %1 is not before --until %2</source>
        <translation>--since %1 が --until %2 より前ではありません</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="94"/>
        <source>results: only this version of a recipe (its checksum, as eol recipe check prints it).</source>
        <translation>results: このバージョンのレシピのみ（eol recipe check が表示するチェックサムで指定）。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="96"/>
        <source>SUM</source>
        <translation>SUM</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="98"/>
        <source>results: pass, fail, error (station error), interrupted, aborted or running.</source>
        <translation>results: pass、fail、error（ステーションエラー）、interrupted、aborted、running のいずれか。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="105"/>
        <source>results: first-, second- and last-pass yield and failure reasons per recipe version and per shift; station errors and aborts are kept out of yield.</source>
        <translation>results: レシピバージョン別・シフト別の直行率、2 回目までの合格率、最終合格率と不合格理由。ステーションエラーと中止は歩留まりに含めません。</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="178"/>
        <source>--verdict &quot;%1&quot;: give pass, fail, error, interrupted, aborted or running</source>
        <translation>--verdict &quot;%1&quot;: pass、fail、error、interrupted、aborted、running のいずれかを指定してください</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="186"/>
        <source>--limit &quot;%1&quot;: give a number of units from 1</source>
        <translation>--limit &quot;%1&quot;: 製品の台数を 1 以上で指定してください</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="196"/>
        <location filename="../cli/EolResultsCommand.cpp" line="226"/>
        <source>no unit matches</source>
        <translation>該当する製品はありません</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="199"/>
        <source>started</source>
        <translation>開始</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="199"/>
        <source>serial</source>
        <translation>シリアル</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="199"/>
        <location filename="../cli/EolResultsCommand.cpp" line="230"/>
        <source>recipe</source>
        <translation>レシピ</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="199"/>
        <source>station</source>
        <translation>ステーション</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="199"/>
        <source>approved by</source>
        <translation>承認者</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="200"/>
        <source>operator</source>
        <translation>作業者</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="200"/>
        <source>verdict</source>
        <translation>判定</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="200"/>
        <source>time</source>
        <translation>時刻</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="200"/>
        <source>reason</source>
        <translation>理由</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="200"/>
        <source>drives</source>
        <translation>ドライバ</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="209"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="211"/>
        <source>%1 rev. %2</source>
        <translation>%1 rev. %2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="232"/>
        <source>shift</source>
        <translation>シフト</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="233"/>
        <source>serials</source>
        <translation>シリアル数</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="233"/>
        <source>first pass</source>
        <translation>初回合格</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="233"/>
        <source>second pass</source>
        <translation>2 回目までに合格</translation>
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
        <translation>ステーションエラー</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="254"/>
        <source>Yield per recipe version (station errors and aborts are not counted)</source>
        <translation>レシピバージョン別の歩留まり（ステーションエラーと中止は含めない）</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="263"/>
        <source>%1: checksum %2</source>
        <translation>%1: チェックサム %2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="234"/>
        <source>not finished</source>
        <translation>未完了</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="266"/>
        <source>Per shift</source>
        <translation>シフト別</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="282"/>
        <source>Failure reasons</source>
        <translation>不合格理由</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="283"/>
        <source>Station errors (not counted in yield)</source>
        <translation>ステーションエラー（歩留まりに含めない）</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="300"/>
        <source>wrote %1</source>
        <translation>%1 を書き込みました</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="308"/>
        <source>error: unexpected argument &quot;%1&quot;; usage: eol %2</source>
        <translation>エラー: 予期しない引数 &quot;%1&quot;。使い方: eol %2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="315"/>
        <source>error: give --csv or --json, not both</source>
        <translation>エラー: --csv と --json は同時に指定できません</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="319"/>
        <source>error: -o names the CSV file: give --csv too</source>
        <translation>エラー: -o は CSV ファイルを指定します。--csv も指定してください</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="324"/>
        <source>error: --shifts is for --yield</source>
        <translation>エラー: --shifts は --yield 用です</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="333"/>
        <source>error: --shifts %1: %2</source>
        <translation>エラー: --shifts %1: %2</translation>
    </message>
    <message>
        <location filename="../cli/EolResultsCommand.cpp" line="352"/>
        <location filename="../cli/EolResultsCommand.cpp" line="382"/>
        <location filename="../cli/EolResultsCommand.cpp" line="393"/>
        <source>error: %1: %2</source>
        <translation>エラー: %1: %2</translation>
    </message>
</context>
<context>
    <name>opentop::EolRun</name>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="59"/>
        <source>recording the unit before anything is sent</source>
        <translation>送信前に製品を記録しています</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="65"/>
        <source>the results database cannot record the unit: %1</source>
        <translation>結果データベースに製品を記録できません: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="98"/>
        <source>the recipe has no drives</source>
        <translation>レシピにドライバがありません</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="111"/>
        <source>the recipe is not valid: %1</source>
        <translation>レシピが無効です: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="116"/>
        <source>%1: no value for %2 for this unit</source>
        <translation>%1: この製品の %2 の値がありません</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="134"/>
        <source>cancelled by the operator</source>
        <translation>作業者によるキャンセル</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="145"/>
        <source>the connection was lost: %1</source>
        <translation>接続が切れました: %1</translation>
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
        <translation>%1 失敗</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="198"/>
        <source>NOT CONFIRMED STOPPED: %1</source>
        <translation>停止未確認: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolRun.cpp" line="207"/>
        <source>recording the result</source>
        <translation>結果を記録しています</translation>
    </message>
</context>
<context>
    <name>opentop::EolRunCommand</name>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="59"/>
        <source>Set up and test one unit at the end of the line; record the result</source>
        <translation>出荷検査で製品を 1 台設定・試験し、結果を記録します</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="65"/>
        <source>The unit&apos;s serial number (as its barcode reads).</source>
        <translation>製品のシリアル番号（バーコードの読取り値）。</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="65"/>
        <source>S</source>
        <translation>S</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="66"/>
        <source>Who tests it, on a station without users (default: the login name).</source>
        <translation>ユーザーのいないステーションで検査する人 (既定: ログイン名)。</translation>
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
        <translation>このステーションの名前（既定: ホスト名）。</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="70"/>
        <source>Results database: an SQLite file or postgresql://user@host/db.</source>
        <translation>結果データベース: SQLite ファイルまたは postgresql://user@host/db。</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="70"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="71"/>
        <source>CSV file with the per-unit values, by serial number.</source>
        <translation>個別値の CSV ファイル（シリアル番号別）。</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="71"/>
        <source>CSV</source>
        <translation>CSV</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="72"/>
        <source>A per-unit value typed by the operator, e.g. 1:spno3.speed=1500.</source>
        <translation>作業者が入力する個別値。例: 1:spno3.speed=1500。</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="73"/>
        <source>ID:NAME=VALUE</source>
        <translation>ID:NAME=VALUE</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="75"/>
        <source>A technician allows a retest the recipe&apos;s rules hold back (a serial that passed already, or its attempts used up).</source>
        <translation>レシピの規則で止められる再試験（合格済みのシリアル、または試験回数を使い切ったもの）を技術者が許可します。</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="109"/>
        <source>--value %1: write it as MACHINE:NAME=VALUE, e.g. 1:spno3.speed=1500</source>
        <translation>--value %1: MACHINE:NAME=VALUE の形式で指定してください。例: 1:spno3.speed=1500</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="114"/>
        <source>--value %1: %2</source>
        <translation>--value %1: %2</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="137"/>
        <source>--variant %1: %2 allows %3; nothing was sent</source>
        <translation>--variant %1: %2 が許可するのは %3。何も送信していない</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="139"/>
        <source>any %1 variant</source>
        <translation>%1 の全機種</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="148"/>
        <source>--variant %1: the recipe has no position at machine number %2; nothing was sent</source>
        <translation>--variant %1: レシピに局番 %2 の位置がない。何も送信していない</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="162"/>
        <source>usage: opentop-cli eol %1</source>
        <translation>使い方: opentop-cli eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="178"/>
        <source>%1: the recipe is not valid; nothing was sent:</source>
        <translation>%1: レシピが無効です。何も送信していません:</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="188"/>
        <source>--serial: %1; nothing was sent</source>
        <translation>--serial: %1。何も送信していない</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="217"/>
        <source>results database: %1; nothing was sent</source>
        <translation>結果データベース: %1。何も送信していません</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="223"/>
        <source>note: unit %1 (begun %2) was left unfinished by a station process that is gone; it is now recorded as interrupted. Check that its motor is stopped.</source>
        <translation>注意: ユニット %1（%2 開始）はステーションのプロセスが終了したため完了せず、「中断」として記録されました。モーターが停止していることを確認してください。</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="228"/>
        <source>note: %1 result(s) kept on this station could not be sent to the results database yet</source>
        <translation>注意: このステーションに保管された結果 %1 件を、まだ結果データベースへ送れていません</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="317"/>
        <source>error: %1; nothing was sent</source>
        <translation>エラー: %1。何も送信していません</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="320"/>
        <source>a technician allows it with --retest</source>
        <translation>技術者は --retest で許可できます</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="269"/>
        <source>note: %1; tested again as --retest allows</source>
        <translation>注: %1。--retest の許可により再試験します</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="273"/>
        <source>note: %1</source>
        <translation>注: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="280"/>
        <source>station: %1</source>
        <translation>ステーション: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="326"/>
        <source>a drive of the station is not confirmed stopped; nothing was tested</source>
        <translation>ステーションのドライブに停止を確認できないものがあります。何も検査していません</translation>
    </message>
    <message>
        <location filename="../cli/EolRunCommand.cpp" line="298"/>
        <source>interrupted at the station</source>
        <translation>ステーションで中断</translation>
    </message>
</context>
<context>
    <name>opentop::EolRunIdentity</name>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="50"/>
        <location filename="../cli/EolRunIdentity.cpp" line="88"/>
        <source>the results database is not open</source>
        <translation>結果データベースが開いていません</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="53"/>
        <location filename="../cli/EolRunIdentity.cpp" line="101"/>
        <source>results database: %1; nothing was sent</source>
        <translation>結果データベース: %1。何も送信していません</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="65"/>
        <location filename="../cli/EolRunIdentity.cpp" line="107"/>
        <source>refused: %1; nothing was sent</source>
        <translation>拒否: %1。何も送信していません</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="66"/>
        <source>this station has users: name who tests with --user NAME (the password from OPENTOP_PASSWORD or the terminal)</source>
        <translation>このステーションにはユーザーがいます: --user NAME で検査する人を指定してください (パスワードは OPENTOP_PASSWORD または端末から)</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="73"/>
        <source>error: on a station with users the operator is the user who logs in (--user); --operator is not taken</source>
        <translation>エラー: ユーザーのいるステーションでは、作業者はログインしたユーザー (--user) です。--operator は受け付けません</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="98"/>
        <source>run-units: recipe checksum %1 is not approved</source>
        <translation>run-units: レシピのチェックサム %1 は承認されていません</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="113"/>
        <source>refused: %1 Nothing was sent.</source>
        <translation>拒否: %1 何も送信していません。</translation>
    </message>
    <message>
        <location filename="../cli/EolRunIdentity.cpp" line="123"/>
        <source>%1 logged in; recipe approved by %2 (approval %3)</source>
        <translation>%1 がログイン。レシピ承認者 %2 (承認 %3)</translation>
    </message>
</context>
<context>
    <name>opentop::EolRunOutput</name>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="98"/>
        <location filename="../cli/EolRunOutput.cpp" line="121"/>
        <source>drive %1</source>
        <translation>ドライバ %1</translation>
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
        <translation>rev. %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="167"/>
        <source>attempt %1</source>
        <translation>%1 回目の試験</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="174"/>
        <source>the result was NOT recorded: %1</source>
        <translation>結果は記録されていません: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="178"/>
        <source>the results database did not answer: the result is kept on this station (%1) and sent when a station program next reaches the database</source>
        <translation>結果データベースが応答しません: 結果はこのステーション（%1）に保管され、次にステーションのプログラムがデータベースに接続したときに送信されます</translation>
    </message>
    <message>
        <location filename="../cli/EolRunOutput.cpp" line="183"/>
        <source>WARNING: motor not confirmed stopped: %1</source>
        <translation>警告: モータの停止が確認できません: %1</translation>
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
        <translation>%1 を読み戻せません: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/EolSettingsWriter.cpp" line="101"/>
        <source>%1 does not keep its value: set to %2, reads %3</source>
        <translation>%1 が値を保持しません: %2 に設定、読出し値 %3</translation>
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
        <translation>ドライバ %1</translation>
    </message>
</context>
<context>
    <name>opentop::EolStation</name>
    <message>
        <location filename="../model/station/EolStation.cpp" line="121"/>
        <source>a unit is being tested</source>
        <translation>製品を試験中です</translation>
    </message>
    <message>
        <location filename="../model/station/EolStation.cpp" line="125"/>
        <source>open a recipe first</source>
        <translation>先にレシピを開いてください</translation>
    </message>
    <message>
        <location filename="../model/station/EolStation.cpp" line="145"/>
        <source>run-units: serial %1: %2</source>
        <translation>run-units: シリアル番号 %1: %2</translation>
    </message>
    <message>
        <location filename="../model/station/EolStation.cpp" line="149"/>
        <source>not connected to a bus</source>
        <translation>バスに接続されていません</translation>
    </message>
    <message>
        <location filename="../model/station/EolStation.cpp" line="153"/>
        <source>unit %1 starts as soon as the station&apos;s drives are safe</source>
        <translation>ステーションのドライブが安全になり次第、ユニット %1 を開始します</translation>
    </message>
    <message>
        <location filename="../model/station/EolStation.cpp" line="185"/>
        <source>serial %1 tested again, allowed by %2: %3</source>
        <translation>シリアル %1 を再試験、%2 が許可:%3</translation>
    </message>
    <message>
        <location filename="../model/station/EolStation.cpp" line="227"/>
        <source>no unit was started yet</source>
        <translation>まだ試験を開始した製品がありません</translation>
    </message>
</context>
<context>
    <name>opentop::EolStepRunner</name>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="118"/>
        <source>step %1 (%2)</source>
        <translation>ステップ %1 (%2)</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="124"/>
        <location filename="../model/eol/EolStepRunner.cpp" line="148"/>
        <source>the drive&apos;s session ended</source>
        <translation>ドライバのセッションが終了しました</translation>
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
        <translation>%1: ドライバが通信優先になっていません</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="256"/>
        <source>the stop command failed: %1</source>
        <translation>停止コマンドが失敗しました: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="269"/>
        <source>stopped after %1 s</source>
        <translation>%1 s 後に停止</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="270"/>
        <source>not confirmed stopped: %1</source>
        <translation>停止未確認: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="326"/>
        <source>communication priority could not be given back: %1</source>
        <translation>通信優先を戻せませんでした: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/EolStepRunner.cpp" line="157"/>
        <source>the steps ended with the motor running</source>
        <translation>ステップ終了時にモータが運転中でした</translation>
    </message>
</context>
<context>
    <name>opentop::EolSupport</name>
    <message>
        <location filename="../cli/EolSupport.cpp" line="26"/>
        <source>error: name one recipe file; usage: eol %1</source>
        <translation>エラー: レシピファイルを 1 つ指定してください。使い方: eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="39"/>
        <source>no such file</source>
        <translation>ファイルがありません</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="41"/>
        <source>is a directory; name a recipe file</source>
        <translation>ディレクトリです。レシピファイルを指定してください</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="43"/>
        <source>is not a regular file (a device, FIFO or socket); name a recipe file</source>
        <translation>通常のファイルではありません（デバイス、FIFO、ソケット）。レシピファイルを指定してください</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="45"/>
        <source>is larger than %1 MB, the most a recipe file may hold</source>
        <translation>%1 MB を超えています（レシピファイルの上限）</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="49"/>
        <source>cannot be read: %1</source>
        <translation>読み込めません: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="51"/>
        <location filename="../cli/EolSupport.cpp" line="177"/>
        <source>error: %1: %2</source>
        <translation>エラー: %1: %2</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="78"/>
        <location filename="../cli/EolSupport.cpp" line="199"/>
        <source>error: %1</source>
        <translation>エラー: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="86"/>
        <source>error: %1 refused: %2</source>
        <translation>エラー: %1 は使用できません: %2</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="95"/>
        <source>%1 was changed after OpenTOP wrote it (its checksum does not match), so no station runs it. Check it with &quot;opentop-cli eol recipe check %1&quot; and, when it is right, sign it with &quot;opentop-cli eol recipe sign %1&quot;</source>
        <translation>%1 は OpenTOP が書き込んだ後に変更されています（チェックサム不一致）。そのため、どのステーションでも実行できません。&quot;opentop-cli eol recipe check %1&quot; でチェックし、正しければ &quot;opentop-cli eol recipe sign %1&quot; で署名してください</translation>
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
            <numerusform>位置 %n 箇所</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolSupport.cpp" line="141"/>
        <source>%n setting(s)</source>
        <translation>
            <numerusform>%n 個の設定</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolSupport.cpp" line="143"/>
        <source>%n per-unit value(s)</source>
        <translation>
            <numerusform>個別値 %n 個</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/EolSupport.cpp" line="144"/>
        <source>%n step(s)</source>
        <translation>
            <numerusform>%n ステップ</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="151"/>
        <source>The file to write (recipe create; results --csv; certificate).</source>
        <translation>書き込むファイル（recipe create、results --csv、certificate）。</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="152"/>
        <source>FILE</source>
        <translation>FILE</translation>
    </message>
    <message>
        <location filename="../cli/EolSupport.cpp" line="188"/>
        <source>error: no results database at %1 (nothing recorded there yet); name one with --db URL</source>
        <translation>エラー: %1 に結果データベースがありません（まだ何も記録されていません）。--db URL で指定してください</translation>
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
        <translation>%1 のパラメータではありません</translation>
    </message>
    <message>
        <location filename="../model/eol/EolTarget.cpp" line="51"/>
        <source>this unit&apos;s value is missing</source>
        <translation>この製品の値がありません</translation>
    </message>
    <message>
        <location filename="../model/eol/EolTarget.cpp" line="54"/>
        <source>%1 is outside this product&apos;s range %2–%3 %4</source>
        <translation>%1 はこの製品の範囲 %2–%3 %4 外です</translation>
    </message>
</context>
<context>
    <name>opentop::EolUserCommand</name>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="72"/>
        <source>Add a user (operator, technician, engineer or administrator); the first user is an administrator and needs no --user</source>
        <translation>ユーザーを追加 (作業者、技術者、エンジニア、管理者)。最初のユーザーは管理者で、--user は不要です</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="75"/>
        <source>List the users of the results database</source>
        <translation>結果データベースのユーザー一覧</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="77"/>
        <source>Disable a user: they can no longer log in; their records stay</source>
        <translation>ユーザーを無効化: ログインできなくなります。記録は残ります</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="81"/>
        <source>Set a user&apos;s password (your own with your old one, anyone&apos;s as administrator)</source>
        <translation>ユーザーのパスワードを設定 (自分のものは旧パスワードで、管理者は誰のものでも)</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="87"/>
        <source>Results database: an SQLite file or postgresql://user@host/db.</source>
        <translation>結果データベース: SQLite ファイルまたは postgresql://user@host/db。</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="87"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="90"/>
        <source>user add: operator, technician, engineer or administrator.</source>
        <translation>user add: operator、technician、engineer、administrator のいずれか。</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="92"/>
        <source>ROLE</source>
        <translation>ロール</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="93"/>
        <source>user add: the name shown on the screen.</source>
        <translation>user add: 画面に表示する名前。</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="94"/>
        <source>TEXT</source>
        <translation>テキスト</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="109"/>
        <location filename="../cli/EolUserCommand.cpp" line="168"/>
        <source>error: %1</source>
        <translation>エラー: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="124"/>
        <source>no users: this station is unmanaged (anyone can run, edit and leave); add the first administrator with: opentop-cli eol user add NAME --role administrator</source>
        <translation>ユーザーなし: このステーションは管理されていません (誰でも実行・編集・終了できます)。最初の管理者の追加: opentop-cli eol user add NAME --role administrator</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="130"/>
        <source>user</source>
        <translation>ユーザー</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="130"/>
        <source>name</source>
        <translation>名前</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="130"/>
        <source>role</source>
        <translation>ロール</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="130"/>
        <source>active</source>
        <translation>有効</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="130"/>
        <source>created</source>
        <translation>作成日時</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="133"/>
        <source>yes</source>
        <translation>はい</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="133"/>
        <source>no (disabled)</source>
        <translation>いいえ (無効)</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="145"/>
        <source>usage: opentop-cli eol %1</source>
        <translation>使い方: opentop-cli eol %1</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="153"/>
        <source>error: --role is one of: %1</source>
        <translation>エラー: --role は次のいずれかです: %1</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="183"/>
        <source>Present password for %1: </source>
        <translation>%1 の現在のパスワード: </translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="194"/>
        <location filename="../cli/EolUserCommand.cpp" line="216"/>
        <source>New password for %1: </source>
        <translation>%1 の新しいパスワード: </translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="203"/>
        <source>user %1 added as %2</source>
        <translation>ユーザー %1 を %2 として追加しました</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="211"/>
        <source>user %1 disabled</source>
        <translation>ユーザー %1 を無効にしました</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="221"/>
        <source>password of %1 changed</source>
        <translation>%1 のパスワードを変更しました</translation>
    </message>
    <message>
        <location filename="../cli/EolUserCommand.cpp" line="230"/>
        <source>error: %1; nothing was changed</source>
        <translation>エラー: %1。何も変更していません</translation>
    </message>
</context>
<context>
    <name>opentop::ExitActions</name>
    <message>
        <location filename="../model/run/ExitActions.cpp" line="50"/>
        <source>Machine number %1: left in communication priority, as it was not confirmed stopped</source>
        <translation>局番 %1: 停止を確認できなかったため、通信優先のままにしました</translation>
    </message>
    <message>
        <location filename="../model/run/ExitActions.cpp" line="75"/>
        <source>The stop broadcast to the %1 drives failed: %2</source>
        <translation>%1 ドライバへの停止ブロードキャストに失敗しました: %2</translation>
    </message>
    <message>
        <location filename="../model/run/ExitActions.cpp" line="81"/>
        <source>Machine number %1: STILL RUNNING (%2) %3</source>
        <translation>局番 %1: まだ運転中 (%2) %3</translation>
    </message>
    <message>
        <location filename="../model/run/ExitActions.cpp" line="86"/>
        <source>Machine number %1: NO ANSWER, not confirmed stopped %2</source>
        <translation>局番 %1: 応答なし、停止未確認 %2</translation>
    </message>
    <message>
        <location filename="../model/run/ExitActions.cpp" line="111"/>
        <source>Machine number %1: no way to give control back to its inputs is known</source>
        <translation>局番 %1: 入力端子に制御を戻す方法が不明です</translation>
    </message>
    <message>
        <location filename="../model/run/ExitActions.cpp" line="123"/>
        <source>Machine number %1: %2</source>
        <translation>局番 %1: %2</translation>
    </message>
</context>
<context>
    <name>opentop::ExitCheck</name>
    <message>
        <location filename="../model/run/ExitCheck.cpp" line="20"/>
        <source>in communication priority (its own inputs cannot start or stop it)</source>
        <translation>通信優先（自身の入力端子では起動・停止できません）</translation>
    </message>
    <message>
        <location filename="../model/run/ExitCheck.cpp" line="21"/>
        <source>Machine number %1 (%2): %3</source>
        <translation>局番 %1 (%2): %3</translation>
    </message>
</context>
<context>
    <name>opentop::ExitGuard</name>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="99"/>
        <source>Cancel</source>
        <translation>キャンセル</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="134"/>
        <source>Stopping the drives, then giving control back to their inputs…</source>
        <translation>ドライバを停止し、その後入力端子に制御を戻し中…</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="135"/>
        <source>Stopping the drives…</source>
        <translation>ドライバを停止中…</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="132"/>
        <source>Giving control back to the drives&apos; inputs…</source>
        <translation>ドライバの入力端子に制御を戻し中…</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="159"/>
        <source>Not every drive is safe</source>
        <translation>安全でないドライバがあります</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="160"/>
        <source>Could not %1 every drive:</source>
        <translation>すべてのドライバで%1を完了できませんでした:</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="162"/>
        <source>Stay connected</source>
        <translation>接続したままにする</translation>
    </message>
    <message>
        <location filename="../ui/run/ExitGuard.cpp" line="163"/>
        <source>Go on anyway</source>
        <translation>このまま続行</translation>
    </message>
</context>
<context>
    <name>opentop::ExitPlan</name>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="55"/>
        <source>Stop and give control back</source>
        <translation>停止して制御を戻す</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="56"/>
        <source>Stop the drives</source>
        <translation>ドライバを停止</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="56"/>
        <source>Give control back (I/O priority)</source>
        <translation>制御を戻す（I/O 優先）</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="58"/>
        <source>Give control back only</source>
        <translation>制御を戻すだけ</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="60"/>
        <source>Leave them running</source>
        <translation>運転したままにする</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="60"/>
        <source>Leave them so</source>
        <translation>そのままにする</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="70"/>
        <location filename="../model/run/ExitPlan.cpp" line="73"/>
        <source>give control back to</source>
        <translation>制御の返却</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="71"/>
        <source>stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="71"/>
        <source>stop and give control back to</source>
        <translation>停止と制御の返却</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="82"/>
        <source>Drives are running</source>
        <translation>運転中のドライバがあります</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="82"/>
        <source>Drives left in communication priority</source>
        <translation>通信優先のままのドライバ</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="88"/>
        <source>Before you %1: these drives are left in communication priority.</source>
        <translation>%1の前に: これらのドライバは通信優先のままです。</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="89"/>
        <source>Before you %1: these drives are running or left in communication priority.</source>
        <translation>%1の前に: これらのドライバは運転中、または通信優先のままです。</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="101"/>
        <source>left as it is: it runs from its own inputs (I/O priority), which a stop over the bus does not override</source>
        <translation>そのまま: 自身の入力端子で運転中（I/O 優先）で、バスからの停止指令では変えられません</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="104"/>
        <source>stopped (confirmed by reading it), then given back to its own inputs (I/O priority, read back)</source>
        <translation>停止（読み出して確認）し、その後自身の入力端子に戻す（I/O 優先、読み戻しで確認）</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="107"/>
        <source>stopped (confirmed by reading it); its family has no I/O priority setting, so it stays under the bus&apos;s control</source>
        <translation>停止（読み出して確認）。このファミリには I/O 優先の設定がないため、バスからの制御のままです</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="110"/>
        <source>stopped (confirmed by reading it)</source>
        <translation>停止（読み出して確認）</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="112"/>
        <source>given back to its own inputs (I/O priority, read back)</source>
        <translation>自身の入力端子に戻す（I/O 優先、読み戻しで確認）</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="114"/>
        <source>left as it is: no way to give control back to its inputs is known</source>
        <translation>そのまま: 入力端子に制御を戻す方法が不明です</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="115"/>
        <source>   → %1</source>
        <translation>   → %1</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="122"/>
        <source>In communication priority a drive takes run and stop only from the bus: once OpenTOP lets go, only another bus master or switching its power off stops it.</source>
        <translation>通信優先では、ドライバはバスからのみ運転・停止を受け付けます: OpenTOP が制御を離すと、停止できるのは別のバスマスタか電源遮断だけです。</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="126"/>
        <source>Stopping broadcasts every family&apos;s stop command to the whole bus and checks that each drive above has stopped; a drive that has not stopped is not given back to its inputs.</source>
        <translation>停止では全ファミリの停止コマンドをバス全体にブロードキャストし、上記の各ドライバが停止したことを確認します。停止しなかったドライバは入力端子に戻しません。</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="131"/>
        <source>&quot;Give control back only&quot; sets I/O priority without a stop: the machine&apos;s own inputs decide at once whether the drives run.</source>
        <translation>「制御を戻すだけ」は停止せずに I/O 優先に設定します: ドライバを運転するかどうかは、すぐに機械側の入力が決めます。</translation>
    </message>
    <message>
        <location filename="../model/run/ExitPlan.cpp" line="135"/>
        <source>&quot;Give control back&quot; sets I/O priority, so the machine&apos;s own inputs run the drives again.</source>
        <translation>「制御を戻す」は I/O 優先に設定し、機械側の入力で再びドライバを運転できるようにします。</translation>
    </message>
</context>
<context>
    <name>opentop::FaultInjector</name>
    <message>
        <location filename="../sim/FaultInjector.cpp" line="30"/>
        <source>fault &apos;%1&apos; must be NAME=VALUE; names: %2</source>
        <translation>フォールト &apos;%1&apos; は NAME=VALUE でなければなりません。名前: %2</translation>
    </message>
    <message>
        <location filename="../sim/FaultInjector.cpp" line="38"/>
        <source>late_ms must be a whole number of milliseconds 1..60000, got &apos;%1&apos;</source>
        <translation>late_ms は 1..60000 のミリ秒の整数でなければなりません（指定値 &apos;%1&apos;）</translation>
    </message>
    <message>
        <location filename="../sim/FaultInjector.cpp" line="52"/>
        <source>unknown fault &apos;%1&apos;; allowed: %2</source>
        <translation>不明なフォールト &apos;%1&apos;。使用可能: %2</translation>
    </message>
    <message>
        <location filename="../sim/FaultInjector.cpp" line="57"/>
        <source>fault rate %1 must be a number 0..1, got &apos;%2&apos;</source>
        <translation>フォールト率 %1 は 0..1 の数値でなければなりません（指定値 &apos;%2&apos;）</translation>
    </message>
    <message>
        <location filename="../sim/FaultInjector.cpp" line="64"/>
        <source>the fault rates add up to more than 1</source>
        <translation>フォールト率の合計が 1 を超えています</translation>
    </message>
</context>
<context>
    <name>opentop::FileActions</name>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="22"/>
        <source>OpenTOP backups (*.json);;All files (*)</source>
        <translation>OpenTOP バックアップ (*.json);;すべてのファイル (*)</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="38"/>
        <location filename="../ui/files/FileActions.cpp" line="94"/>
        <source>&amp;Back up selected drive…</source>
        <translation>選択したドライバをバックアップ(&amp;B)…</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="44"/>
        <source>Back up &amp;whole bus…</source>
        <translation>バス全体をバックアップ(&amp;W)…</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="50"/>
        <source>Save the settings of every identified drive to one file</source>
        <translation>識別済みの全ドライバの設定を 1 つのファイルに保存します</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="52"/>
        <source>&amp;Open backup file…</source>
        <translation>バックアップファイルを開く(&amp;O)…</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="54"/>
        <source>Show the drives and settings a backup file holds</source>
        <translation>バックアップファイルに含まれるドライバと設定を表示します</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="55"/>
        <source>Co&amp;mpare…</source>
        <translation>比較(&amp;M)…</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="58"/>
        <source>Compare drives and backup files side by side, or against factory defaults</source>
        <translation>ドライバやバックアップファイルを並べて比較、または工場出荷時設定と比較します</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="59"/>
        <source>&amp;Restore from file…</source>
        <translation>ファイルから復元(&amp;R)…</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="60"/>
        <source>Preview, then write a backup&apos;s settings back to drives</source>
        <translation>プレビューしてから、バックアップの設定をドライバに書き戻します</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="93"/>
        <source>&amp;Back up selected drives…</source>
        <translation>選択したドライバをバックアップ(&amp;B)…</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="96"/>
        <source>Select an identified drive in the bus list first</source>
        <translation>先にバスリストで識別済みのドライバを選択してください</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="97"/>
        <source>Save the settings of the selected drive(s) to a file</source>
        <translation>選択したドライバの設定をファイルに保存します</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="108"/>
        <source>Back up to file</source>
        <translation>ファイルにバックアップ</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="120"/>
        <source>Open backup file</source>
        <translation>バックアップファイルを開く</translation>
    </message>
    <message>
        <location filename="../ui/files/FileActions.cpp" line="141"/>
        <source>Restore from backup file</source>
        <translation>バックアップファイルから復元</translation>
    </message>
</context>
<context>
    <name>opentop::FileCommandSupport</name>
    <message>
        <location filename="../cli/FileCommandSupport.cpp" line="29"/>
        <source>no such file</source>
        <translation>ファイルがありません</translation>
    </message>
    <message>
        <location filename="../cli/FileCommandSupport.cpp" line="31"/>
        <source>is a directory; name a backup file</source>
        <translation>ディレクトリです。バックアップファイルを指定してください</translation>
    </message>
    <message>
        <location filename="../cli/FileCommandSupport.cpp" line="33"/>
        <source>is not a regular file (a device, FIFO or socket); name a backup file</source>
        <translation>通常のファイルではありません（デバイス、FIFO、ソケット）。バックアップファイルを指定してください</translation>
    </message>
    <message>
        <location filename="../cli/FileCommandSupport.cpp" line="35"/>
        <source>error: %1: %2</source>
        <translation>エラー: %1: %2</translation>
    </message>
    <message>
        <location filename="../cli/FileCommandSupport.cpp" line="43"/>
        <source>error: %1 refused: %2</source>
        <translation>エラー: %1 は使用できません: %2</translation>
    </message>
</context>
<context>
    <name>opentop::FixedLineHint</name>
    <message>
        <location filename="../model/bus/FixedLineHint.cpp" line="41"/>
        <source>A DC controller in potentiometer/analog control mode talks only at %1 bit/s, 8%2%3, address %4.</source>
        <translation>ボリューム/アナログ制御モードの DC コントローラは %1 bit/s、8%2%3、アドレス %4 でのみ通信します。</translation>
    </message>
    <message>
        <location filename="../model/bus/FixedLineHint.cpp" line="60"/>
        <source>%1 8%2%3, address %4</source>
        <translation>%1 8%2%3、アドレス %4</translation>
    </message>
</context>
<context>
    <name>opentop::GainDesign</name>
    <message>
        <location filename="../model/tuning/GainDesign.cpp" line="21"/>
        <source>the model has no ultimate point</source>
        <translation>モデルに限界点がありません</translation>
    </message>
    <message>
        <location filename="../model/tuning/GainDesign.cpp" line="55"/>
        <source>no gains from the %1 rule settle within %2 ms with at most %3 % overshoot on the motor&apos;s model, even with P at a tenth of the rule&apos;s</source>
        <translation>P をルールの 1/10 まで下げても、モータのモデル上で %1 ルールのゲインが %2 ms 以内に、オーバーシュート %3 % 以下で整定しません</translation>
    </message>
    <message>
        <location filename="../model/tuning/GainDesign.cpp" line="60"/>
        <source>Try a rule that allows more overshoot or a smaller step (a lower operating speed), or raise the drive&apos;s current limit if the motor allows it.</source>
        <translation>オーバーシュートの大きいルールか、小さいステップ（低い運転速度）を試すか、モータが許せばドライバの電流制限を上げてください。</translation>
    </message>
</context>
<context>
    <name>opentop::GetCommand</name>
    <message>
        <location filename="../cli/GetCommand.cpp" line="44"/>
        <source>Read parameters by name in engineering units (or registers with --raw)</source>
        <translation>パラメータを名前で指定し、工業単位で読み出します（--raw ではレジスタ）</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="50"/>
        <source>Read every parameter of a group (see params).</source>
        <translation>グループの全パラメータを読み出します（params を参照）。</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="50"/>
        <source>GROUP</source>
        <translation>GROUP</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="51"/>
        <source>Read every readable parameter.</source>
        <translation>読出し可能な全パラメータを読み出します。</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="53"/>
        <source>Read registers by address: ADDR or ADDR:COUNT (0x.. or decimal).</source>
        <translation>アドレスでレジスタを読み出します: ADDR または ADDR:COUNT（0x.. または 10 進）。</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="53"/>
        <source>ADDR</source>
        <translation>ADDR</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="55"/>
        <source>Function code for --raw: 3 (holding) or 4 (input) to read, 6 or 16 to write.</source>
        <translation>--raw のファンクションコード: 読出しは 3（保持レジスタ）または 4（入力レジスタ）、書込みは 6 または 16。</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="56"/>
        <source>FC</source>
        <translation>FC</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="64"/>
        <source>error: give one machine number first: get ID NAME...</source>
        <translation>エラー: 最初に局番を 1 つ指定してください: get ID NAME...</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="72"/>
        <source>error: name parameters, or give exactly one of --group, --all, --raw</source>
        <translation>エラー: パラメータ名を指定するか、--group、--all、--raw のいずれか 1 つを指定してください</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="80"/>
        <location filename="../cli/GetCommand.cpp" line="210"/>
        <source>error: %1</source>
        <translation>エラー: %1</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="91"/>
        <source>error: %1 has no group &quot;%2&quot;; groups: %3</source>
        <translation>エラー: %1 にグループ &quot;%2&quot; はありません。グループ: %3</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="109"/>
        <source>error: %1 is a write-only command and cannot be read</source>
        <translation>エラー: %1 は書込み専用コマンドのため読み出せません</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="110"/>
        <source>error: %1 has no parameter &quot;%2&quot;; see &quot;opentop-cli params --family %1&quot;</source>
        <translation>エラー: %1 にパラメータ &quot;%2&quot; はありません。&quot;opentop-cli params --family %1&quot; を参照してください</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="124"/>
        <source>interrupted</source>
        <translation>中断</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="154"/>
        <source>Parameter</source>
        <translation>パラメータ</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="154"/>
        <source>Value</source>
        <translation>値</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="154"/>
        <source>Raw</source>
        <translation>生データ</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="154"/>
        <source>Label</source>
        <translation>ラベル</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="159"/>
        <source>(failed: %1)</source>
        <translation>（失敗: %1）</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="161"/>
        <source>  ! outside the profile&apos;s allowed values</source>
        <translation>  ! プロファイルの許容値外</translation>
    </message>
    <message numerus="yes">
        <location filename="../cli/GetCommand.cpp" line="168"/>
        <source>error: %n parameter(s) could not be read</source>
        <translation>
            <numerusform>エラー: %n 個のパラメータを読み出せませんでした</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="191"/>
        <source>error: --raw needs ADDR or ADDR:COUNT (address 0x0000–0xFFFF, count 1–125) and --fc 3 or 4</source>
        <translation>エラー: --raw には ADDR または ADDR:COUNT（アドレス 0x0000–0xFFFF、個数 1–125）と --fc 3 または 4 が必要です</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="223"/>
        <source>Address</source>
        <translation>アドレス</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="223"/>
        <source>Hex</source>
        <translation>16 進</translation>
    </message>
    <message>
        <location filename="../cli/GetCommand.cpp" line="223"/>
        <source>Decimal</source>
        <translation>10 進</translation>
    </message>
</context>
<context>
    <name>opentop::GoldenLimits</name>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="67"/>
        <source>the golden unit did not pass its own test (%1): no limits can come from it</source>
        <translation>マスター品が自身の検査に合格しませんでした (%1): 判定値を決められません</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="75"/>
        <source>machine number %1: unknown family &quot;%2&quot;</source>
        <translation>局番 %1: 不明な機種ファミリ「%2」</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="94"/>
        <source>machine number %1: unknown parameter &quot;%2&quot;</source>
        <translation>局番 %1: 不明なパラメータ「%2」</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="104"/>
        <source>machine number %1: the golden unit&apos;s %2 was not measured</source>
        <translation>局番 %1: マスター品の %2 が測定されていません</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="129"/>
        <source>Hold limits measured on the golden unit on %1: the measured value ± %2 % (at least %3 % of full scale), never wider than the default limits.</source>
        <translation>保持ステップの判定値は %1 にマスター品で測定: 測定値 ± %2 % (最小でもフルスケールの %3 %)、既定の判定値より広げません。</translation>
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
        <translation>判定値なし</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="153"/>
        <source>%1 %2 (kept: measured %3)</source>
        <translation>%1 %2 (変更なし: 測定値 %3)</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenLimits.cpp" line="155"/>
        <source>%1 %2 (default %3, measured %4)</source>
        <translation>%1 %2 (既定 %3、測定値 %4)</translation>
    </message>
</context>
<context>
    <name>opentop::GoldenMeasure</name>
    <message>
        <location filename="../model/eol/GoldenMeasure.cpp" line="31"/>
        <source>machine number %1 (%2): runs its motor for about %3 s: %4</source>
        <translation>局番 %1 (%2): モータを約 %3 s 運転します: %4</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenMeasure.cpp" line="43"/>
        <source>golden unit</source>
        <translation>マスター品</translation>
    </message>
    <message>
        <location filename="../model/eol/GoldenMeasure.cpp" line="44"/>
        <source>recipe from a golden unit</source>
        <translation>マスター品からのレシピ作成</translation>
    </message>
</context>
<context>
    <name>opentop::GoldenMeasureButton</name>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="36"/>
        <source>Measure limits…</source>
        <translation>判定値を測定…</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="42"/>
        <source>Run the golden unit on the bus through the recipe&apos;s steps once and take the hold limits from what it measures: the measured value ± 25 % (at least 5 % of full scale), never wider than the limits before</source>
        <translation>バス上のマスター品をレシピのステップどおりに一度運転し、測定値から保持ステップの判定値を決めます: 測定値 ± 25 % (最小でもフルスケールの 5 %)、元の判定値より広げません</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="52"/>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="87"/>
        <source>Measure limits on the golden unit</source>
        <translation>マスター品で判定値を測定</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="60"/>
        <source>The recipe has no positions.</source>
        <translation>レシピにポジションがありません。</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="61"/>
        <source>The recipe cannot be read: %1</source>
        <translation>レシピを読み取れません: %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="65"/>
        <source>Machine number %1 is not a drive on the bus: connect to the golden unit and scan first.</source>
        <translation>局番 %1 はバス上のドライバではありません: 先にマスター品に接続してスキャンしてください。</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="70"/>
        <source>Run the golden unit through the recipe&apos;s steps? These motors turn:</source>
        <translation>マスター品をレシピのステップどおりに運転しますか? 次のモータが回転します:</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="76"/>
        <source>Run the motors</source>
        <translation>モータを運転</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="90"/>
        <source>The bus is not connected.</source>
        <translation>バスが接続されていません。</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="95"/>
        <source>Measuring the golden unit…</source>
        <translation>マスター品を測定中…</translation>
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
        <translation>ユーザーが停止</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="108"/>
        <source>Machine number %1: %2</source>
        <translation>局番 %1: %2</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="120"/>
        <source>%1 is not confirmed stopped.</source>
        <translation>%1 の停止を確認できていません。</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="122"/>
        <source>No limits were taken: %1</source>
        <translation>判定値は決められませんでした: %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="129"/>
        <source>Machine number %1, step %2: %3</source>
        <translation>局番 %1、ステップ %2: %3</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenMeasureButton.cpp" line="135"/>
        <source>The hold limits now follow the golden unit. Check them, then save the recipe.</source>
        <translation>保持ステップの判定値をマスター品に合わせました。確認してからレシピを保存してください。</translation>
    </message>
</context>
<context>
    <name>opentop::GoldenRecipeSource</name>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="39"/>
        <source>New recipe from %1: check the settings and the test steps&apos; limits, then save it.</source>
        <translation>%1 から新規レシピ: 設定と試験ステップの規格値を確認してから保存してください。</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="55"/>
        <source>machine number %1 is not a known drive on the bus; scan the bus first</source>
        <translation>局番 %1 はバス上の既知のドライバではありません。先にバスをスキャンしてください</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="64"/>
        <source>Reading the golden unit&apos;s settings…</source>
        <translation>マスター品の設定を読出し中…</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="64"/>
        <source>Cancel</source>
        <translation>キャンセル</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="73"/>
        <source>machine number %1 is not on the bus</source>
        <translation>局番 %1 はバス上にありません</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="86"/>
        <source>cancelled: no recipe was made</source>
        <translation>キャンセル: レシピは作成していません</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="98"/>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="103"/>
        <source>New recipe</source>
        <translation>新規レシピ</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="98"/>
        <source>Product name:</source>
        <translation>製品名:</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="103"/>
        <source>Revision:</source>
        <translation>リビジョン:</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="111"/>
        <source>Golden unit&apos;s backup file</source>
        <translation>マスター品のバックアップファイル</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="112"/>
        <source>Backups (*.json)</source>
        <translation>バックアップ (*.json)</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="124"/>
        <source>No drives on the bus: connect and scan first.</source>
        <translation>バス上にドライバがありません: 先に接続してスキャンしてください。</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="132"/>
        <source>New recipe from drives</source>
        <translation>ドライバから新規レシピ</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="133"/>
        <source>Machine numbers of the golden unit&apos;s drives (found: %1):</source>
        <translation>マスター品のドライバの局番（検出: %1）:</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="143"/>
        <source>&quot;%1&quot; is not a machine number (1–247)</source>
        <translation>&quot;%1&quot; は局番 (1–247) ではありません</translation>
    </message>
    <message>
        <location filename="../ui/eol/GoldenRecipeSource.cpp" line="152"/>
        <source>New recipe from the drives on the bus: check the settings and the test steps&apos; limits, then save it.</source>
        <translation>バス上のドライバから新規レシピ: 設定と試験ステップの規格値を確認してから保存してください。</translation>
    </message>
</context>
<context>
    <name>opentop::GroupCheck</name>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="65"/>
        <location filename="../cli/GroupCheck.cpp" line="131"/>
        <source>error: %1</source>
        <translation>エラー: %1</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="73"/>
        <source>note: --no-group-check: drives in communication group %1 (which also execute what is sent to %1) were not looked for</source>
        <translation>注意: --no-group-check: 通信グループ %1 のドライバ（%1 に送られたものを同時に実行する）は探していません</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="79"/>
        <source>error: the drives on this bus are not known, so drives in communication group %1 (which also execute what is sent to %1, without replying) cannot be named; nothing was sent</source>
        <translation>エラー: このバス上のドライバが不明なため、通信グループ %1 のドライバ（%1 に送られたものを応答せずに同時に実行する）を示せません。何も送信していません</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="84"/>
        <source>scan the bus first (opentop-cli scan), name its drives with --bus-drives LIST, or add --no-group-check to send it without looking</source>
        <translation>先にバスをスキャンする（opentop-cli scan）か、--bus-drives LIST でドライバを指定するか、確認せずに送るには --no-group-check を付けてください</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="109"/>
        <source>warning: the communication group of %1 could not be read</source>
        <translation>警告: %1 の通信グループを読み出せませんでした</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="119"/>
        <source>note: the drives on the bus are %1, from %2; drives added since are not known until the next scan</source>
        <translation>注意: バス上のドライバは %1（%2 による）。その後追加されたドライバは次のスキャンまでわかりません</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="131"/>
        <source>note: %1</source>
        <translation>注: %1</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="134"/>
        <source>add --yes to send it to all of %1 and %2; nothing was sent</source>
        <translation>%1 と %2 のすべてに送信するには --yes を付けてください。何も送信していません</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="169"/>
        <source>not readable</source>
        <translation>読出し不可</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="193"/>
        <source>Read back from the drives of the group:</source>
        <translation>グループのドライバから読み戻した値:</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="194"/>
        <source>Drive</source>
        <translation>ドライバ</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="194"/>
        <source>Parameter</source>
        <translation>パラメータ</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="194"/>
        <source>Value</source>
        <translation>値</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="194"/>
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="197"/>
        <source>(not read: %1)</source>
        <translation>（未読出し: %1）</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="198"/>
        <source>verified</source>
        <translation>確認済み</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="199"/>
        <source>DIFFERS from what was written</source>
        <translation>書き込んだ値と異なる</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="200"/>
        <source>not verified</source>
        <translation>未確認</translation>
    </message>
    <message>
        <location filename="../cli/GroupCheck.cpp" line="248"/>
        <source>off</source>
        <translation>無効</translation>
    </message>
</context>
<context>
    <name>opentop::GroupFollowers</name>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="78"/>
        <source>could not be read</source>
        <translation>読み出せませんでした</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="109"/>
        <source>its control priority could not be read</source>
        <translation>制御優先を読み出せませんでした</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="111"/>
        <source>it is in %1: it takes run commands only from its input terminals and ignores them over the bus</source>
        <translation>%1 です。運転コマンドは入力端子からしか受け付けず、通信で送られたものは無視します</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="115"/>
        <source>an alarm is active: it runs only once the alarm is cleared</source>
        <translation>アラームが発生しています。アラームが解除されるまで運転しません</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="129"/>
        <source>error code %1h</source>
        <translation>エラーコード %1h</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="154"/>
        <source>Machine number %1 follows it.</source>
        <translation>局番 %1 は従います。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="155"/>
        <source>Machine number %1 follows it (%2).</source>
        <translation>局番 %1 は従います（%2）。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="158"/>
        <source>Machine number %1: not known whether it follows: %2.</source>
        <translation>局番 %1: 従うかどうか不明です: %2。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="160"/>
        <source>Machine number %1 does NOT follow it: %2. To run it with this drive, set its control priority to communication priority; otherwise it shows E2h &quot;Cannot execute command&quot;.</source>
        <translation>局番 %1 は従いません: %2。このドライバと一緒に運転するには、制御優先を通信優先に設定してください。そうしないと E2h「コマンド実行不可」を表示します。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="174"/>
        <source>Machine number %1: its run state could not be read.</source>
        <translation>局番 %1: 運転状態を読み出せませんでした。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="176"/>
        <source>Machine number %1 runs.</source>
        <translation>局番 %1 は運転中です。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="177"/>
        <source>Machine number %1 runs (%2).</source>
        <translation>局番 %1 は運転中です（%2）。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="179"/>
        <source>Machine number %1 does not run: %2.</source>
        <translation>局番 %1 は運転していません: %2。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="181"/>
        <source>Machine number %1 does not run.</source>
        <translation>局番 %1 は運転していません。</translation>
    </message>
    <message>
        <location filename="../model/run/GroupFollowers.cpp" line="183"/>
        <source>It shows %1</source>
        <translation>表示: %1</translation>
    </message>
</context>
<context>
    <name>opentop::GroupWriteCheck</name>
    <message>
        <location filename="../ui/groups/GroupWriteCheck.cpp" line="50"/>
        <source>Machine number %1: %2</source>
        <translation>局番 %1: %2</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupWriteCheck.cpp" line="59"/>
        <source>Communication group</source>
        <translation>通信グループ</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupWriteCheck.cpp" line="64"/>
        <source>Their values are read back afterwards.</source>
        <translation>値は送信後に読み戻します。</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupWriteCheck.cpp" line="65"/>
        <source>Send, also to %1</source>
        <translation>%1 にも送信</translation>
    </message>
</context>
<context>
    <name>opentop::GroupsView</name>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="34"/>
        <source>Read &amp;groups again</source>
        <translation>グループを再読出し(&amp;G)</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="35"/>
        <source>&amp;Write plan…</source>
        <translation>計画を書込み(&amp;W)…</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="38"/>
        <source>A drive whose communication group is another drive&apos;s machine number is that drive&apos;s child: it executes every write and command sent to its parent, without replying. Plan the groups in the last column and write them; every drive&apos;s group is then read back.</source>
        <translation>通信グループが他のドライバの局番になっているドライバは、そのドライバの子局です: 親局に送信されたすべての書込みとコマンドを、応答せずに実行します。最後の列でグループを計画して書き込んでください。その後、全ドライバのグループを読み戻します。</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="49"/>
        <source>Machine number</source>
        <translation>局番</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="49"/>
        <source>Model</source>
        <translation>型式</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="49"/>
        <source>Group</source>
        <translation>グループ</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="50"/>
        <source>Follows / followed by</source>
        <translation>親局 / 子局</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="50"/>
        <source>Problem</source>
        <translation>問題</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="50"/>
        <source>Plan</source>
        <translation>計画</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="51"/>
        <source>Read back</source>
        <translation>読み戻し</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="57"/>
        <source>Read every drive&apos;s communication group from the drive</source>
        <translation>全ドライバの通信グループをドライバから読み出します</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="58"/>
        <source>Write the planned groups (asks first), then read every drive&apos;s group back</source>
        <translation>計画したグループを書き込み（事前に確認）、全ドライバのグループを読み戻します</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="79"/>
        <location filename="../ui/groups/GroupsView.cpp" line="145"/>
        <source>Disabled</source>
        <translation>無効</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="146"/>
        <source>Planned group of machine number %1</source>
        <translation>局番 %1 の計画グループ</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="147"/>
        <source>The group machine number %1 should have: its own number makes it a parent, another drive&apos;s number its child; Disabled: no group</source>
        <translation>局番 %1 に設定するグループ: 自身の局番なら親局、他のドライバの局番ならその子局になります。無効: グループなし</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="166"/>
        <source>child and parent</source>
        <translation>子局かつ親局</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="167"/>
        <source>no drive %1</source>
        <translation>ドライバ %1 なし</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="176"/>
        <source>not read</source>
        <translation>未読出し</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="198"/>
        <source>No problem found in the groups as read from the drives.</source>
        <translation>ドライバから読み出したグループに問題はありません。</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="199"/>
        <source>Problems:</source>
        <translation>問題:</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="206"/>
        <source>%1: %2 → %3</source>
        <translation>%1: %2 → %3</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="213"/>
        <source>The plan is what the drives hold.</source>
        <translation>計画はドライバの現在値と同じです。</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="214"/>
        <source>Plan changes: %1.</source>
        <translation>計画の変更: %1。</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="216"/>
        <source>After it: %1</source>
        <translation>変更後: %1</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="242"/>
        <source>Reading every drive&apos;s group…</source>
        <translation>全ドライバのグループを読出し中…</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/groups/GroupsView.cpp" line="248"/>
        <source>%n drive(s) did not answer</source>
        <translation>
            <numerusform>%n 台のドライバが応答しませんでした</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="263"/>
        <source>Machine number %1: group %2 → %3.</source>
        <translation>局番 %1: グループ %2 → %3。</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="268"/>
        <source>This also reaches %1 (its children), which are written again after it.</source>
        <translation>これは %1（子局）にも届くため、子局はその後に再度書き込みます。</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="277"/>
        <source>Warning: %1</source>
        <translation>警告: %1</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="279"/>
        <source>Write communication groups</source>
        <translation>通信グループの書込み</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/groups/GroupsView.cpp" line="280"/>
        <source>Write the planned communication group to %n drive(s)?</source>
        <translation>
            <numerusform>計画した通信グループを %n 台のドライバに書き込みますか？</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="284"/>
        <source>Drives with children are written last; every drive&apos;s group is read back afterwards.</source>
        <translation>子局を持つドライバは最後に書き込みます。その後、全ドライバのグループを読み戻します。</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="286"/>
        <source>&amp;Write groups</source>
        <translation>グループを書込み(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="317"/>
        <source>Writing group %1 to machine number %2…</source>
        <translation>グループ %1 を局番 %2 に書込み中…</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="326"/>
        <source>write failed: %1</source>
        <translation>書込み失敗: %1</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="340"/>
        <source>Reading every drive&apos;s group back…</source>
        <translation>全ドライバのグループを読み戻し中…</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="353"/>
        <source>write failed</source>
        <translation>書込み失敗</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="354"/>
        <source>✓ %1</source>
        <translation>✓ %1</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="355"/>
        <source>✗ %1, planned %2</source>
        <translation>✗ %1、計画 %2</translation>
    </message>
    <message>
        <location filename="../ui/groups/GroupsView.cpp" line="365"/>
        <source>Proved: every drive read back holds its planned group.</source>
        <translation>確認完了: 読み戻した全ドライバが計画どおりのグループです。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/groups/GroupsView.cpp" line="366"/>
        <source>Not as planned: %1 (read back; %n drive(s) did not answer).</source>
        <translation>
            <numerusform>計画と不一致: %1（読み戻し。%n 台のドライバが応答なし）。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::HelpActions</name>
    <message>
        <location filename="../ui/help/HelpActions.cpp" line="18"/>
        <source>&amp;User guide</source>
        <translation>ユーザガイド(&amp;U)</translation>
    </message>
    <message>
        <location filename="../ui/help/HelpActions.cpp" line="21"/>
        <source>&amp;Keyboard shortcuts</source>
        <translation>キーボードショートカット(&amp;K)</translation>
    </message>
    <message>
        <location filename="../ui/help/HelpActions.cpp" line="25"/>
        <source>&amp;About OpenTOP</source>
        <translation>OpenTOP について(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/help/HelpActions.cpp" line="28"/>
        <source>About &amp;Qt</source>
        <translation>Qt について(&amp;Q)</translation>
    </message>
</context>
<context>
    <name>opentop::IdentityDialog</name>
    <message>
        <location filename="../ui/eol/IdentityDialog.cpp" line="23"/>
        <source>Who is it?</source>
        <translation>どなたですか?</translation>
    </message>
    <message>
        <location filename="../ui/eol/IdentityDialog.cpp" line="25"/>
        <source>To %1 this station needs the %2 role or higher. Log in with your user name and password.</source>
        <translation>%1には、このステーションでは %2 以上のロールが必要です。ユーザー名とパスワードでログインしてください。</translation>
    </message>
    <message>
        <location filename="../ui/eol/IdentityDialog.cpp" line="42"/>
        <source>User name:</source>
        <translation>ユーザー名:</translation>
    </message>
    <message>
        <location filename="../ui/eol/IdentityDialog.cpp" line="43"/>
        <source>Password:</source>
        <translation>パスワード:</translation>
    </message>
    <message>
        <location filename="../ui/eol/IdentityDialog.cpp" line="62"/>
        <source>Refused: %1</source>
        <translation>拒否: %1</translation>
    </message>
</context>
<context>
    <name>opentop::InputFile</name>
    <message>
        <location filename="../model/io/InputFile.cpp" line="13"/>
        <source>cannot read %1: %2</source>
        <translation>%1 を読み込めません: %2</translation>
    </message>
</context>
<context>
    <name>opentop::IoTerminalsPage</name>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="31"/>
        <source>Not functioning: the drive ignores this input.</source>
        <translation>機能なし: ドライバはこの入力を無視します。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="33"/>
        <source>RUN/STOP: ON runs the motor, OFF stops it.</source>
        <translation>RUN/STOP: ON でモータ運転、OFF で停止。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="35"/>
        <source>CW/CCW: the running direction, OFF clockwise, ON counter-clockwise.</source>
        <translation>CW/CCW: 回転方向。OFF で時計回り (CW)、ON で反時計回り (CCW)。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="38"/>
        <source>CW/STOP: ON runs the motor clockwise, OFF stops it.</source>
        <translation>CW/STOP: ON でモータを時計回りに運転、OFF で停止。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="40"/>
        <source>CCW/STOP: ON runs the motor counter-clockwise, OFF stops it.</source>
        <translation>CCW/STOP: ON でモータを反時計回りに運転、OFF で停止。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="43"/>
        <source>Alarm-Reset: clears an alarm (alarm erase method Alarm-Reset).</source>
        <translation>Alarm-Reset: アラームを解除します（アラーム解除方法が Alarm-Reset の場合）。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="51"/>
        <source>M%1: bit %1 of the running data selection (M2 M1 M0 = 000–111 select SPno1–SPno8).</source>
        <translation>M%1: 運転データ選択のビット %1（M2 M1 M0 = 000–111 で SPno1–SPno8 を選択）。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="56"/>
        <source>Ext-Error (EX-Er): an external interrupt that stops the motor; the only input still active in communication priority.</source>
        <translation>Ext-Error (EX-Er): モータを停止させる外部停止入力。通信優先でも有効な唯一の入力です。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="61"/>
        <source>H-Free: releases the motor&apos;s holding force while stopped.</source>
        <translation>H-Free: 停止中のモータの保持力を解除します。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="63"/>
        <source>Code %1 is not a known input function.</source>
        <translation>コード %1 は既知の入力機能ではありません。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="71"/>
        <source>Not functioning: the output stays off.</source>
        <translation>機能なし: 出力はオフのままです。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="73"/>
        <source>Alarm-Out: switches when an alarm stops the motor.</source>
        <translation>Alarm-Out: アラームでモータが停止すると切り替わります。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="75"/>
        <source>Reach Speed-Out: switches when the motor reaches the target speed.</source>
        <translation>Reach Speed-Out: モータが目標速度に到達すると切り替わります。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="78"/>
        <source>VA-Out: switches before the target speed, at the target speed minus the VA speed.</source>
        <translation>VA-Out: 目標速度の手前、目標速度から VA 速度を引いた速度で切り替わります。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="81"/>
        <source>Speed-Out: speed pulses, 24 per motor revolution.</source>
        <translation>Speed-Out: 速度パルス、モータ 1 回転あたり 24 パルス。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="83"/>
        <source>Warning-Out: switches on a warning; the motor keeps running.</source>
        <translation>Warning-Out: 警告で切り替わります。モータは運転を続けます。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="86"/>
        <source>Move-Out: switches while the motor is turning.</source>
        <translation>Move-Out: モータ回転中に切り替わります。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="88"/>
        <source>Code %1 is not a known output function.</source>
        <translation>コード %1 は既知の出力機能ではありません。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="102"/>
        <source>I/O terminals</source>
        <translation>I/O 端子</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="118"/>
        <source>Control</source>
        <translation>制御</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="123"/>
        <source>Control &amp;mode:</source>
        <translation>制御モード(&amp;M):</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="124"/>
        <source>Mode1 uses RUN/STOP and CW/CCW inputs (like UBD, SBD, DBD); Mode2 uses CW/STOP and CCW/STOP inputs (like DB, BMD). The input function codes differ: switching the mode disables the other mode&apos;s input functions, so every input X0–X3 needs a function of the new mode.</source>
        <translation>Mode1 は RUN/STOP と CW/CCW 入力を使用します（UBD、SBD、DBD と同様）。Mode2 は CW/STOP と CCW/STOP 入力を使用します（DB、BMD と同様）。入力機能コードが異なるため、モードを切り替えると他方のモードの入力機能は無効になります。したがって、入力 X0–X3 のすべてに新しいモードの機能を割り当てる必要があります。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="136"/>
        <source>Control &amp;priority:</source>
        <translation>制御優先(&amp;P):</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="137"/>
        <source>In I/O priority the input terminals run the motor. In communication priority the drive runs from bus commands and of the inputs only EX-Er (external error) acts.</source>
        <translation>I/O 優先では入力端子でモータを運転します。通信優先ではドライバはバスのコマンドで運転し、入力端子は EX-Er（外部エラー）のみ有効です。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="146"/>
        <source>Inputs — CN5</source>
        <translation>入力 — CN5</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="148"/>
        <source>COM0: input common (external supply)</source>
        <translation>COM0: 入力コモン（外部電源）</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="151"/>
        <source>COM1: input common (internal supply)</source>
        <translation>COM1: 入力コモン（内部電源）</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="156"/>
        <source>Outputs — CN6</source>
        <translation>出力 — CN6</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="174"/>
        <source>Give each flagged input the default function of the new mode (pending, not written)</source>
        <translation>マークされた各入力に新しいモードの初期機能を割り当てます（未書込み。書込みはしません）</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="203"/>
        <source>Connector pin %1</source>
        <translation>コネクタピン %1</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="208"/>
        <source>Terminal %1 function</source>
        <translation>端子 %1 の機能</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="235"/>
        <source>unknown</source>
        <translation>不明</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="261"/>
        <source>Not read yet.</source>
        <translation>未読出しです。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="268"/>
        <source>Not valid in %1: choose again</source>
        <translation>%1 では無効です: 選び直してください</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="296"/>
        <source>The mode changes from %1 to %2 when written; Write page writes the mode first, then the terminals.</source>
        <translation>書き込むとモードが %1 から %2 に変わります。「ページ書込み」はモードを先に書き込み、その後に端子を書き込みます。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="306"/>
        <source>Not valid in %1: %2. Choose their functions again before writing.</source>
        <translation>%1 では無効です: %2。書き込む前に機能を選び直してください。</translation>
    </message>
    <message>
        <location filename="../ui/pages/IoTerminalsPage.cpp" line="309"/>
        <source>Use %1 defaults</source>
        <translation>%1 の初期値を使用</translation>
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
        <translation>&quot;%1&quot; がありません</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="33"/>
        <source>&quot;%1&quot; must be a string</source>
        <translation>&quot;%1&quot; は文字列でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="48"/>
        <source>&quot;%1&quot; must be a number</source>
        <translation>&quot;%1&quot; は数値でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="59"/>
        <source>%1 must be a whole number</source>
        <translation>%1 は整数でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="64"/>
        <source>%1 is out of range</source>
        <translation>%1 が範囲外です</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="80"/>
        <source>%1 must be an integer or a &quot;0x...&quot; string</source>
        <translation>%1 は整数または &quot;0x...&quot; 形式の文字列でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="104"/>
        <source>&quot;%1&quot; must be an array</source>
        <translation>&quot;%1&quot; は配列でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="120"/>
        <source>&quot;%1&quot; must be an object</source>
        <translation>&quot;%1&quot; はオブジェクトでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/JsonReader.cpp" line="130"/>
        <source>%1: unknown key &quot;%2&quot;</source>
        <translation>%1: 不明なキー &quot;%2&quot;</translation>
    </message>
</context>
<context>
    <name>opentop::Language</name>
    <message>
        <location filename="../model/i18n/Language.cpp" line="140"/>
        <source>unknown language &apos;%1&apos;; available: %2</source>
        <translation>不明な言語 &apos;%1&apos;。使用可能: %2</translation>
    </message>
    <message>
        <location filename="../model/i18n/Language.cpp" line="167"/>
        <source>the %1 translation is missing from this build</source>
        <translation>このビルドには %1 の翻訳がありません</translation>
    </message>
</context>
<context>
    <name>opentop::LanguageMenu</name>
    <message>
        <location filename="../ui/i18n/LanguageMenu.cpp" line="10"/>
        <source>&amp;Language</source>
        <translation>言語(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/i18n/LanguageMenu.cpp" line="16"/>
        <source>System language (%1)</source>
        <translation>システムの言語 (%1)</translation>
    </message>
</context>
<context>
    <name>opentop::LimitCheck</name>
    <message>
        <location filename="../model/eol/LimitCheck.cpp" line="35"/>
        <source>%1 could not be read</source>
        <translation>%1 を読み出せませんでした</translation>
    </message>
    <message>
        <location filename="../model/eol/LimitCheck.cpp" line="50"/>
        <source>%1 %2 %3, %4</source>
        <translation>%1 %2 %3、%4</translation>
    </message>
    <message>
        <location filename="../model/eol/LimitCheck.cpp" line="73"/>
        <source>allowed %1–%2 %3</source>
        <translation>許容 %1–%2 %3</translation>
    </message>
    <message>
        <location filename="../model/eol/LimitCheck.cpp" line="75"/>
        <source>allowed at most %1 %2</source>
        <translation>許容 最大 %1 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/LimitCheck.cpp" line="77"/>
        <source>allowed at least %1 %2</source>
        <translation>許容 最小 %1 %2</translation>
    </message>
</context>
<context>
    <name>opentop::LineFormat</name>
    <message>
        <location filename="../transport/LineFormat.cpp" line="37"/>
        <source>Baud rate %1 is not supported: use 1200–115200.</source>
        <translation>ボーレート %1 は使用できません。1200–115200 を使ってください。</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="39"/>
        <source>Parity &apos;%1&apos; is not supported: use N (none), E (even) or O (odd).</source>
        <translation>パリティ「%1」は使用できません。N（なし）、E（偶数）、O（奇数）を使ってください。</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="42"/>
        <source>%1 data bits are not supported: use 7 or 8.</source>
        <translation>データビット %1 は使用できません。7 または 8 を使ってください。</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="44"/>
        <source>%1 stop bits are not supported: use 1 or 2.</source>
        <translation>ストップビット %1 は使用できません。1 または 2 を使ってください。</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="66"/>
        <source>&quot;%1&quot; is not a line format: write DATA BITS, PARITY and STOP BITS as 8N1, 8E1, 8O1 or 8N2, with the baud rate before it if it differs from the port&apos;s (9600:8E1)</source>
        <translation>&quot;%1&quot; は通信フォーマットではありません。データビット、パリティ、ストップビットを 8N1、8E1、8O1、8N2 のように書き、ボーレートがポートと異なる場合はその前に書いてください（9600:8E1）</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="81"/>
        <source>&quot;%1&quot;: %2</source>
        <translation>&quot;%1&quot;: %2</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="98"/>
        <source>&quot;%1&quot;: write MACHINE NUMBER=FORMAT, e.g. 7=9600:8E1 or 7=8N2 (machine numbers 1–247)</source>
        <translation>&quot;%1&quot;: 局番=形式 と書いてください。例: 7=9600:8E1 または 7=8N2（局番 1–247）</translation>
    </message>
    <message>
        <location filename="../transport/LineFormat.cpp" line="107"/>
        <source>machine number %1: %2</source>
        <translation>局番 %1: %2</translation>
    </message>
</context>
<context>
    <name>opentop::LineFormatHint</name>
    <message>
        <location filename="../model/bus/LineFormatHint.cpp" line="72"/>
        <source>%1: %2 from the factory (it can be set to %3).</source>
        <translation>%1: 工場出荷時 %2（%3 に設定可能）。</translation>
    </message>
    <message>
        <location filename="../model/bus/LineFormatHint.cpp" line="77"/>
        <source>Drives set to another line format than %1 do not answer it. %2</source>
        <translation>%1 以外の通信フォーマットに設定されたドライブは応答しません。%2</translation>
    </message>
</context>
<context>
    <name>opentop::LinkLoss</name>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="31"/>
        <source>Machine number %1 (%2): state never read</source>
        <translation>局番 %1 (%2): 状態を一度も読み出していません</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="46"/>
        <source>The connection to %1 was lost at %2.</source>
        <translation>%1 との接続が %2 に切れました。</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="54"/>
        <source>• %1 — last answer %2 (%3 when the link dropped)</source>
        <translation>• %1 — 最終応答 %2（接続が切れた時点で %3）</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="61"/>
        <source>By the last values read, no drive was running or in communication priority.</source>
        <translation>最後に読み出した値では、運転中または通信優先のドライバはありませんでした。</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="62"/>
        <source>When the link dropped, by the last values read:</source>
        <translation>接続が切れた時点で、最後に読み出した値では:</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="70"/>
        <source>OpenTOP cannot stop these drives or give control back to their inputs until the link is back: nothing is sent over a lost link. A drive in communication priority keeps its last command. Check on the machine: each drive&apos;s own STOP input, the emergency stop, and the drives&apos; power.</source>
        <translation>接続が戻るまで、OpenTOP はこれらのドライバを停止することも、入力端子に制御を戻すこともできません: 切れた接続には何も送信しません。通信優先のドライバは最後の指令を保持します。機械側で確認してください: 各ドライバ自身の停止入力端子、非常停止、ドライバの電源。</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="78"/>
        <source>Before you %1: the connection to %2 was lost at %3, and OpenTOP cannot reach these drives.</source>
        <translation>%1の前に: %2 との接続が %3 に切れたため、OpenTOP はこれらのドライバにアクセスできません。</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="96"/>
        <source>Running when it dropped, by the last values read: machine number %1.</source>
        <translation>切れた時点で最後に読み出した値では運転中: 局番 %1。</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="99"/>
        <source>In communication priority: machine number %1.</source>
        <translation>通信優先: 局番 %1。</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/run/LinkLoss.cpp" line="102"/>
        <source>%n drive(s) never read.</source>
        <translation>
            <numerusform>一度も読み出していないドライバ %n 台。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="104"/>
        <source>OpenTOP cannot stop them until the link is back: check each drive&apos;s STOP input, the emergency stop and the power on the machine.</source>
        <translation>接続が戻るまで OpenTOP はこれらを停止できません: 機械側で各ドライバの停止入力端子、非常停止、電源を確認してください。</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="118"/>
        <source>Machine number %1 (%2): no answer, its state is not known</source>
        <translation>局番 %1 (%2): 応答なし、状態不明</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="126"/>
        <source>Every drive read again: none is running or in communication priority.</source>
        <translation>すべてのドライバを読み出し直しました: 運転中または通信優先のドライバはありません。</translation>
    </message>
    <message>
        <location filename="../model/run/LinkLoss.cpp" line="127"/>
        <source>Read again just now:</source>
        <translation>今読み出し直した結果:</translation>
    </message>
</context>
<context>
    <name>opentop::MainMenus</name>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="35"/>
        <source>&amp;Bus</source>
        <translation>バス(&amp;B)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="36"/>
        <source>Main</source>
        <translation>メイン</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="39"/>
        <source>&amp;Connect…</source>
        <translation>接続(&amp;C)…</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="41"/>
        <source>Choose the serial port, gateway or simulated bus (Ctrl+K)</source>
        <translation>シリアルポート、ゲートウェイ、シミュレーションバスを選択します (Ctrl+K)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="45"/>
        <source>&amp;Scan bus</source>
        <translation>バスをスキャン(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="51"/>
        <source>&amp;Disconnect</source>
        <translation>切断(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="57"/>
        <source>Communication &amp;groups…</source>
        <translation>通信グループ(&amp;G)…</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="62"/>
        <source>&amp;Export alarm histories…</source>
        <translation>アラーム履歴をエクスポート(&amp;E)…</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="64"/>
        <source>&amp;Quit</source>
        <translation>終了(&amp;Q)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="67"/>
        <source>&amp;Files</source>
        <translation>ファイル(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="72"/>
        <source>&amp;Drive</source>
        <translation>ドライバ(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="75"/>
        <source>&amp;Write all pending</source>
        <translation>未書込みをすべて書込み(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="77"/>
        <source>&amp;Re-read all</source>
        <translation>すべて再読出し(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="79"/>
        <source>Write a setting to the selected drives…</source>
        <translation>選択したドライバに設定を書込み…</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="85"/>
        <source>&amp;Next page</source>
        <translation>次のページ(&amp;N)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="91"/>
        <source>&amp;Previous page</source>
        <translation>前のページ(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="107"/>
        <source>&amp;View</source>
        <translation>表示(&amp;V)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="113"/>
        <source>&amp;Traffic log</source>
        <translation>通信ログ(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="114"/>
        <source>Bus &amp;overview</source>
        <translation>バス一覧(&amp;O)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="116"/>
        <source>T&amp;rends</source>
        <translation>トレンド(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="117"/>
        <source>Communication &amp;groups</source>
        <translation>通信グループ(&amp;G)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="130"/>
        <source>Language</source>
        <translation>言語</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="131"/>
        <source>OpenTOP will be in %1 the next time it starts.</source>
        <translation>OpenTOP は次回の起動時から %1 で表示されます。</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="137"/>
        <source>&amp;End of line</source>
        <translation>出荷検査(&amp;E)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="139"/>
        <source>&amp;Help</source>
        <translation>ヘルプ(&amp;H)</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="155"/>
        <source>connect elsewhere</source>
        <translation>別の接続先への接続</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="165"/>
        <source>Export alarm histories</source>
        <translation>アラーム履歴のエクスポート</translation>
    </message>
    <message>
        <location filename="../ui/main/MainMenus.cpp" line="166"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV ファイル (*.csv)</translation>
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
        <translation>別の接続先への接続</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="141"/>
        <source>Connecting to %1… (still connected to %2)</source>
        <translation>%1 に接続中…（%2 には接続したまま）</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="158"/>
        <source>Connected: %1 (the new connection failed: %2)</source>
        <translation>接続済み: %1（新しい接続は失敗しました: %2）</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="161"/>
        <location filename="../ui/main/MainWindow.cpp" line="175"/>
        <source>Cannot connect</source>
        <translation>接続できません</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="162"/>
        <source>%1

Still connected to %2; nothing was changed.</source>
        <translation>%1

%2 に接続したままです。何も変更していません。</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="165"/>
        <location filename="../ui/main/MainWindow.cpp" line="242"/>
        <source>Not connected: %1</source>
        <translation>未接続: %1</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="217"/>
        <location filename="../ui/main/MainWindow.cpp" line="219"/>
        <source>Connection lost: %1</source>
        <translation>接続が切れました: %1</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="224"/>
        <source>OpenTOP — SIMULATED BUS (no hardware) — %1</source>
        <translation>OpenTOP — シミュレーションバス（ハードウェアなし）— %1</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="225"/>
        <source>OpenTOP — %1</source>
        <translation>OpenTOP — %1</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="226"/>
        <source>Connecting to %1…</source>
        <translation>%1 に接続中…</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="241"/>
        <source>Connected: %1</source>
        <translation>接続済み: %1</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="248"/>
        <source>Connected: %1 (simulated, no hardware)</source>
        <translation>接続済み: %1（シミュレーション、ハードウェアなし）</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="276"/>
        <source>The drive does not report its variant; %1 is the configured one.</source>
        <translation>ドライバが機種を通知しません。%1 は設定された機種です。</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="293"/>
        <location filename="../ui/main/MainWindow.cpp" line="303"/>
        <source>disconnect</source>
        <translation>切断</translation>
    </message>
    <message>
        <location filename="../ui/main/MainWindow.cpp" line="300"/>
        <source>Not connected (disconnected)</source>
        <translation>未接続（切断済み）</translation>
    </message>
</context>
<context>
    <name>opentop::MissingValues</name>
    <message>
        <location filename="../model/session/MissingValues.cpp" line="18"/>
        <source>cannot check the value: reading %1 failed: %2</source>
        <translation>値をチェックできません: %1 の読出しに失敗しました: %2</translation>
    </message>
    <message>
        <location filename="../model/session/MissingValues.cpp" line="41"/>
        <source>reading %1 failed: %2</source>
        <translation>%1 の読出しに失敗しました: %2</translation>
    </message>
</context>
<context>
    <name>opentop::MonitorCommand</name>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="47"/>
        <source>Watch speed, load, state, inputs and alarms live (Ctrl-C ends)</source>
        <translation>速度、負荷、状態、入力、アラームをライブで監視します（Ctrl-C で終了）</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="54"/>
        <source>Time between samples of a drive in ms, %1–%2 (default 500).</source>
        <translation>ドライバのサンプリング間隔 (ms)、%1–%2（既定 500）。</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="57"/>
        <source>MS</source>
        <translation>MS</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="58"/>
        <source>Stop after N samples per drive (default: until Ctrl-C).</source>
        <translation>ドライバあたり N サンプル後に停止します（既定: Ctrl-C まで）。</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="59"/>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="61"/>
        <source>Also write every sample to FILE (CSV with a header; a row with a note where the link was lost and where it came back).</source>
        <translation>全サンプルを FILE にも書き込みます（ヘッダ付き CSV。接続が切れた所と戻った所に注記の行）。</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="63"/>
        <source>FILE</source>
        <translation>FILE</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="65"/>
        <source>When the link to the bus is lost, exit 1 if it is not back within SECONDS (default: reconnect by itself, 0.5 s to 5 s apart, until Ctrl-C).</source>
        <translation>バスへの接続が切れたとき、SECONDS 秒以内に戻らなければ 1 で終了します（既定: Ctrl-C まで 0.5 秒〜5 秒間隔で自動再接続）。</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="67"/>
        <source>SECONDS</source>
        <translation>SECONDS</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="79"/>
        <source>error: usage: %1</source>
        <translation>エラー: 使い方: %1</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="89"/>
        <source>error: --interval must be %1–%2 ms, got &quot;%3&quot;</source>
        <translation>エラー: --interval は %1–%2 ms でなければなりません（指定値 &quot;%3&quot;）</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="102"/>
        <source>error: --count must be a whole number of samples, 1 or more, got &quot;%1&quot;</source>
        <translation>エラー: --count はサンプル数（1 以上の整数）でなければなりません（指定値 &quot;%1&quot;）</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="113"/>
        <source>error: --give-up must be a number of seconds, more than 0 and at most %1, got &quot;%2&quot;</source>
        <translation>エラー: --give-up は 0 より大きく %1 以下の秒数にしてください（指定値「%2」）</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="125"/>
        <source>error: cannot write %1: %2</source>
        <translation>エラー: %1 に書き込めません: %2</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="134"/>
        <source>error: %1</source>
        <translation>エラー: %1</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="154"/>
        <source>warning: machine number %1: %2; speeds are shown in r/min only</source>
        <translation>警告: 局番 %1: %2。速度は r/min でのみ表示します</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="194"/>
        <source>error: cannot write %1: %2; monitoring stopped</source>
        <translation>エラー: %1 に書き込めません: %2。モニタを停止しました</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="233"/>
        <source>%1 link lost: %2 (%3); reconnecting for up to %4 s (Ctrl-C ends)</source>
        <translation>%1 接続断: %2（%3）。最大 %4 秒間再接続を試みます（Ctrl-C で終了）</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="237"/>
        <source>%1 link lost: %2 (%3); reconnecting until it is back (Ctrl-C ends)</source>
        <translation>%1 接続断: %2（%3）。戻るまで再接続を試みます（Ctrl-C で終了）</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="246"/>
        <source>%1 link back after %2 s: %3; monitoring goes on</source>
        <translation>%1 %2 秒後に接続が戻りました: %3。モニタを続けます</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="261"/>
        <source>error: the link to %1 was lost at %2 and is not back after %3 s (--give-up %4): %5; monitoring stopped</source>
        <translation>エラー: %1 への接続が %2 に切れ、%3 秒後も戻りません（--give-up %4）: %5。モニタを停止しました</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCommand.cpp" line="303"/>
        <source>%1 error: %2</source>
        <translation>%1 エラー: %2</translation>
    </message>
</context>
<context>
    <name>opentop::MonitorCsv</name>
    <message>
        <location filename="../cli/MonitorCsv.cpp" line="33"/>
        <source>link lost</source>
        <translation>接続断</translation>
    </message>
    <message>
        <location filename="../cli/MonitorCsv.cpp" line="38"/>
        <source>link back</source>
        <translation>接続復帰</translation>
    </message>
</context>
<context>
    <name>opentop::MonitorDetails</name>
    <message>
        <location filename="../ui/monitor/MonitorDetails.cpp" line="81"/>
        <location filename="../ui/monitor/MonitorDetails.cpp" line="88"/>
        <source>not read</source>
        <translation>未読出し</translation>
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
        <translation>目標（表示値）</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="118"/>
        <source>Speed shown</source>
        <translation>速度（表示値）</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="128"/>
        <source>Active alarm</source>
        <translation>発生中のアラーム</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="170"/>
        <source>none</source>
        <translation>なし</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="173"/>
        <source>code %1</source>
        <translation>コード %1</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="173"/>
        <source>active</source>
        <translation>発生中</translation>
    </message>
    <message>
        <location filename="../cli/MonitorOutput.cpp" line="180"/>
        <source>Time</source>
        <translation>時刻</translation>
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
        <translation>ライブ値</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="199"/>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="215"/>
        <source>State</source>
        <translation>状態</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="280"/>
        <source>%1 %2 on the drive&apos;s display</source>
        <translation>%1 %2（ドライバの表示）</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="289"/>
        <source>Alarm %1 %2 — %3</source>
        <translation>アラーム %1 %2 — %3</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="292"/>
        <source>Alarm active (reading which one…)</source>
        <translation>アラーム発生中（内容を読出し中…）</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPage.cpp" line="347"/>
        <source>No live state: %1</source>
        <translation>ライブ状態なし: %1</translation>
    </message>
</context>
<context>
    <name>opentop::MonitorPollBar</name>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="30"/>
        <source>Poll every</source>
        <translation>ポーリング周期</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="32"/>
        <source>%1 ms (%2 Hz)</source>
        <translation>%1 ms (%2 Hz)</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="33"/>
        <source>How often every monitored drive is read. Commands you give always go first; the drives share what is left of the bus in turn.</source>
        <translation>モニタ中の各ドライバを読み出す頻度。操作したコマンドは常に優先され、各ドライバはバスの残りの帯域を順番に使用します。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="45"/>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="53"/>
        <source>Resume polling</source>
        <translation>ポーリングを再開</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="53"/>
        <source>Pause polling</source>
        <translation>ポーリングを一時停止</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="67"/>
        <source>Polling paused: the values shown are the last ones read (%1).</source>
        <translation>ポーリング一時停止中: 表示値は最後に読み出した値です (%1)。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="69"/>
        <source>Polling waits for the bus scan: %1.</source>
        <translation>ポーリングはバススキャンの終了待ち: %1。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="71"/>
        <source>Connection lost — not live: %1.</source>
        <translation>接続断 — 更新停止: %1。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="73"/>
        <source>Not live: %1.</source>
        <translation>更新停止: %1。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="74"/>
        <source>The drive does not answer (%1) — not live: %2.</source>
        <translation>ドライバが応答しません (%1) — 更新停止: %2。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="77"/>
        <source>Values %1 · %2 samples/s</source>
        <translation>値 %1 · %2 サンプル/s</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="81"/>
        <source>Not read yet.</source>
        <translation>未読出しです。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MonitorPollBar.cpp" line="82"/>
        <source>Cannot read the drive: %1</source>
        <translation>ドライバを読み出せません: %1</translation>
    </message>
</context>
<context>
    <name>opentop::MotionPriorityBox</name>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="34"/>
        <source>Switch to communication priority…</source>
        <translation>通信優先に切替え…</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="59"/>
        <source>Machine number %1 is in &quot;%2&quot; (%3): it takes run, stop, direction and speed selection from its input terminals and refuses motion commands over the bus, so the test run is disabled.

Switching to &quot;%4&quot; hands these commands to the bus: the input terminals no longer start or stop the motor, and the machine&apos;s own controls stay without effect until you switch back to &quot;%2&quot;.</source>
        <translation>局番 %1 は「%2」(%3) です: 運転、停止、回転方向、速度選択を入力端子から受け付け、バス経由の運転コマンドを拒否するため、試運転は無効です。

「%4」に切り替えると、これらのコマンドはバスから受け付けるようになります: 入力端子ではモータを起動・停止できなくなり、「%2」に戻すまで機械側の操作は無効になります。</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="85"/>
        <source>Switch to communication priority</source>
        <translation>通信優先に切替え</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="86"/>
        <source>Machine number %1 will take run, stop, direction and speed selection from the bus (%2 = &quot;%3&quot;). Its input terminals then no longer start or stop the motor.</source>
        <translation>局番 %1 は運転、停止、回転方向、速度選択をバスから受け付けるようになります (%2 = &quot;%3&quot;)。入力端子ではモータを起動・停止できなくなります。</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="92"/>
        <source>Switch</source>
        <translation>切替え</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="101"/>
        <source>Switching to communication priority…</source>
        <translation>通信優先に切替え中…</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="109"/>
        <source>Machine number %1 takes motion commands over the bus now.</source>
        <translation>局番 %1 はバス経由で運転コマンドを受け付けるようになりました。</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="111"/>
        <source>Cannot switch the control priority: %1</source>
        <translation>制御優先を切り替えられません: %1</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="121"/>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="127"/>
        <source>Return to I/O priority</source>
        <translation>I/O 優先に戻す</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="122"/>
        <source>Machine number %1 will take run, stop, direction and speed selection from its input terminals again, and refuse motion commands over the bus. If an input says run, the motor runs.</source>
        <translation>局番 %1 は再び運転、停止、回転方向、速度選択を入力端子から受け付け、バス経由の運転コマンドを拒否します。入力が運転状態の場合、モータは運転します。</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="130"/>
        <source>Returning to I/O priority…</source>
        <translation>I/O 優先に戻し中…</translation>
    </message>
    <message>
        <location filename="../ui/run/MotionPriorityBox.cpp" line="139"/>
        <source>Machine number %1 follows its input terminals again.</source>
        <translation>局番 %1 は再び入力端子に従います。</translation>
    </message>
</context>
<context>
    <name>opentop::MotorSpeedBox</name>
    <message>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="23"/>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="49"/>
        <source>Motor speed</source>
        <translation>モータ速度</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="33"/>
        <source>not set</source>
        <translation>未設定</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="34"/>
        <source>Commutations per motor revolution (a motor property, see its data sheet). r/min = %1 ÷ this × 60.</source>
        <translation>モータ 1 回転あたりの転流回数（モータ固有値。データシートを参照）。r/min = %1 ÷ この値 × 60。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="38"/>
        <source>Commutations per revolution</source>
        <translation>1 回転あたりの転流回数</translation>
    </message>
    <message>
        <location filename="../ui/monitor/MotorSpeedBox.cpp" line="79"/>
        <source>set the commutations per revolution</source>
        <translation>1 回転あたりの転流回数を設定してください</translation>
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
        <translation>すべてに書込み(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="41"/>
        <source>Write one setting to several drives</source>
        <translation>1 つの設定を複数のドライバに書込み</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="58"/>
        <source>Machine number</source>
        <translation>局番</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="58"/>
        <source>Model</source>
        <translation>型式</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="58"/>
        <source>Current value</source>
        <translation>現在値</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="59"/>
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="77"/>
        <source>Not written: another family (%1)</source>
        <translation>未書込み: 別ファミリ (%1)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="78"/>
        <source>Not written: not identified (%1)</source>
        <translation>未書込み: 未識別 (%1)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="83"/>
        <source>&amp;Setting:</source>
        <translation>設定(&amp;S):</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="89"/>
        <source>New &amp;value:</source>
        <translation>新しい値(&amp;V):</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="162"/>
        <source>cannot be read</source>
        <translation>読出し不可</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="165"/>
        <source>reading…</source>
        <translation>読出し中…</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="193"/>
        <source>read failed: %1</source>
        <translation>読出し失敗: %1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="218"/>
        <source>Drive %1: %2 is not known yet, and the allowed values depend on it.</source>
        <translation>ドライバ %1: %2 がまだ不明で、許容値はそれに依存します。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="222"/>
        <source>drive %1: %2</source>
        <translation>ドライバ %1: %2</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="228"/>
        <source>The unit differs between the drives (%1); write them one at a time.</source>
        <translation>ドライバ間で単位が異なります (%1)。1 台ずつ書き込んでください。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="237"/>
        <source>Not allowed on drive %1 (%2): %3</source>
        <translation>ドライバ %1 では許可されていません (%2): %3</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="244"/>
        <source>Not allowed on the communication group of drive %1: %2</source>
        <translation>ドライバ %1 の通信グループでは許可されていません: %2</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="249"/>
        <source>None of the selected drives is identified.</source>
        <translation>選択したドライバはいずれも識別されていません。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="263"/>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="315"/>
        <source>Drive %1: %2</source>
        <translation>ドライバ %1: %2</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="266"/>
        <source>Allowed on %1</source>
        <translation>%1 で許可</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="274"/>
        <source>Warning: %1</source>
        <translation>警告: %1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="275"/>
        <source>Allowed on %1.</source>
        <translation>%1 で許可。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="323"/>
        <source>Set it on %n drive(s) anyway?</source>
        <translation>
            <numerusform>それでも %n 台のドライバに設定しますか？</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="324"/>
        <source>&amp;Set it</source>
        <translation>設定する(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="344"/>
        <source>Write %1 to machine number(s) %2</source>
        <translation>%1 を局番 %2 に書込み</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="346"/>
        <source>Nothing was written.</source>
        <translation>何も書き込んでいません。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="351"/>
        <source>waiting…</source>
        <translation>待機中…</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="353"/>
        <source>Writing %1 to %n drive(s)…</source>
        <translation>
            <numerusform>%1 を %n 台のドライバに書込み中…</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="365"/>
        <source>Written and verified on %1 of %n drive(s).</source>
        <translation>
            <numerusform>%n 台中 %1 台のドライバで書込み・照合完了。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="374"/>
        <source>writing…</source>
        <translation>書込み中…</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="391"/>
        <source>Written and verified</source>
        <translation>書込み・照合済み</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="393"/>
        <source>Written, not verified: %1</source>
        <translation>書込み済み、未確認: %1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="394"/>
        <source>Written, not verified (cannot be read back)</source>
        <translation>書込み済み、未照合（読み戻し不可）</translation>
    </message>
    <message>
        <location filename="../ui/workspace/MultiDriveWriteDialog.cpp" line="395"/>
        <source>Failed: %1</source>
        <translation>失敗: %1</translation>
    </message>
</context>
<context>
    <name>opentop::NameCommand</name>
    <message>
        <location filename="../cli/NameCommand.cpp" line="39"/>
        <source>Name a machine (&quot;Infeed conveyor 3&quot;) or show the names of the bus</source>
        <translation>機械に名前を付ける (「Infeed conveyor 3」)、またはバスの名前を表示</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="45"/>
        <source>error: name takes a machine number and one name; put a name with spaces in quotes: name 1 &quot;Infeed conveyor 3&quot;</source>
        <translation>エラー：name には局番と名前を 1 つずつ指定します。空白を含む名前は引用符で囲んでください：name 1 &quot;Infeed conveyor 3&quot;</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="53"/>
        <source>error: %1</source>
        <translation>エラー：%1</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="63"/>
        <source>No machine of this bus has a name yet; give one with: name ID &quot;TEXT&quot;</source>
        <translation>このバスの機械にはまだ名前がありません。次のように付けます：name ID &quot;TEXT&quot;</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="67"/>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="67"/>
        <source>name</source>
        <translation>名前</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="78"/>
        <source>error: &quot;%1&quot; is not a machine number 1–247</source>
        <translation>エラー：「%1」は 1–247 の局番ではありません</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="88"/>
        <source>Machine number %1 has no name.</source>
        <translation>局番 %1 には名前がありません。</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="94"/>
        <source>error: %1 Nothing was changed.</source>
        <translation>エラー：%1 何も変更していません。</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="107"/>
        <source>Machine number %1 has no name now.</source>
        <translation>局番 %1 の名前は削除されました。</translation>
    </message>
    <message>
        <location filename="../cli/NameCommand.cpp" line="108"/>
        <source>%1 is named now; messages, files and scans show it.</source>
        <translation>%1 に名前を付けました。メッセージ、ファイル、スキャンに表示されます。</translation>
    </message>
</context>
<context>
    <name>opentop::OutputFile</name>
    <message>
        <location filename="../model/io/OutputFile.cpp" line="24"/>
        <source>cannot write %1: it is a directory; name a file</source>
        <translation>%1 に書き込めません: ディレクトリです。ファイルを指定してください</translation>
    </message>
    <message>
        <location filename="../model/io/OutputFile.cpp" line="26"/>
        <source>cannot write %1: the folder %2 does not exist</source>
        <translation>%1 に書き込めません: フォルダ %2 が存在しません</translation>
    </message>
    <message>
        <location filename="../model/io/OutputFile.cpp" line="35"/>
        <source>cannot write %1: %2</source>
        <translation>%1 に書き込めません: %2</translation>
    </message>
    <message>
        <location filename="../model/io/OutputFile.cpp" line="40"/>
        <source>it is a directory; name a file</source>
        <translation>ディレクトリです。ファイルを指定してください</translation>
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
        <translation>局番</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="24"/>
        <source>running data No.</source>
        <translation>運転データ番号</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="26"/>
        <source>countdown</source>
        <translation>カウントダウン</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="28"/>
        <source>load rate</source>
        <translation>負荷率</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="47"/>
        <source>Alarm %1 %2</source>
        <translation>アラーム %1 %2</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="48"/>
        <source>Alarm (code not read yet)</source>
        <translation>アラーム（コード未読出し）</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="59"/>
        <source>Current speed %1 %2</source>
        <translation>現在速度 %1 %2</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="63"/>
        <source>Current speed: no finite value in %1</source>
        <translation>現在速度: %1 に有限値がありません</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="70"/>
        <source>Current speed %1 r/min</source>
        <translation>現在速度 %1 r/min</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="70"/>
        <source>Speed not read</source>
        <translation>速度未読出し</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="76"/>
        <source>Machine number %1</source>
        <translation>局番 %1</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="83"/>
        <source>Running data SPno%1</source>
        <translation>運転データ SPno%1</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="86"/>
        <source>Running data not read</source>
        <translation>運転データ未読出し</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="96"/>
        <source>Countdown set to %1 d %2 h %3 min %4 s (the drive does not report the time left)</source>
        <translation>カウントダウン設定 %1 d %2 h %3 min %4 s（ドライバは残り時間を通知しません）</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="110"/>
        <source>Load rate %1 %</source>
        <translation>負荷率 %1 %</translation>
    </message>
    <message>
        <location filename="../model/monitor/PanelMirror.cpp" line="113"/>
        <source>Load rate not read</source>
        <translation>負荷率未読出し</translation>
    </message>
</context>
<context>
    <name>opentop::PanelMirrorView</name>
    <message>
        <location filename="../ui/monitor/PanelMirrorView.cpp" line="21"/>
        <source>Drive panel</source>
        <translation>ドライバパネル</translation>
    </message>
    <message>
        <location filename="../ui/monitor/PanelMirrorView.cpp" line="51"/>
        <source>Not read yet</source>
        <translation>未読出し</translation>
    </message>
    <message>
        <location filename="../ui/monitor/PanelMirrorView.cpp" line="64"/>
        <source>%1 (more digits than the panel has)</source>
        <translation>%1（パネルの桁数を超えています）</translation>
    </message>
    <message>
        <location filename="../ui/monitor/PanelMirrorView.cpp" line="68"/>
        <source>Panel set to show the %1 while running.</source>
        <translation>運転中はパネルに%1を表示する設定です。</translation>
    </message>
    <message>
        <location filename="../ui/monitor/PanelMirrorView.cpp" line="69"/>
        <source>Drive panel shows %1</source>
        <translation>ドライバパネル表示: %1</translation>
    </message>
    <message>
        <location filename="../ui/monitor/PanelMirrorView.cpp" line="80"/>
        <source>not live</source>
        <translation>更新停止</translation>
    </message>
</context>
<context>
    <name>opentop::ParameterField</name>
    <message>
        <location filename="../ui/workspace/ParameterField.cpp" line="217"/>
        <source>%1 (not valid now)</source>
        <translation>%1（現在は無効）</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterField.cpp" line="246"/>
        <source>not read</source>
        <translation>未読出し</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterField.cpp" line="255"/>
        <source>Allowed: %1</source>
        <translation>許容: %1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterField.cpp" line="258"/>
        <source>On the drive: %1</source>
        <translation>ドライバの値: %1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterField.cpp" line="289"/>
        <source>Not accepted: %1</source>
        <translation>受け付けられません: %1</translation>
    </message>
</context>
<context>
    <name>opentop::ParameterInitBox</name>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="40"/>
        <source>Parameter initialisation</source>
        <translation>パラメータ初期化</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="50"/>
        <source>Returns every setting of drive %1 to its factory default, including the communication settings: afterwards the drive may answer only at the default rate, and control priority goes back to its input terminals. The motor must be stopped. The consequences for this drive are listed before anything is sent.</source>
        <translation>ドライバ %1 の全設定を、通信設定も含めて工場出荷時設定に戻します: その後、ドライバは初期値の通信速度でしか応答しない場合があり、制御優先は入力端子側に戻ります。モータは停止している必要があります。送信前に、このドライバへの影響を一覧表示します。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="58"/>
        <source>&amp;Initialise all parameters of drive %1…</source>
        <translation>ドライバ %1 の全パラメータを初期化(&amp;I)…</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="60"/>
        <source>Asks first, naming the drive and what changes</source>
        <translation>ドライバと変更内容を示して事前に確認します</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="88"/>
        <source>Reading what the initialisation would change…</source>
        <translation>初期化による変更内容を読出し中…</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="112"/>
        <source>Afterwards:</source>
        <translation>その後:</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="117"/>
        <source>Your %n unwritten edit(s) of this drive are discarded.</source>
        <translation>
            <numerusform>このドライバの未書込みの編集 %n 件は破棄されます。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="123"/>
        <source>Sent: %1 to machine %2 only.</source>
        <translation>送信済み: %1（局番 %2 のみ）。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="124"/>
        <source>Sent: %1 to machine %2.</source>
        <translation>送信済み: %1（局番 %2）。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="128"/>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="133"/>
        <source>Initialise drive %1</source>
        <translation>ドライバ %1 の初期化</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="129"/>
        <source>Reset every setting of %1 to its factory defaults?</source>
        <translation>%1 のすべての設定を工場出荷時の値に戻しますか？</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="143"/>
        <source>Cancelled; nothing was sent.</source>
        <translation>キャンセルしました。何も送信していません。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="151"/>
        <source>Initialising drive %1…</source>
        <translation>ドライバ %1 を初期化中…</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="160"/>
        <source>Drive %1 did not confirm the initialisation: %2</source>
        <translation>ドライバ %1 が初期化を確認しませんでした: %2</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="161"/>
        <source>Nothing was sent: %1</source>
        <translation>何も送信していません: %1</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="174"/>
        <source>&amp;Reconnect at %1 bit/s after the power-up</source>
        <translation>電源投入後に %1 bit/s で再接続(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="178"/>
        <source>Drive %1 initialised; reading its values again…</source>
        <translation>ドライバ %1 を初期化しました。値を再読出し中…</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="184"/>
        <source>Drive %1 initialised; %n value(s) could not be read back (it may answer only at the default communication settings now).</source>
        <translation>
            <numerusform>ドライバ %1 を初期化しました。%n 個の値を読み戻せませんでした（現在は初期値の通信設定でのみ応答する可能性があります）。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="188"/>
        <source>Drive %1 initialised to its factory defaults; values read again.</source>
        <translation>ドライバ %1 を工場出荷時設定に初期化しました。値を再読出ししました。</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="214"/>
        <source>Reconnecting at %1 bit/s in %2 s…</source>
        <translation>%2 s 後に %1 bit/s で再接続します…</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterInitBox.cpp" line="227"/>
        <source>Reconnect at %1 bit/s from the Bus menu.</source>
        <translation>「バス」メニューから %1 bit/s で再接続してください。</translation>
    </message>
</context>
<context>
    <name>opentop::ParameterInitialiser</name>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="65"/>
        <source>%1 drives have no parameter initialisation.</source>
        <translation>%1 ドライバにはパラメータ初期化がありません。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="68"/>
        <source>%1 = %2 (register %3)</source>
        <translation>%1 = %2（レジスタ %3）</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="76"/>
        <source>Drive %1 is running. Stop the motor first: parameter initialisation is only sent to a drive at standstill.</source>
        <translation>ドライバ %1 は運転中です。先にモータを停止してください: パラメータ初期化は停止中のドライバにのみ送信します。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="80"/>
        <source>Whether drive %1 is running could not be read (%2), so nothing was sent.</source>
        <translation>ドライバ %1 が運転中かどうかを読み出せなかったため (%2)、何も送信していません。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="94"/>
        <source>Every setting of drive %1 returns to its factory default: %2. Values set for this machine are lost; save a backup first to keep them.</source>
        <translation>ドライバ %1 の全設定が工場出荷時設定に戻ります: %2。この機械用に設定した値は失われます。残すには先にバックアップを保存してください。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="111"/>
        <source>%1 could not be read; it returns to %2. %3</source>
        <translation>%1 を読み出せませんでした。%2 に戻ります。%3</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="114"/>
        <source>%1 goes from %2 back to %3. %4</source>
        <translation>%1 は %2 から %3 に戻ります。%4</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="119"/>
        <source>%1 stays %2 (already the default).</source>
        <translation>%1 は %2 のままです（すでに初期値）。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="123"/>
        <source>%1 bit/s, parity %2, %3 stop bit(s)</source>
        <translation>%1 bit/s、パリティ %2、ストップビット %3</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="131"/>
        <source>The link to the drive is lost from its next power-up: it answers only at the factory line settings, %1.</source>
        <translation>次回の電源投入からドライバとの接続が失われます: ドライバは工場出荷時の通信設定 (%1) でのみ応答します。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="142"/>
        <source>To reach drive %1 again: switch it off and on, wait %2 s after power-on, then reconnect at %3.</source>
        <translation>ドライバ %1 に再び接続するには: 電源を入れ直し、電源投入後 %2 s 待ってから %3 で再接続してください。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="159"/>
        <source>Bus control is lost: the drive follows its input terminals again and refuses start, stop and speed commands over the bus; an input that is on may start the motor, with the factory input functions.</source>
        <translation>バスからの制御ができなくなります: ドライバは再び入力端子に従い、バス経由の起動・停止・速度指令を拒否します。オンになっている入力があると、工場出荷時の入力機能でモータが起動する可能性があります。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="168"/>
        <source>To control the motor over the bus again, set %1 to %2.</source>
        <translation>バス経由で再びモータを制御するには、%1 を %2 に設定してください。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="150"/>
        <source>The drive no longer follows writes sent to its group&apos;s parent, and drives that followed it no longer do.</source>
        <translation>ドライバはグループ親局宛の書込みに従わなくなり、このドライバに従っていたドライバも従わなくなります。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="173"/>
        <source>The machine number %1 is not a setting and does not change.</source>
        <translation>局番 %1 は設定ではないため変更されません。</translation>
    </message>
    <message>
        <location filename="../model/session/ParameterInitialiser.cpp" line="175"/>
        <source>The motor must stand still: drive %1 reports it stopped now, and this is read again just before the command is sent.</source>
        <translation>モータは停止している必要があります: ドライバ %1 は現在停止中と通知しています。コマンド送信の直前に再度読み出します。</translation>
    </message>
</context>
<context>
    <name>opentop::ParameterPage</name>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="26"/>
        <location filename="../ui/workspace/ParameterPage.cpp" line="149"/>
        <source>&amp;Write page</source>
        <translation>ページ書込み(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="27"/>
        <source>Re&amp;vert</source>
        <translation>元に戻す(&amp;V)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="28"/>
        <source>Re-&amp;read</source>
        <translation>再読出し(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="48"/>
        <source>Write this page&apos;s pending edits to the drive and verify them by reading back</source>
        <translation>このページの未書込みの編集をドライバに書き込み、読み戻して照合します</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="49"/>
        <source>Discard this page&apos;s pending edits</source>
        <translation>このページの未書込みの編集を破棄します</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="50"/>
        <source>Read this page&apos;s values from the drive again (edits stay)</source>
        <translation>このページの値をドライバから再読出しします（編集は保持）</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterPage.cpp" line="137"/>
        <source>Every field is accepted now. Nothing has been written yet: Write page sends %n value(s).</source>
        <translation>
            <numerusform>すべての欄が受け付けられました。まだ何も書き込んでいません：「ページを書込み」で %n 個の値を送信します。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="150"/>
        <source>&amp;Write page (%1)</source>
        <translation>ページ書込み(&amp;W) (%1)</translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="163"/>
        <source>Reading…</source>
        <translation>読出し中…</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterPage.cpp" line="167"/>
        <source>%n value(s) could not be read</source>
        <translation>
            <numerusform>%n 個の値を読み出せませんでした</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterPage.cpp" line="116"/>
        <source>Nothing was written: %n field(s) not accepted. %1</source>
        <translation>
            <numerusform>何も書き込んでいません: %n 項目が受け付けられません。%1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterPage.cpp" line="208"/>
        <source>Write %n value(s) of the page %1 to machine number %2</source>
        <translation>
            <numerusform>ページ %1 の %n 個の値を局番 %2 に書込み</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/workspace/ParameterPage.cpp" line="182"/>
        <location filename="../ui/workspace/ParameterPage.cpp" line="203"/>
        <location filename="../ui/workspace/ParameterPage.cpp" line="212"/>
        <source>Nothing was written.</source>
        <translation>何も書き込んでいません。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/workspace/ParameterPage.cpp" line="217"/>
        <source>Writing %n value(s)…</source>
        <translation>
            <numerusform>%n 個の値を書込み中…</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::ParameterReader</name>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="55"/>
        <source>entry</source>
        <translation>エントリ</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="63"/>
        <source>name must be lower-case dotted words: [a-z0-9_] separated by dots</source>
        <translation>name はドット区切りの小文字の単語でなければなりません（[a-z0-9_] をドットで区切る）</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="72"/>
        <source>&quot;label&quot; is empty</source>
        <translation>&quot;label&quot; が空です</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="74"/>
        <source>group &quot;%1&quot; is not declared in &quot;groups&quot;</source>
        <translation>グループ &quot;%1&quot; が &quot;groups&quot; で宣言されていません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="76"/>
        <source>kind must be one of %1</source>
        <translation>kind は %1 のいずれかでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="82"/>
        <source>address must be 0x0000–0xFFFF</source>
        <translation>address は 0x0000–0xFFFF でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="89"/>
        <source>read must be 3 (holding) or 4 (input)</source>
        <translation>read は 3（保持）または 4（入力）でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="91"/>
        <source>write must be 6 or 16</source>
        <translation>write は 6 または 16 でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="95"/>
        <source>input registers (read 4) cannot be written</source>
        <translation>入力レジスタ (read 4) には書き込めません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="97"/>
        <source>neither readable nor writable</source>
        <translation>読出しも書込みもできません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="105"/>
        <source>type must be u16, s16, u32, s32, f32, string or bits</source>
        <translation>type は u16、s16、u32、s32、f32、string、bits のいずれかでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="114"/>
        <source>string parameters need &quot;count&quot; 1–125 registers</source>
        <translation>string パラメータには &quot;count&quot; 1–125 レジスタが必要です</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="119"/>
        <source>bits parameters have &quot;count&quot; 1 or 2</source>
        <translation>bits パラメータの &quot;count&quot; は 1 または 2 です</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="124"/>
        <source>%1 takes %2 register(s), not %3</source>
        <translation>%1 は %3 ではなく %2 レジスタを使用します</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="129"/>
        <source>&quot;wordOrder&quot; is for 2-register numbers and bit fields only</source>
        <translation>&quot;wordOrder&quot; は 2 レジスタの数値とビットフィールド専用です</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="133"/>
        <source>&quot;wordOrder&quot; must be &quot;high-first&quot; or &quot;low-first&quot;</source>
        <translation>&quot;wordOrder&quot; は &quot;high-first&quot; または &quot;low-first&quot; でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="136"/>
        <source>a %1-register value cannot be written with function 06; use 16</source>
        <translation>%1 レジスタの値はファンクション 06 では書き込めません。16 を使用してください</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="141"/>
        <source>safety must be one of %1</source>
        <translation>safety は %1 のいずれかでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="143"/>
        <source>commands need a &quot;safety&quot; class</source>
        <translation>コマンドには &quot;safety&quot; クラスが必要です</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="146"/>
        <source>code table &quot;%1&quot; is not declared</source>
        <translation>コードテーブル &quot;%1&quot; が宣言されていません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="157"/>
        <source>a setting needs &quot;allowed&quot; or &quot;enum&quot;</source>
        <translation>設定には &quot;allowed&quot; または &quot;enum&quot; が必要です</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="160"/>
        <source>a writable parameter needs &quot;allowed&quot; or &quot;enum&quot;</source>
        <translation>書込み可能なパラメータには &quot;allowed&quot; または &quot;enum&quot; が必要です</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="165"/>
        <source>bits parameters need &quot;bits&quot;</source>
        <translation>bits パラメータには &quot;bits&quot; が必要です</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="173"/>
        <source>&quot;backup&quot; must be true or false</source>
        <translation>&quot;backup&quot; は true または false でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="178"/>
        <source>only readable and writable parameters can be backed up</source>
        <translation>バックアップできるのは読出し・書込み可能なパラメータのみです</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="191"/>
        <source>%1 needs &quot;address&quot; and &quot;count&quot;</source>
        <translation>%1 には &quot;address&quot; と &quot;count&quot; が必要です</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="193"/>
        <source>%1: the parameter is not writable</source>
        <translation>%1: このパラメータは書込みできません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="196"/>
        <source>%1: address 0x0000–0xFFFF and count 1–%2 (limits.maxWriteRegisters)</source>
        <translation>%1: address は 0x0000–0xFFFF、count は 1–%2 でなければなりません（limits.maxWriteRegisters）</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="205"/>
        <source>%1: tail values are registers, 0–65535</source>
        <translation>%1: tail の値はレジスタ値（0–65535）です</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="213"/>
        <source>%1: the parameter&apos;s registers must lie in the block, before its tail</source>
        <translation>%1: パラメータのレジスタはブロック内の tail より前になければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="221"/>
        <source>scale must be positive</source>
        <translation>scale は正の値でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="233"/>
        <source>decimals must be 0–9</source>
        <translation>decimals は 0–9 でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="257"/>
        <source>recommended[%1] is not inside one of the &quot;allowed&quot; intervals</source>
        <translation>recommended[%1] がどの &quot;allowed&quot; 区間にも含まれていません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="275"/>
        <source>default %1 is not a whole number of steps of %2</source>
        <translation>default %1 が %2 のステップの整数倍ではありません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="284"/>
        <source>default must be a number (or &quot;0x...&quot; code)</source>
        <translation>default は数値（または &quot;0x...&quot; コード）でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="287"/>
        <source>default must be a number or a string</source>
        <translation>default は数値または文字列でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="298"/>
        <source>%1 must be an object {&quot;min&quot;:…, &quot;max&quot;:…}</source>
        <translation>%1 はオブジェクト {&quot;min&quot;:…, &quot;max&quot;:…} でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="305"/>
        <source>%1 needs numeric min and max</source>
        <translation>%1 には数値の min と max が必要です</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="311"/>
        <source>%1: %2 is not a whole number of steps of %3</source>
        <translation>%1: %2 が %3 のステップの整数倍ではありません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="319"/>
        <source>%1: min is greater than max</source>
        <translation>%1: min が max より大きくなっています</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="333"/>
        <source>%1 must be an object {&quot;value&quot;:…, &quot;label&quot;:…}</source>
        <translation>%1 はオブジェクト {&quot;value&quot;:…, &quot;label&quot;:…} でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="349"/>
        <source>%1 has no label</source>
        <translation>%1 にラベルがありません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="351"/>
        <source>%1 repeats a code or label</source>
        <translation>%1 でコードまたはラベルが重複しています</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="362"/>
        <source>&quot;bits&quot; only belongs to type bits</source>
        <translation>&quot;bits&quot; は type bits にのみ使用できます</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="386"/>
        <source>%1.appliesWhen needs &quot;param&quot; and &quot;equals&quot;</source>
        <translation>%1.appliesWhen には &quot;param&quot; と &quot;equals&quot; が必要です</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="391"/>
        <source>%1 lies outside the %2-bit register</source>
        <translation>%1 が %2 ビットレジスタの範囲外です</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="393"/>
        <source>%1 needs a unique name</source>
        <translation>%1 には一意の名前が必要です</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="407"/>
        <source>%1 must be an object</source>
        <translation>%1 はオブジェクトでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="419"/>
        <source>%1 needs either &quot;variant&quot; or &quot;param&quot;</source>
        <translation>%1 には &quot;variant&quot; または &quot;param&quot; のいずれかが必要です</translation>
    </message>
    <message>
        <location filename="../model/profile/ParameterReader.cpp" line="422"/>
        <source>%1: variant &quot;%2&quot; is not declared</source>
        <translation>%1: 機種 &quot;%2&quot; が宣言されていません</translation>
    </message>
</context>
<context>
    <name>opentop::ParamsCommand</name>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="82"/>
        <source>List every parameter of the device profiles</source>
        <translation>デバイスプロファイルの全パラメータを一覧表示します</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="162"/>
        <source>error: params takes no arguments; use --family F</source>
        <translation>エラー: params は引数を取りません。--family F を使用してください</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="170"/>
        <source>error: unknown family &quot;%1&quot;; known: %2</source>
        <translation>エラー: 不明なファミリ &quot;%1&quot;。既知: %2</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="192"/>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="192"/>
        <source>Label</source>
        <translation>ラベル</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="192"/>
        <source>Address</source>
        <translation>アドレス</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="192"/>
        <source>FC</source>
        <translation>FC</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="192"/>
        <source>Type</source>
        <translation>型</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="192"/>
        <source>Unit</source>
        <translation>単位</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="193"/>
        <source>Allowed</source>
        <translation>許容値</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="193"/>
        <source>Default</source>
        <translation>初期値</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="193"/>
        <source>Access</source>
        <translation>アクセス</translation>
    </message>
    <message>
        <location filename="../cli/ParamsCommand.cpp" line="193"/>
        <source>Group</source>
        <translation>グループ</translation>
    </message>
</context>
<context>
    <name>opentop::PasswordHash</name>
    <message>
        <location filename="../model/access/PasswordHash.cpp" line="52"/>
        <source>a password needs at least %1 characters</source>
        <translation>パスワードは %1 文字以上必要です</translation>
    </message>
</context>
<context>
    <name>opentop::PidGains</name>
    <message>
        <location filename="../model/tuning/PidGains.cpp" line="9"/>
        <source>P %1, I %2, D %3, D period %4 ms</source>
        <translation>P %1、I %2、D %3、D 周期 %4 ms</translation>
    </message>
</context>
<context>
    <name>opentop::PlantModel</name>
    <message>
        <location filename="../model/tuning/PlantModel.cpp" line="18"/>
        <source>the relay test gives no usable model (K·Ku = %1, Tu = %2 ms)</source>
        <translation>リレー試験から使用できるモデルが得られません（K·Ku = %1、Tu = %2 ms）</translation>
    </message>
</context>
<context>
    <name>opentop::PortsCommand</name>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="16"/>
        <source>List serial ports and USB adapters</source>
        <translation>シリアルポートと USB アダプタを一覧表示します</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="23"/>
        <source>error: ports takes no arguments</source>
        <translation>エラー: ports は引数を取りません</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="43"/>
        <source>No serial ports found.</source>
        <translation>シリアルポートが見つかりません。</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="47"/>
        <source>Port</source>
        <translation>ポート</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="48"/>
        <source>Adapter</source>
        <translation>アダプタ</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="49"/>
        <source>Manufacturer</source>
        <translation>メーカ</translation>
    </message>
    <message>
        <location filename="../cli/PortsCommand.cpp" line="50"/>
        <source>Serial no.</source>
        <translation>シリアル番号</translation>
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
        <translation>%1 は判定の記録ファイルではありません (%2): 無視します。以前に中断した判定の値がドライバに残っている可能性があります</translation>
    </message>
    <message>
        <location filename="../model/session/ProbeJournal.cpp" line="42"/>
        <source>cannot create the folder of %1</source>
        <translation>%1 のフォルダを作成できません</translation>
    </message>
    <message>
        <location filename="../model/session/ProbeJournal.cpp" line="78"/>
        <location filename="../model/session/ProbeJournal.cpp" line="92"/>
        <source>%1 is locked by another program</source>
        <translation>%1 は別のプログラムがロックしています</translation>
    </message>
</context>
<context>
    <name>opentop::ProductionMode</name>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="39"/>
        <source>&amp;Production mode (end of line)</source>
        <translation>生産モード（出荷検査）(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="42"/>
        <source>The operator screen of an end-of-line station; no parameter editing until you switch back (Ctrl+Shift+P)</source>
        <translation>出荷検査ステーションの作業者画面。元に戻すまでパラメータは編集できません (Ctrl+Shift+P)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="45"/>
        <source>&amp;Full screen</source>
        <translation>全画面表示(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="54"/>
        <source>&amp;Station name…</source>
        <translation>ステーション名(&amp;S)…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="55"/>
        <source>The name this end-of-line station records with every unit</source>
        <translation>この出荷検査ステーションが各ユニットに記録する名前</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="64"/>
        <source>%1

No unit can be tested until results can be recorded. The station tries again by itself.</source>
        <translation>%1

結果を記録できるようになるまで、製品は試験できません。ステーションが自動で再試行します。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="83"/>
        <location filename="../ui/eol/ProductionMode.cpp" line="91"/>
        <source>Station name</source>
        <translation>ステーション名</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="84"/>
        <source>The name this station records with every unit (each station of a line needs its own):</source>
        <translation>このステーションが各ユニットに記録する名前（ラインの各ステーションにそれぞれ別の名前が必要です）:</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="92"/>
        <source>A station needs a name.</source>
        <translation>ステーションには名前が必要です。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="93"/>
        <source>A unit is being tested: change the name once it is finished.</source>
        <translation>ユニットを検査中です。完了してから名前を変更してください。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="110"/>
        <source>Production mode</source>
        <translation>生産モード</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="111"/>
        <source>A unit is being tested. Cancel it (Esc) or let it finish before switching back to engineering mode.</source>
        <translation>製品を試験中です。エンジニアリングモードに戻る前に、キャンセル (Esc) するか試験の終了を待ってください。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="63"/>
        <source>Results database</source>
        <translation>結果データベース</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="124"/>
        <source>leave production mode</source>
        <translation>生産モードを終了する</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="171"/>
        <source>A unit is being tested</source>
        <translation>製品を試験中です</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="172"/>
        <source>Unit %1 is being tested. Cancel it and %2? Its motors are stopped first; the unit is recorded as aborted.</source>
        <translation>製品 %1 を試験中です。キャンセルして「%2」を実行しますか？ 先にモータを停止し、製品は中止として記録します。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionMode.cpp" line="184"/>
        <source>cancelled to %1</source>
        <translation>「%1」のためキャンセル</translation>
    </message>
</context>
<context>
    <name>opentop::ProductionOptions</name>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="32"/>
        <source>Start in production mode (end-of-line station) with this recipe.</source>
        <translation>このレシピで生産モード（出荷検査ステーション）で起動します。</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="33"/>
        <source>RECIPE</source>
        <translation>RECIPE</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="34"/>
        <source>Per-unit values (CSV by serial number) for production mode.</source>
        <translation>生産モードの個別値（シリアル番号別 CSV）。</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="34"/>
        <source>CSV</source>
        <translation>CSV</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="36"/>
        <source>Results database for production mode: an SQLite file or postgresql://user@host/db.</source>
        <translation>生産モードの結果データベース: SQLite ファイルまたは postgresql://user@host/db。</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="37"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="39"/>
        <source>This station&apos;s name in the results (default: as set in the program, else the computer&apos;s name); not saved.</source>
        <translation>結果に記録するこのステーションの名前（既定: プログラムで設定した名前、なければコンピューター名）。保存されません。</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="41"/>
        <source>NAME</source>
        <translation>名前</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="42"/>
        <source>Start full screen.</source>
        <translation>全画面で起動します。</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="50"/>
        <source>--units, --results-db and --station go with --production RECIPE</source>
        <translation>--units、--results-db、--station は --production RECIPE と一緒に使います</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="59"/>
        <source>--station needs a name</source>
        <translation>--station には名前が必要です</translation>
    </message>
    <message>
        <location filename="../app/gui/ProductionOptions.cpp" line="64"/>
        <source>%1 cannot be run:
  %2</source>
        <translation>%1 は実行できません:
  %2</translation>
    </message>
</context>
<context>
    <name>opentop::ProductionView</name>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="56"/>
        <source>Open recipe…</source>
        <translation>レシピを開く…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="57"/>
        <source>Per-unit values…</source>
        <translation>個別値…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="63"/>
        <source>Recipe:</source>
        <translation>レシピ:</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="84"/>
        <source>Drive</source>
        <translation>ドライバ</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="84"/>
        <source>Now</source>
        <translation>実行中</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="161"/>
        <source>Unit %1: %2…</source>
        <translation>製品 %1：%2…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="195"/>
        <source>Recipe not usable</source>
        <translation>レシピを使用できません</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="196"/>
        <source>%1 cannot be run; nothing will be sent:

%2</source>
        <translation>%1 は実行できません。何も送信しません:

%2</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="217"/>
        <source>open another recipe</source>
        <translation>別のレシピを開く</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="220"/>
        <source>Open recipe</source>
        <translation>レシピを開く</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="220"/>
        <source>Recipes (*.json)</source>
        <translation>レシピ (*.json)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="228"/>
        <location filename="../ui/eol/ProductionView.cpp" line="234"/>
        <source>Per-unit values</source>
        <translation>個別値</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="229"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV ファイル (*.csv)</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/eol/ProductionView.cpp" line="242"/>
        <source>&lt;b&gt;%1&lt;/b&gt; rev. %2 — %n drive(s)</source>
        <translation>
            <numerusform>&lt;b&gt;%1&lt;/b&gt; rev. %2 — ドライバ %n 台</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="246"/>
        <source>&lt;i&gt;none: open the product&apos;s recipe&lt;/i&gt;</source>
        <translation>&lt;i&gt;なし: 製品のレシピを開いてください&lt;/i&gt;</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="247"/>
        <source>Station %1 · results: %2 · per-unit values: %3</source>
        <translation>ステーション %1 · 結果: %2 · 個別値: %3</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="250"/>
        <source>loaded</source>
        <translation>読込み済み</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="250"/>
        <source>none</source>
        <translation>なし</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="118"/>
        <source>Unit %1: making the station&apos;s drives safe first…</source>
        <translation>ユニット %1: まずステーションのドライブを安全な状態にしています…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="287"/>
        <source>drive %1</source>
        <translation>ドライバ %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="288"/>
        <source>drive %1 (%2)</source>
        <translation>ドライバ %1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="289"/>
        <source>waiting</source>
        <translation>待機中</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="294"/>
        <source>Unit %1 — attempt %2</source>
        <translation>製品 %1 — %2 回目</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="316"/>
        <source>Kept on this station: the results server did not answer. It is sent by itself when the server answers.</source>
        <translation>このステーションに保管: 結果サーバーが応答しませんでした。サーバーが応答すると自動的に送信されます。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="361"/>
        <source>%1
Recorded at %2, after the results database came back.</source>
        <translation>%1
結果データベースの復旧後、%2 に記録しました。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="161"/>
        <location filename="../ui/eol/ProductionView.cpp" line="295"/>
        <location filename="../ui/eol/ProductionView.cpp" line="314"/>
        <location filename="../ui/eol/ProductionView.cpp" line="362"/>
        <source>Unit %1</source>
        <translation>製品 %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="341"/>
        <source>Unit %1 ended %2, but its result is not in the results database: %3
Nothing is tested until it is recorded. The station tries again by itself (next try at %4); keep the unit aside.</source>
        <translation>製品 %1 は %2 で終了しましたが、結果が結果データベースに記録されていません：%3
記録されるまで試験しません。ステーションが自動で再試行します（次回 %4）。この製品は別に置いてください。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="322"/>
        <source>Motor not confirmed stopped</source>
        <translation>モータの停止が確認できません</translation>
    </message>
    <message>
        <location filename="../ui/eol/ProductionView.cpp" line="323"/>
        <source>These motors may still be turning; stop them before touching the unit:

%1</source>
        <translation>これらのモータはまだ回転している可能性があります。製品に触れる前に停止してください:

%1</translation>
    </message>
</context>
<context>
    <name>opentop::ProfileCrossCheck</name>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="49"/>
        <source>%1: storeWith &quot;%2&quot; is not a command parameter</source>
        <translation>%1: storeWith &quot;%2&quot; はコマンドパラメータではありません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="52"/>
        <source>%1: the default is not among its allowed values</source>
        <translation>%1: 初期値が許容値に含まれていません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="56"/>
        <source>%1: bit field &quot;%2&quot;: function &quot;%3&quot; is not a readable parameter</source>
        <translation>%1: ビットフィールド &quot;%2&quot;: function &quot;%3&quot; は読出し可能なパラメータではありません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="63"/>
        <source>%1: condition on unknown parameter &quot;%2&quot;</source>
        <translation>%1: 不明なパラメータ &quot;%2&quot; に対する条件です</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="65"/>
        <source>%1: the default is not allowed when %2</source>
        <translation>%1: %2 のときは初期値が許容されません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="75"/>
        <source>%1 runs past address 0xFFFF</source>
        <translation>%1 がアドレス 0xFFFF を超えています</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="78"/>
        <source>%1 overlaps &quot;%2&quot; at 0x%3 (%4 registers)</source>
        <translation>%1 が 0x%3 で &quot;%2&quot; と重なっています（%4 レジスタ）</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="107"/>
        <source>identify: &quot;%1&quot; must be a parameter inside the identify read</source>
        <translation>identify: &quot;%1&quot; は identify の読出し範囲内のパラメータでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileCrossCheck.cpp" line="110"/>
        <source>identify.nameMatch is not a valid regular expression</source>
        <translation>identify.nameMatch が正しい正規表現ではありません</translation>
    </message>
</context>
<context>
    <name>opentop::ProfileLoader</name>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="345"/>
        <source>not valid JSON at offset %1: %2</source>
        <translation>オフセット %1 で JSON が不正です: %2</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="349"/>
        <source>the top level must be a JSON object</source>
        <translation>最上位は JSON オブジェクトでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="360"/>
        <source>&quot;parameters&quot; is empty</source>
        <translation>&quot;parameters&quot; が空です</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="371"/>
        <source>must be an object</source>
        <translation>オブジェクトでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="373"/>
        <source>name repeated</source>
        <translation>名前が重複しています</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="384"/>
        <source>texts: {setting:…} names no parameter (%1)</source>
        <translation>texts: {setting:…} が指すパラメータがありません (%1)</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileLoader.cpp" line="393"/>
        <source>%1: cannot open: %2</source>
        <translation>%1: 開けません: %2</translation>
    </message>
</context>
<context>
    <name>opentop::ProfileTranslation</name>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="79"/>
        <source>%1 is larger than %2 MB, the most a profile translation may hold</source>
        <translation>%1 はプロファイル翻訳の上限 %2 MB を超えています</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="97"/>
        <source>larger than %1 MB, the most a profile translation may hold</source>
        <translation>プロファイル翻訳の上限 %1 MB を超えています</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="102"/>
        <source>not valid JSON at offset %1: %2</source>
        <translation>オフセット %1 で有効な JSON ではありません: %2</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="106"/>
        <source>the top level must be a JSON object</source>
        <translation>最上位は JSON オブジェクトでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="109"/>
        <source>&quot;format&quot; must be &quot;%1&quot;</source>
        <translation>&quot;format&quot; は &quot;%1&quot; でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="112"/>
        <source>&quot;formatVersion&quot; must be %1</source>
        <translation>&quot;formatVersion&quot; は %1 でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="118"/>
        <source>&quot;family&quot; is &quot;%1&quot;, but the profile is &quot;%2&quot;</source>
        <translation>&quot;family&quot; は &quot;%1&quot; ですが、プロファイルは &quot;%2&quot; です</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="120"/>
        <source>&quot;language&quot; is &quot;%1&quot;, expected &quot;%2&quot;</source>
        <translation>&quot;language&quot; は &quot;%1&quot; ですが、&quot;%2&quot; であるべきです</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="123"/>
        <source>&quot;texts&quot; must be an object of key → text</source>
        <translation>&quot;texts&quot; はキー → テキストのオブジェクトでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="127"/>
        <source>texts &quot;%1&quot; must be a non-empty string</source>
        <translation>texts &quot;%1&quot; は空でない文字列でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="144"/>
        <source>%1 key(s) of the profile missing: %2</source>
        <translation>プロファイルのキーが %1 個ありません: %2</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="148"/>
        <source>%1 key(s) the profile does not have: %2</source>
        <translation>プロファイルにないキーが %1 個あります: %2</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="156"/>
        <source>texts &quot;%1&quot;: the panel codes must stay as in the English (%2), found (%3)</source>
        <translation>texts &quot;%1&quot;: パネルコードは英語と同じでなければなりません (%2)。実際: (%3)</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="161"/>
        <source>texts &quot;%1&quot;: the placeholders must stay as in the English (%2), found (%3)</source>
        <translation>texts &quot;%1&quot;: プレースホルダーは英語と同じでなければなりません (%2)。実際: (%3)</translation>
    </message>
    <message>
        <location filename="../model/profile/ProfileTranslation.cpp" line="168"/>
        <source>texts &quot;%1&quot;: the settings named ({setting:…}) must stay as in the English (%2), found (%3)</source>
        <translation>texts &quot;%1&quot;: 参照する設定 ({setting:…}) は英語と同じでなければなりません (%2)。実際は (%3)</translation>
    </message>
</context>
<context>
    <name>opentop::ProposalFlow</name>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="57"/>
        <source>Proposal rejected; the drive&apos;s gains were not changed.</source>
        <translation>提案値を却下しました。ドライバのゲインは変更していません。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="60"/>
        <source>Proposal rejected</source>
        <translation>提案値を却下</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="71"/>
        <source>The accepted gains failed the check: %1. Reject them, or store them only after looking at the step.</source>
        <translation>採用したゲインは確認に不合格でした: %1。不採用にするか、ステップを確かめてから保存してください。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="85"/>
        <source>no step test ran after Accept</source>
        <translation>採用後にステップ試験を実行していません</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="87"/>
        <source>Store gains that failed the check?</source>
        <translation>確認に不合格のゲインを保存しますか?</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="88"/>
        <source>The gains accepted on %1 did not pass the check after Accept.</source>
        <translation>%1 で採用したゲインは、採用後の確認に合格しませんでした。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="90"/>
        <source>Stored, they stay after a power cycle and the motor may oscillate or overshoot as measured. Reject writes back the gains the drive had.</source>
        <translation>保存すると電源再投入後も残り、モータは測定どおり振動したりオーバーシュートしたりするおそれがあります。「不採用」でドライバの元のゲインを書き戻します。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="95"/>
        <source>Reject the gains</source>
        <translation>ゲインを不採用</translation>
    </message>
    <message>
        <location filename="../ui/tuning/ProposalFlow.cpp" line="96"/>
        <source>Store anyway</source>
        <translation>それでも保存</translation>
    </message>
</context>
<context>
    <name>opentop::PtySimServer</name>
    <message>
        <location filename="../sim/PtySimServer.cpp" line="66"/>
        <source>cannot open a pseudo-terminal: %1</source>
        <translation>疑似端末を開けません: %1</translation>
    </message>
    <message>
        <location filename="../sim/PtySimServer.cpp" line="112"/>
        <source>%1 is in use by another simulator (PID %2); stop it first, or choose another path for --pty</source>
        <translation>%1 は別のシミュレータ（PID %2）が使用中です。先にそれを停止するか、--pty に別のパスを指定してください</translation>
    </message>
    <message>
        <location filename="../sim/PtySimServer.cpp" line="121"/>
        <source>cannot create the lock file %1: %2</source>
        <translation>ロックファイル %1 を作成できません: %2</translation>
    </message>
    <message>
        <location filename="../sim/PtySimServer.cpp" line="80"/>
        <source>%1 exists and is not a symlink; refusing to replace it</source>
        <translation>%1 は既に存在し、シンボリックリンクではありません。置き換えません</translation>
    </message>
    <message>
        <location filename="../sim/PtySimServer.cpp" line="83"/>
        <source>cannot create the symlink %1 -&gt; %2</source>
        <translation>シンボリックリンク %1 -&gt; %2 を作成できません</translation>
    </message>
    <message>
        <location filename="../sim/PtySimServer.cpp" line="162"/>
        <source>the port is plugged in: %1</source>
        <translation>ポートを接続しました: %1</translation>
    </message>
    <message>
        <location filename="../sim/PtySimServer_win.cpp" line="29"/>
        <source>a simulated serial line needs a pseudo-terminal, which Windows does not have: serve Modbus TCP with --tcp PORT (e.g. --tcp 5020) and connect with --tcp 127.0.0.1:5020</source>
        <translation>模擬シリアル回線には疑似端末が必要ですが、Windows にはありません: --tcp PORT（例: --tcp 5020）で Modbus TCP を提供し、--tcp 127.0.0.1:5020 で接続してください</translation>
    </message>
</context>
<context>
    <name>opentop::ReachedDrives</name>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="47"/>
        <source>%1, variant not known</source>
        <translation>%1、機種不明</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="62"/>
        <source>machine number %1 (%2) executes this write too (communication group %3), but has no such setting at 0x%4</source>
        <translation>局番 %1（%2）もこの書込みを実行しますが（通信グループ %3）、0x%4 にその設定がありません</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="86"/>
        <source>machine number %1 (%2) executes this write too (communication group %3) and does not allow it: %4</source>
        <translation>局番 %1（%2）もこの書込みを実行しますが（通信グループ %3）、この値を許可していません: %4</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="95"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="110"/>
        <source>%1 cannot be checked: %2</source>
        <translation>%1 を確認できません: %2</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="150"/>
        <source>verification failed in communication group %1: %2</source>
        <translation>通信グループ %1 で確認に失敗しました: %2</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="209"/>
        <source>reading %1 of machine number %2, which executes this write too, failed: %3</source>
        <translation>この書込みも実行する局番 %2 の %1 の読出しに失敗しました: %3</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="245"/>
        <source>machine number %1: not verified (the setting cannot be read there)</source>
        <translation>局番 %1: 未確認（そのドライバでは設定を読み出せません）</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="258"/>
        <source>machine number %1: not verified, reading it back failed: %2</source>
        <translation>局番 %1: 未確認、読み戻しに失敗しました: %2</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="260"/>
        <source>the drive was removed</source>
        <translation>ドライバが削除されました</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="273"/>
        <source>machine number %1 holds %2</source>
        <translation>局番 %1 の値は %2</translation>
    </message>
    <message>
        <location filename="../model/session/ReachedDrives.cpp" line="274"/>
        <source>machine number %1 holds %2, not %3</source>
        <translation>局番 %1 の値は %3 ではなく %2</translation>
    </message>
</context>
<context>
    <name>opentop::Recipe</name>
    <message>
        <location filename="../model/eol/Recipe.cpp" line="64"/>
        <source>position %1 (machine number %2)</source>
        <translation>位置 %1（局番 %2）</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeApprovals</name>
    <message>
        <location filename="../model/access/RecipeApprovals.cpp" line="19"/>
        <source>recipe &quot;%1&quot; rev. %2 is a draft: this version (its checksum) is not approved, so it does not run. An engineer approves it (Approve… in the recipe editor, or opentop-cli eol recipe approve FILE --user NAME).</source>
        <translation>レシピ &quot;%1&quot; rev. %2 は下書きです: この版 (チェックサム) は承認されていないため実行されません。エンジニアが承認します (レシピエディタの「承認…」、または opentop-cli eol recipe approve FILE --user NAME)。</translation>
    </message>
    <message>
        <location filename="../model/access/RecipeApprovals.cpp" line="56"/>
        <source>a recipe without a checksum cannot be approved: sign it first</source>
        <translation>チェックサムのないレシピは承認できません: 先に署名してください</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeApproveButton</name>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="16"/>
        <source>Approve…</source>
        <translation>承認…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="21"/>
        <source>Approve the saved recipe for the line (an engineer): stations with users run only approved recipes</source>
        <translation>保存したレシピをライン用に承認 (エンジニア): ユーザーのいるステーションは承認済みレシピだけを実行します</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="35"/>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="43"/>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="65"/>
        <source>Approve recipe</source>
        <translation>レシピの承認</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="37"/>
        <source>Save the recipe first: what is approved is the saved file&apos;s checksum.</source>
        <translation>先にレシピを保存してください: 承認されるのは保存したファイルのチェックサムです。</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="39"/>
        <source>%1 cannot be approved: %2</source>
        <translation>%1 は承認できません: %2</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="44"/>
        <source>This station has no users: an approval names its approver. Set up users with opentop-cli eol user add.</source>
        <translation>このステーションにはユーザーがいません: 承認には承認者が記録されます。opentop-cli eol user add でユーザーを設定してください。</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="50"/>
        <source>approve %1 rev. %2</source>
        <translation>%1 rev. %2 の承認</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeApproveButton.cpp" line="66"/>
        <source>%1 rev. %2 is approved by %3: stations run it.</source>
        <translation>%1 rev. %2 は %3 が承認しました: ステーションで実行されます。</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeBuilder</name>
    <message>
        <location filename="../model/eol/RecipeBuilder.cpp" line="208"/>
        <source>%1: unknown family &quot;%2&quot;</source>
        <translation>%1: 不明なファミリ &quot;%2&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeBuilder.cpp" line="228"/>
        <source>%1: %2 holds a value the profile does not allow: %3</source>
        <translation>%1: %2 にプロファイルで許可されていない値があります: %3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeBuilder.cpp" line="261"/>
        <source>no drive to make a recipe of</source>
        <translation>レシピを作成するドライバがありません</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeChecker</name>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="62"/>
        <source> (for %1)</source>
        <translation> (%1 用)</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="94"/>
        <source>the recipe names no product</source>
        <translation>レシピに製品名がありません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="96"/>
        <source>the recipe has no revision</source>
        <translation>レシピにリビジョンがありません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="98"/>
        <source>the recipe names no drive</source>
        <translation>レシピにドライバが指定されていません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="111"/>
        <source>%1: machine number %2 is already position %3; every drive of a unit needs its own machine number</source>
        <translation>%1: 局番 %2 はすでに位置 %3 で使用されています。製品の各ドライバには固有の局番が必要です</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="133"/>
        <source>%1: unknown family &quot;%2&quot;; known: %3</source>
        <translation>%1: 不明なファミリ &quot;%2&quot;。既知: %3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="139"/>
        <source>%1: a %2 takes machine numbers %3–%4</source>
        <translation>%1: %2 の局番は %3–%4 です</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="152"/>
        <source>%1: the %2 has no variant &quot;%3&quot;; known: %4</source>
        <translation>%1: %2 に機種 &quot;%3&quot; はありません。既知: %4</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="154"/>
        <source>none</source>
        <translation>なし</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="156"/>
        <source>%1: variant &quot;%2&quot; is named twice</source>
        <translation>%1: 機種 &quot;%2&quot; が 2 回指定されています</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="164"/>
        <source>%1: variantProof &quot;%2&quot; is not known; use &quot;required&quot; or &quot;operator&quot; (or leave it out)</source>
        <translation>%1: variantProof「%2」は不明。&quot;required&quot; か &quot;operator&quot; を使用（または省略）</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="169"/>
        <source>%1: variantProof &quot;operator&quot; needs exactly one allowed variant for the operator to confirm</source>
        <translation>%1: variantProof &quot;operator&quot; には作業者が確認する許可機種がちょうど 1 つ必要</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="181"/>
        <source>%1: firmware version &quot;%2&quot; is not a version as the drive reports it (major.minor, e.g. &quot;1.5&quot;)</source>
        <translation>%1: ファームウェアバージョン &quot;%2&quot; はドライバが通知する形式ではありません（major.minor、例: &quot;1.5&quot;）</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="194"/>
        <source>the %1 has no setting &quot;%2&quot;</source>
        <translation>%1 に設定 &quot;%2&quot; はありません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="196"/>
        <source>%1 is not a setting a recipe can write</source>
        <translation>%1 はレシピで書き込める設定ではありません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="198"/>
        <source>%1 decides how the drive communicates; a recipe cannot change it, or the station would lose the drive in the middle of the run</source>
        <translation>%1 はドライバの通信方法を決める設定です。レシピでは変更できません（変更すると、実行中にステーションがドライバを見失います）</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="218"/>
        <source>%1: setting %2</source>
        <translation>%1: 設定 %2</translation>
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
        <translation>%1 が 2 回指定されています</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="237"/>
        <source>%1: what it allows depends on %2, which the recipe does not set; add %2 to the settings</source>
        <translation>%1: 許容値は %2 に依存しますが、レシピで設定されていません。%2 を設定に追加してください</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="246"/>
        <source>%1 decides what %2 allows; set %2 in the recipe too, or the drive may be left with a value that is no longer valid</source>
        <translation>%1 は %2 の許容値を決めます。%2 もレシピで設定してください。設定しないと、ドライバに無効な値が残る可能性があります</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="262"/>
        <location filename="../model/eol/RecipeChecker.cpp" line="330"/>
        <source>%1: unit &quot;%2&quot;, but the drive&apos;s value is in &quot;%3&quot;</source>
        <translation>%1: 単位が &quot;%2&quot; ですが、ドライバの値の単位は &quot;%3&quot; です</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="283"/>
        <location filename="../model/eol/RecipeChecker.cpp" line="385"/>
        <source>%1: per-unit value %2</source>
        <translation>%1: 個別値 %2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="294"/>
        <source>%1 is given twice (as a setting or as a per-unit value)</source>
        <translation>%1 が 2 回指定されています（設定または個別値として）</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="300"/>
        <source>%1: the range&apos;s lowest value %2 is above its highest value %3</source>
        <translation>%1: 範囲の最小値 %2 が最大値 %3 を超えています</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="321"/>
        <source>%1: what it allows depends on %2, which the recipe does not set</source>
        <translation>%1: 許容値は %2 に依存しますが、レシピで設定されていません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="328"/>
        <source>%1 is not a number; a per-unit value needs a numeric setting</source>
        <translation>%1 は数値ではありません。個別値には数値の設定が必要です</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="334"/>
        <source>%1: range %2–%3%4</source>
        <translation>%1: 範囲 %2–%3%4</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="340"/>
        <source>%1 is outside what the drive allows: %2%3</source>
        <translation>%1 はドライバの許容範囲外です: %2%3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="352"/>
        <source>%1 includes values the drive does not allow; allowed: %2%3</source>
        <translation>%1 にドライバで許可されていない値が含まれています。許容値: %2%3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="378"/>
        <source>%1: per-unit value %2: %3%4 is outside the recipe&apos;s range %5–%6%4</source>
        <translation>%1: 個別値 %2: %3%4 はレシピの範囲 %5–%6%4 外です</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="389"/>
        <source>%1: the recipe has no per-unit value %2</source>
        <translation>%1: レシピに個別値 %2 はありません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeChecker.cpp" line="392"/>
        <source>the recipe has no drive at machine number %1</source>
        <translation>レシピに局番 %1 のドライバはありません</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeEditor</name>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="40"/>
        <source>Recipe editor</source>
        <translation>レシピエディタ</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="61"/>
        <source>Revision:</source>
        <translation>リビジョン:</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="63"/>
        <source>Product:</source>
        <translation>製品:</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="64"/>
        <source>Description:</source>
        <translation>説明:</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="65"/>
        <source>Position:</source>
        <translation>位置:</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="108"/>
        <source>New from drives on the bus…</source>
        <translation>バス上のドライバから新規作成…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="109"/>
        <source>New from backup file…</source>
        <translation>バックアップファイルから新規作成…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="110"/>
        <source>Open…</source>
        <translation>開く…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="111"/>
        <source>Save</source>
        <translation>保存</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="112"/>
        <source>Save as…</source>
        <translation>名前を付けて保存…</translation>
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
        <translation>マスター品のバス上のドライバまたはバックアップファイルからレシピを作成するか、既存のレシピを開いてください。</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="238"/>
        <source>the recipe is empty</source>
        <translation>レシピが空です</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="249"/>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="253"/>
        <source>The recipe passes check: it can be saved and run.</source>
        <translation>レシピはチェックに合格しました: 保存して実行できます。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/eol/RecipeEditor.cpp" line="256"/>
        <source>%n problem(s): the recipe cannot be saved until they are fixed.</source>
        <translation>
            <numerusform>%n 件の問題: 修正するまでレシピを保存できません。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/eol/RecipeEditor.cpp" line="268"/>
        <source>the recipe does not pass check (%n problem(s)); nothing was saved</source>
        <translation>
            <numerusform>レシピがチェックに合格しません（%n 件の問題）。何も保存していません</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="284"/>
        <source>cannot read %1: %2</source>
        <translation>%1 を読み込めません: %2</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="296"/>
        <source>%1 is not an OpenTOP recipe file</source>
        <translation>%1 は OpenTOP のレシピファイルではありません</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="303"/>
        <source>Opened %1</source>
        <translation>%1 を開きました</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="304"/>
        <source>Opened %1, which does not load as it is (%2). Saving checks it and signs it again.</source>
        <translation>%1 を開きましたが、そのままでは読み込めません (%2)。保存時にチェックし、再度署名します。</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="325"/>
        <source>Open recipe</source>
        <translation>レシピを開く</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="326"/>
        <source>Recipes (*.json);;All files (*)</source>
        <translation>レシピ (*.json);;すべてのファイル (*)</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="336"/>
        <source>Save recipe</source>
        <translation>レシピを保存</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="338"/>
        <source>Recipes (*.json)</source>
        <translation>レシピ (*.json)</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeEditor.cpp" line="343"/>
        <source>Saved and signed: %1</source>
        <translation>保存・署名しました: %1</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeFile</name>
    <message>
        <location filename="../model/eol/RecipeFile.cpp" line="268"/>
        <source>%1 is larger than %2 MB, the most a recipe file may hold; not a recipe file</source>
        <translation>%1 は %2 MB を超えています（レシピファイルの上限）。レシピファイルではありません</translation>
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
        <translation>局番 %1: %2。機種が分かれば指定してください</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeFromDrives.cpp" line="74"/>
        <source>machine number %1: %2, %3 (%4)</source>
        <translation>局番 %1: %2、%3（%4）</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeFromDrives.cpp" line="113"/>
        <source>Made from a golden unit; variants: %1.</source>
        <translation>マスター品から作成。機種: %1。</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeLimitsTable</name>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="33"/>
        <source>Parameter</source>
        <translation>パラメータ</translation>
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
        <translation>単位</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="54"/>
        <source>Add limit</source>
        <translation>規格値を追加</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="55"/>
        <source>Remove limit</source>
        <translation>規格値を削除</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="64"/>
        <source>Limits (measured over the hold):</source>
        <translation>規格値（保持中に測定）：</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeLimitsTable.cpp" line="78"/>
        <source>(unknown: %1)</source>
        <translation>（不明：%1）</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeParser</name>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="48"/>
        <source>not a JSON file: %1 at byte %2</source>
        <translation>JSON ファイルではありません: %2 バイト目で %1</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="52"/>
        <source>not an OpenTOP recipe file: the JSON is not an object</source>
        <translation>OpenTOP のレシピファイルではありません: JSON がオブジェクトではありません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="78"/>
        <source>&quot;positions&quot;: the recipe names no drive</source>
        <translation>&quot;positions&quot;: レシピにドライバが指定されていません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="83"/>
        <source>%1: must be an object</source>
        <translation>%1: オブジェクトでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="100"/>
        <source>not an OpenTOP recipe file (&quot;format&quot; is &quot;%1&quot;, not &quot;%2&quot;)</source>
        <translation>OpenTOP のレシピファイルではありません（&quot;format&quot; が &quot;%2&quot; ではなく &quot;%1&quot; です）</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="102"/>
        <source>not an OpenTOP recipe file (no &quot;format&quot;: &quot;%1&quot;)</source>
        <translation>OpenTOP のレシピファイルではありません（&quot;format&quot;: &quot;%1&quot; がありません）</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="107"/>
        <source>&quot;formatVersion&quot; must be a whole number from 1</source>
        <translation>&quot;formatVersion&quot; は 1 以上の整数でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="109"/>
        <source>written by a newer OpenTOP (recipe format version %1); this version reads recipe format version %2</source>
        <translation>新しい OpenTOP で書き込まれています（レシピフォーマットバージョン %1）。このバージョンが読み込めるのはレシピフォーマットバージョン %2 です</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="115"/>
        <source>the recipe has no checksum (&quot;checksum&quot;: &quot;sha256:…&quot;); it was not written by OpenTOP or was changed afterwards</source>
        <translation>レシピにチェックサムがありません（&quot;checksum&quot;: &quot;sha256:…&quot;）。OpenTOP で書き込まれていないか、書込み後に変更されています</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="121"/>
        <source>the recipe was changed after it was written (checksum mismatch); open and save it with OpenTOP to accept the change</source>
        <translation>書込み後にレシピが変更されています（チェックサム不一致）。変更を承認するには OpenTOP で開いて保存してください</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="138"/>
        <source>%1: &quot;machineNumber&quot; must be a machine number 1–247</source>
        <translation>%1: &quot;machineNumber&quot; は局番 1–247 でなければなりません</translation>
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
        <translation>%1 (%2): &quot;value&quot; は数値またはテキストでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="201"/>
        <source>%1 (%2): &quot;source&quot; must be &quot;csv&quot; or &quot;operator&quot;, not &quot;%3&quot;</source>
        <translation>%1 (%2): &quot;source&quot; は &quot;%3&quot; ではなく &quot;csv&quot; または &quot;operator&quot; でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="214"/>
        <source>%1: unknown step type &quot;%2&quot;; known: %3</source>
        <translation>%1: 不明なステップタイプ &quot;%2&quot;。既知: %3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="230"/>
        <source>%1: &quot;spno&quot; must be a running data number such as 2</source>
        <translation>%1: &quot;spno&quot; は運転データ番号（例: 2）でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="241"/>
        <source>%1: &quot;direction&quot; must be &quot;cw&quot; or &quot;ccw&quot;</source>
        <translation>%1: &quot;direction&quot; は &quot;cw&quot; または &quot;ccw&quot; でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="279"/>
        <source>%1: give either &quot;equals&quot; or limits, not both</source>
        <translation>%1: &quot;equals&quot; または規格値のいずれか一方を指定してください（両方は不可）</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="285"/>
        <source>%1: unknown step</source>
        <translation>%1: 不明なステップ</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="301"/>
        <source>%1: &quot;unit&quot; must be a text (&quot;&quot; for a value without a unit)</source>
        <translation>%1: &quot;unit&quot; はテキストでなければなりません（単位のない値は &quot;&quot;）</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="304"/>
        <source>%1: a limit needs &quot;lower&quot;, &quot;upper&quot; or both</source>
        <translation>%1: 規格値には &quot;lower&quot;、&quot;upper&quot;、またはその両方が必要です</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="325"/>
        <source>&quot;retest&quot; must be an object</source>
        <translation>&quot;retest&quot; はオブジェクトでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="334"/>
        <source>retest: &quot;maxAttempts&quot; must be a whole number from 0 (no limit) to 100</source>
        <translation>retest: &quot;maxAttempts&quot; は 0（制限なし）から 100 までの整数でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="344"/>
        <source>retest: &quot;passedSerial&quot; must be technician, refuse or allow, not &quot;%1&quot;</source>
        <translation>retest: &quot;passedSerial&quot; は &quot;%1&quot; ではなく technician、refuse、allow のいずれかでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="356"/>
        <source>%1: unknown key &quot;%2&quot;; allowed: %3</source>
        <translation>%1: 不明なキー &quot;%2&quot;。使用可能: %3</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="370"/>
        <source>%1&quot;%2&quot; must be a non-empty text</source>
        <translation>%1&quot;%2&quot; は空でないテキストでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="371"/>
        <source>%1&quot;%2&quot; must be a text</source>
        <translation>%1&quot;%2&quot; はテキストでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="383"/>
        <source>%1: &quot;%2&quot; must be a list of texts</source>
        <translation>%1: &quot;%2&quot; はテキストのリストでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="386"/>
        <source>%1: &quot;%2&quot; must be a list of non-empty texts</source>
        <translation>%1: &quot;%2&quot; は空でないテキストのリストでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="396"/>
        <source>%1: &quot;%2&quot; must be a number</source>
        <translation>%1: &quot;%2&quot; は数値でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="422"/>
        <source>%1&quot;%2&quot; must be a list</source>
        <translation>%1&quot;%2&quot; はリストでなければなりません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="425"/>
        <source>%1&quot;%2&quot; has %3 entries; at most %4 are allowed</source>
        <translation>%1&quot;%2&quot; のエントリが %3 個あります。最大 %4 個までです</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeParser.cpp" line="431"/>
        <source>%1&quot;%2&quot;: every entry must be an object</source>
        <translation>%1&quot;%2&quot;: すべてのエントリはオブジェクトでなければなりません</translation>
    </message>
</context>
<context>
    <name>opentop::RecipePositionForm</name>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="125"/>
        <source>every variant of the family, e.g. dbu200, dbu400</source>
        <translation>ファミリの全機種（例: dbu200, dbu400）</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="127"/>
        <source>any firmware, e.g. 1.5, 1.6</source>
        <translation>任意のファームウェア（例: 1.5, 1.6）</translation>
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
        <translation>名称</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="129"/>
        <source>Value</source>
        <translation>値</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="129"/>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="131"/>
        <source>Unit</source>
        <translation>単位</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="131"/>
        <source>Min</source>
        <translation>最小</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="131"/>
        <source>Max</source>
        <translation>最大</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="131"/>
        <source>Source</source>
        <translation>入力元</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="137"/>
        <source>Add per-unit value…</source>
        <translation>個別値を追加…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="137"/>
        <source>Add setting…</source>
        <translation>設定を追加…</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="138"/>
        <source>Remove</source>
        <translation>削除</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="151"/>
        <source>Settings</source>
        <translation>設定</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="152"/>
        <source>Per-unit values</source>
        <translation>個別値</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="153"/>
        <source>Test steps</source>
        <translation>試験ステップ</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="156"/>
        <source>Machine number:</source>
        <translation>局番:</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="157"/>
        <source>Name:</source>
        <translation>名称:</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="158"/>
        <source>Family:</source>
        <translation>ファミリ:</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="159"/>
        <source>Allowed variants:</source>
        <translation>許可する機種:</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="160"/>
        <source>Allowed firmware:</source>
        <translation>許可するファームウェア:</translation>
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
        <translation>CSV ファイル</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="229"/>
        <source>typed by the operator</source>
        <translation>作業者が入力</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="279"/>
        <source>(unknown: %1)</source>
        <translation>（不明: %1）</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="342"/>
        <source>Add a per-unit value</source>
        <translation>個別値を追加</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="342"/>
        <source>Add a setting</source>
        <translation>設定を追加</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipePositionForm.cpp" line="343"/>
        <source>Setting:</source>
        <translation>設定:</translation>
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
        <translation>%1 ではこのステップを実行できません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="53"/>
        <source>%1, step %2 (%3)</source>
        <translation>%1、ステップ %2 (%3)</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="63"/>
        <source>the drive takes motion commands only with communication priority; put a priority step before it</source>
        <translation>ドライバは通信優先でのみ運転コマンドを受け付けます。その前に優先切替えステップを入れてください</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="71"/>
        <source>the motor is not running here; put a start step before it</source>
        <translation>ここではモータが運転していません。その前に運転開始ステップを入れてください</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="82"/>
        <source>%1: the steps leave the motor running; end them with a stop step</source>
        <translation>%1: ステップ終了時にモータが運転したままです。停止ステップで終了してください</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="92"/>
        <source>%1 %2 s is not sane; give more than 0 s and at most %3 s</source>
        <translation>%1 %2 s は妥当ではありません。0 s より大きく %3 s 以下を指定してください</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="105"/>
        <source>unit &quot;%1&quot;, but %2 is measured in &quot;%3&quot;</source>
        <translation>単位が &quot;%1&quot; ですが、%2 の単位は &quot;%3&quot; です</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="129"/>
        <source>the profile&apos;s selection parameter is missing</source>
        <translation>プロファイルの選択パラメータがありません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="131"/>
        <source>running data %1: %2</source>
        <translation>運転データ %1: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="146"/>
        <source>what %1 means depends on %2, which the recipe does not set; add it to the settings</source>
        <translation>%1 の意味は %2 に依存しますが、レシピで設定されていません。設定に追加してください</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="154"/>
        <source>a speed of 0 stops the motor; use a stop step</source>
        <translation>速度 0 ではモータが停止します。停止ステップを使用してください</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="168"/>
        <source>unit &quot;%1&quot;, but with these settings %2 is in &quot;%3&quot;</source>
        <translation>単位が &quot;%1&quot; ですが、これらの設定では %2 の単位は &quot;%3&quot; です</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="185"/>
        <source>a %1 does not report its target speed; give the target</source>
        <translation>%1 は目標速度を通知しません。目標を指定してください</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="187"/>
        <source>the target speed must be above 0</source>
        <translation>目標速度は 0 より大きくなければなりません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="190"/>
        <source>the tolerance %1 must be above 0 and below the target speed</source>
        <translation>許容差 %1 は 0 より大きく、目標速度より小さくなければなりません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="194"/>
        <source>the time to reach the speed</source>
        <translation>速度到達時間</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="198"/>
        <source>the hold time</source>
        <translation>保持時間</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="200"/>
        <source>the step measures nothing; give limits</source>
        <translation>このステップは何も測定しません。規格値を指定してください</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="208"/>
        <source>the margin</source>
        <translation>マージン</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="211"/>
        <source>a %1 has no deceleration time setting to wait for; give the deceleration (0 s when it brakes at once)</source>
        <translation>%1 には待機すべき減速時間の設定がありません。減速時間を指定してください（即時ブレーキの場合は 0 s）</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="217"/>
        <source>the deceleration time %1 s is not sane; give 0–%2 s</source>
        <translation>減速時間 %1 s は妥当ではありません。0–%2 s を指定してください</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="232"/>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="274"/>
        <source>the %1 has no readable value &quot;%2&quot;</source>
        <translation>%1 に読出し可能な値 &quot;%2&quot; はありません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="237"/>
        <source>%1 is not a number</source>
        <translation>%1 は数値ではありません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="247"/>
        <source>%1: &quot;%2&quot; is not a statistic; use min, mean or max</source>
        <translation>%1: &quot;%2&quot; は統計値ではありません。min、mean、max のいずれかを使用してください</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="254"/>
        <source>%1: the limit&apos;s unit is &quot;%2&quot;, but the value is measured in &quot;%3&quot;</source>
        <translation>%1: 規格値の単位は &quot;%2&quot; ですが、値の単位は &quot;%3&quot; です</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="261"/>
        <source>%1: the lower limit %2 %4 is above the upper limit %3 %4</source>
        <translation>%1: 下限 %2 %4 が上限 %3 %4 を超えています</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepChecker.cpp" line="283"/>
        <source>%1 is a number; compare it with lower and upper limits</source>
        <translation>%1 は数値です。下限・上限の規格値と比較してください</translation>
    </message>
</context>
<context>
    <name>opentop::RecipeStepKinds</name>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="29"/>
        <source>take communication priority</source>
        <translation>通信優先にする</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="32"/>
        <source>select running data</source>
        <translation>運転データを選択</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="33"/>
        <source>Running data:</source>
        <translation>運転データ：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="36"/>
        <source>set the speed command</source>
        <translation>速度指令を設定</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="37"/>
        <source>Speed command:</source>
        <translation>速度指令:</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="38"/>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="50"/>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="70"/>
        <source>Unit:</source>
        <translation>単位：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="39"/>
        <source>the speed command&apos;s unit</source>
        <translation>速度指令の単位</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="42"/>
        <source>start</source>
        <translation>運転開始</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="43"/>
        <source>Direction:</source>
        <translation>回転方向：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="46"/>
        <source>wait for speed</source>
        <translation>速度到達を待機</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="47"/>
        <source>Target speed:</source>
        <translation>目標速度：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="48"/>
        <source>empty: the drive&apos;s own target speed</source>
        <translation>空欄：ドライバ自身の目標速度</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="49"/>
        <source>Tolerance (±):</source>
        <translation>許容差（±）：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="50"/>
        <source>the speed&apos;s unit</source>
        <translation>速度の単位</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="51"/>
        <source>Within:</source>
        <translation>制限時間：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="54"/>
        <source>hold and measure</source>
        <translation>保持して測定</translation>
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
        <translation>空欄：ドライバの設定値</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="62"/>
        <source>Margin:</source>
        <translation>余裕時間：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="63"/>
        <source>check for alarms and warnings</source>
        <translation>アラームと警告をチェック</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="66"/>
        <source>read and compare</source>
        <translation>読出しと比較</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="67"/>
        <source>Parameter:</source>
        <translation>パラメータ：</translation>
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
        <translation>空欄：なし</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="69"/>
        <source>Upper limit:</source>
        <translation>上限：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="70"/>
        <source>the value&apos;s unit</source>
        <translation>値の単位</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="71"/>
        <source>Or equals:</source>
        <translation>または一致：</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="72"/>
        <source>the expected text, instead of limits</source>
        <translation>規格値の代わりに期待する文字列</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="123"/>
        <source>SPno%1</source>
        <translation>SPno%1</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="125"/>
        <source>to %1</source>
        <translation>%1 に設定</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="129"/>
        <source>%1 ± %2 within %3 s</source>
        <translation>%3 s 以内に %1 ± %2</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="131"/>
        <source>the drive&apos;s target speed</source>
        <translation>ドライバの目標速度</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="134"/>
        <source>for %1 s; limits: %2</source>
        <translation>%1 s 間、判定値: %2 件</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="139"/>
        <source>stopped within %1 s + %2 s</source>
        <translation>%1 s + %2 s 以内に停止</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="140"/>
        <source>stopped within the deceleration time + %1 s</source>
        <translation>減速時間 + %1 s 以内に停止</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="144"/>
        <source>no value chosen to read yet</source>
        <translation>読み出す値がまだ選ばれていません</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="148"/>
        <source>%1 is &quot;%2&quot;</source>
        <translation>%1 が「%2」</translation>
    </message>
    <message>
        <location filename="../model/eol/RecipeStepKinds.cpp" line="149"/>
        <source>%1 between %2 and %3</source>
        <translation>%1 が %2～%3</translation>
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
        <translation>ステップ</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="48"/>
        <source>What it does</source>
        <translation>内容</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="56"/>
        <source>Add step</source>
        <translation>ステップを追加</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="61"/>
        <source>Remove</source>
        <translation>削除</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="62"/>
        <source>Move up</source>
        <translation>上へ</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="63"/>
        <source>Move down</source>
        <translation>下へ</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="93"/>
        <source>(unknown step: %1)</source>
        <translation>（不明なステップ：%1）</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="216"/>
        <source>No step selected</source>
        <translation>ステップが選択されていません</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="217"/>
        <source>Add a step, or select one to edit it.</source>
        <translation>ステップを追加するか、編集するステップを選択してください。</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="223"/>
        <source>Step %1: %2</source>
        <translation>ステップ %1：%2</translation>
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
        <translation>このステップに設定項目はありません。</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="323"/>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="325"/>
        <source>(unknown: %1)</source>
        <translation>（不明：%1）</translation>
    </message>
    <message>
        <location filename="../ui/eol/RecipeStepsEditor.cpp" line="335"/>
        <source>Parameter:</source>
        <translation>パラメータ：</translation>
    </message>
</context>
<context>
    <name>opentop::Reconnection</name>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="31"/>
        <source>&amp;Reconnect</source>
        <translation>再接続(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="38"/>
        <source>Open the last connection again, with the same drives and page (Ctrl+R)</source>
        <translation>同じドライバとページで前回の接続を開き直します (Ctrl+R)</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="92"/>
        <source>Reconnecting to %1…</source>
        <translation>%1 に再接続中…</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="123"/>
        <source>Reconnected to %1: reading every drive again…</source>
        <translation>%1 に再接続しました: すべてのドライバを読み出し直し中…</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="176"/>
        <source>Reconnected to %1.</source>
        <translation>%1 に再接続しました。</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="200"/>
        <source>Reconnecting failed: %1</source>
        <translation>再接続に失敗しました: %1</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="218"/>
        <location filename="../ui/main/Reconnection.cpp" line="262"/>
        <source>Connection lost</source>
        <translation>接続断</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="226"/>
        <location filename="../ui/main/Reconnection.cpp" line="267"/>
        <source>Reconnect</source>
        <translation>再接続</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="268"/>
        <source>Go on anyway</source>
        <translation>このまま続行</translation>
    </message>
    <message>
        <location filename="../ui/main/Reconnection.cpp" line="269"/>
        <source>Cancel</source>
        <translation>キャンセル</translation>
    </message>
</context>
<context>
    <name>opentop::RelayAnalysis</name>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="47"/>
        <source>no steady oscillation: %1 full cycles around %2, %3 needed</source>
        <translation>安定した振動がありません: %2 付近で完全な周期が %1 回（%3 回必要）</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="51"/>
        <source>Raise the relay amplitude, or choose an operating speed that leaves the output room on both sides.</source>
        <translation>リレー振幅を上げるか、出力の上下に余裕が残る運転速度を選んでください。</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="86"/>
        <source>the oscillation (±%1) is no larger than the hysteresis (%2)</source>
        <translation>振動 (±%1) がヒステリシス (%2) より大きくありません</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="89"/>
        <source>Raise the relay amplitude.</source>
        <translation>リレー振幅を上げてください。</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="97"/>
        <source>the oscillation&apos;s period, %1 ms, holds only %2 readings (one every %3 ms): at least %4 are needed, or its period and amplitude are the bus&apos;s rather than the motor&apos;s</source>
        <translation>振動の周期 %1 ms の間に読出しが %2 回しかありません（%3 ms ごと）: 少なくとも %4 回必要です。足りないと、周期と振幅はモータではなくバスのものになります</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="104"/>
        <source>Raise the line rate (115200 bit/s if every drive on the bus allows it) or stop polling other drives on this bus during the test; a larger relay amplitude or another speed does not change this.</source>
        <translation>通信速度を上げる（バス上のすべてのドライバが対応していれば 115200 bit/s）か、試験中はこのバスの他のドライバのポーリングを止めてください。リレー振幅や速度を変えても改善しません。</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="110"/>
        <source>the oscillation is not steady: periods differ by %1 %, amplitudes by %2 % (at most %3 % and %4 %)</source>
        <translation>振動が安定していません: 周期の差 %1 %、振幅の差 %2 %（上限は %3 % と %4 %）</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="116"/>
        <source>Raise the relay amplitude so that the oscillation stands out of friction and load changes, keep the load steady during the test, and stop polling other drives on this bus meanwhile.</source>
        <translation>振動が摩擦や負荷変動に埋もれないようリレー振幅を上げ、試験中は負荷を一定に保ち、その間このバスの他のドライバのポーリングを止めてください。</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="123"/>
        <source>the oscillation is lopsided: its time above and below %1 differ by %2 % of the period (at most %3 %)</source>
        <translation>振動が偏っています: %1 より上と下の時間の差が周期の %2 %（上限 %3 %）</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAnalysis.cpp" line="128"/>
        <source>The output for the operating speed was misjudged or the load changed: keep the load steady, choose an operating speed further from standstill and from full output, and repeat the test.</source>
        <translation>運転速度に必要な出力の見積りが外れたか、負荷が変わりました。負荷を一定に保ち、停止と最大出力の両方から離れた運転速度を選んで、試験をやり直してください。</translation>
    </message>
</context>
<context>
    <name>opentop::RelayAutotune</name>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="65"/>
        <source>the operating speed must be above 0 and below the test&apos;s speed limit %1 %2</source>
        <translation>運転速度は 0 より大きく、試験の速度制限値 %1 %2 より小さくなければなりません</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="72"/>
        <source>the relay amplitude must be 0–50 % of full output</source>
        <translation>リレー振幅は最大出力の 0–50 % でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="75"/>
        <source>Open loop: finding the output for %1 %2</source>
        <translation>開ループ: %1 %2 に必要な出力を探索中</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="148"/>
        <source>the motor did not turn at %1 % output</source>
        <translation>出力 %1 % でモータが回転しませんでした</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="180"/>
        <source>the operating speed needs %1 % output: no room for ±%2 % around it</source>
        <translation>運転速度には出力 %1 % が必要です: その上下に ±%2 % の余裕がありません</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="185"/>
        <source>Relay test around %1 %2 (output %3 % ± %4 %)</source>
        <translation>%1 %2 付近でリレー試験中 (出力 %3 % ± %4 %)</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="224"/>
        <source>no steady oscillation within %1 s: %2</source>
        <translation>%1 s 以内に安定した振動が得られませんでした: %2</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="226"/>
        <source>try a larger amplitude</source>
        <translation>振幅を大きくしてみてください</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayAutotune.cpp" line="259"/>
        <source>the relay result was refused: %1</source>
        <translation>リレー試験の結果は採用できません: %1</translation>
    </message>
</context>
<context>
    <name>opentop::RelayTuning</name>
    <message>
        <location filename="../model/tuning/RelayTuning.cpp" line="28"/>
        <source>Raise the relay amplitude.</source>
        <translation>リレー振幅を上げてください。</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayTuning.cpp" line="49"/>
        <source>the drive&apos;s own loop, as the model extrapolates it, would oscillate with a period of %1 ms, under %2 readings (one every %3 ms): the step after Accept could not show whether the gains work</source>
        <translation>モデルから外挿したドライバ自身のループは周期 %1 ms で振動し、読出し %2 回分（%3 ms ごと）に満たないため、採用後のステップでゲインが機能するか確かめられません</translation>
    </message>
    <message>
        <location filename="../model/tuning/RelayTuning.cpp" line="55"/>
        <source>Raise the line rate (115200 bit/s if every drive on the bus allows it) or stop polling other drives on this bus during the test.</source>
        <translation>通信速度を上げる（バス上のすべてのドライバが対応していれば 115200 bit/s）か、試験中はこのバスの他のドライバのポーリングを止めてください。</translation>
    </message>
</context>
<context>
    <name>opentop::RestoreChoice</name>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="28"/>
        <source>Drive in file / setting</source>
        <translation>ファイル内のドライバ / 設定</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="28"/>
        <source>Value in file</source>
        <translation>ファイルの値</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="28"/>
        <source>Restore to</source>
        <translation>復元先</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="55"/>
        <source>(do not restore)</source>
        <translation>（復元しない）</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="59"/>
        <source>Drive %1 (%2)</source>
        <translation>ドライバ %1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="121"/>
        <source>Two drives of the file would be restored to drive %1.</source>
        <translation>ファイルの 2 台のドライバがドライバ %1 に復元されます。</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="126"/>
        <source>Drive %1 is not on the bus (or not identified).</source>
        <translation>ドライバ %1 がバス上にありません（または未識別）。</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreChoice.cpp" line="138"/>
        <source>Nothing chosen: tick at least one setting of a drive with a target.</source>
        <translation>何も選択されていません: 復元先のあるドライバの設定を少なくとも 1 つチェックしてください。</translation>
    </message>
</context>
<context>
    <name>opentop::RestoreCommand</name>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="37"/>
        <source>Show what a backup file would change on its drives; with --yes write it, verified</source>
        <translation>バックアップファイルによるドライバの変更内容を表示します。--yes で書き込み、照合します</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="42"/>
        <source>Restore only these drives of the file, e.g. 1,5-7.</source>
        <translation>ファイル内のこれらのドライバのみ復元します。例: 1,5-7。</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="43"/>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="44"/>
        <source>Read the drives and show the plan; write nothing.</source>
        <translation>ドライバを読み出して計画を表示します。何も書き込みません。</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="45"/>
        <source>Write the plan (without it restore only shows it).</source>
        <translation>計画を書き込みます（指定しない場合、restore は表示のみ）。</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="55"/>
        <source>%1: the drive&apos;s settings were not read; nothing compared, nothing written</source>
        <translation>%1: ドライバの設定を読み出せませんでした。比較も書込みもしていません</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="61"/>
        <location filename="../cli/RestoreCommand.cpp" line="99"/>
        <source>note: %1</source>
        <translation>注: %1</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="66"/>
        <source>parameter</source>
        <translation>パラメータ</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="66"/>
        <source>file value</source>
        <translation>ファイルの値</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="66"/>
        <source>device value</source>
        <translation>デバイスの値</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="67"/>
        <source>result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="67"/>
        <source>action</source>
        <translation>操作</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="81"/>
        <source>%1 written and verified, %2 unchanged, %3 failed, %4 not attempted</source>
        <translation>%1 個を書込み・照合、%2 個は変更なし、%3 個は失敗、%4 個は未実行</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="87"/>
        <source>, %1 not confirmed</source>
        <translation>、%1 個は未確認</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="89"/>
        <source>; %1 of %2 store commands written</source>
        <translation>。保存コマンド %2 個中 %1 個を書込み</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="124"/>
        <source>error: name one backup file: restore FILE [--ids LIST] [--yes]</source>
        <translation>エラー: バックアップファイルを 1 つ指定してください: restore FILE [--ids LIST] [--yes]</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="138"/>
        <source>error: --ids: %1</source>
        <translation>エラー: --ids: %1</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="144"/>
        <source>error: %1 holds no drive with machine number %2; it holds %3</source>
        <translation>エラー: %1 に局番 %2 のドライバは含まれていません。含まれているのは %3 です</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="165"/>
        <source>error: %1; nothing written</source>
        <translation>エラー: %1。何も書き込んでいません</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="184"/>
        <source>error: %1: %2</source>
        <translation>エラー: %1: %2</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="205"/>
        <source>%1: not attempted</source>
        <translation>%1: 未実行</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="234"/>
        <source>dry run: nothing written</source>
        <translation>ドライラン: 何も書き込んでいません</translation>
    </message>
    <message>
        <location filename="../cli/RestoreCommand.cpp" line="235"/>
        <source>nothing written; add --yes to write</source>
        <translation>何も書き込んでいません。書き込むには --yes を付けてください</translation>
    </message>
</context>
<context>
    <name>opentop::RestoreDialog</name>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="38"/>
        <source>&amp;Preview</source>
        <translation>プレビュー(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="39"/>
        <source>&amp;Write to drives…</source>
        <translation>ドライバに書込み(&amp;W)…</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="40"/>
        <source>&amp;Cancel</source>
        <translation>キャンセル(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="41"/>
        <source>&amp;Save report…</source>
        <translation>レポートを保存(&amp;S)…</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="43"/>
        <source>Restore from a backup file</source>
        <translation>バックアップファイルから復元</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="45"/>
        <source>No file chosen</source>
        <translation>ファイル未選択</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="46"/>
        <source>&amp;Choose file…</source>
        <translation>ファイルを選択(&amp;C)…</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="48"/>
        <source>File:</source>
        <translation>ファイル:</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="60"/>
        <source>Read the drives and show what would change; writes nothing</source>
        <translation>ドライバを読み出して変更内容を表示します。何も書き込みません</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="61"/>
        <source>Write the previewed changes, each verified by reading it back</source>
        <translation>プレビューした変更を書き込み、それぞれ読み戻して照合します</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="62"/>
        <source>Stop after the write in progress has been verified</source>
        <translation>実行中の書込みの照合後に停止します</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="63"/>
        <source>Save the report as text, or as CSV when the name ends in .csv</source>
        <translation>レポートをテキストで保存します（名前が .csv で終わる場合は CSV）</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="64"/>
        <source>C&amp;lose</source>
        <translation>閉じる(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="113"/>
        <source>%1: no such file</source>
        <translation>%1: ファイルがありません</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="118"/>
        <source>the file could not be read</source>
        <translation>ファイルを読み込めませんでした</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="119"/>
        <location filename="../ui/files/RestoreDialog.cpp" line="179"/>
        <source>Refused, nothing will be written: %1</source>
        <translation>拒否。何も書き込みません: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/RestoreDialog.cpp" line="124"/>
        <source>%n drive(s) in the file. Choose what to restore, then Preview.</source>
        <translation>
            <numerusform>ファイル内のドライバ %n 台。復元する内容を選択し、「プレビュー」を押してください。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="146"/>
        <source>Refused, nothing written:</source>
        <translation>拒否。何も書き込んでいません:</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="148"/>
        <source>Drive %1 from %2: %3</source>
        <translation>ドライバ %1（%2 から）: %3</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="178"/>
        <source>Choose a backup file first.</source>
        <translation>先にバックアップファイルを選択してください。</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="194"/>
        <source>Nothing was read or written: %1.</source>
        <translation>何も読み書きしていません：%1。</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="86"/>
        <source>Reading drive %1…</source>
        <translation>ドライバ %1 を読出し中…</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="86"/>
        <source>Writing drive %1…</source>
        <translation>ドライバ %1 に書込み中…</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="94"/>
        <source>drive %1: %2 (%v of %m)</source>
        <translation>ドライバ %1: %2 (%v / %m)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="229"/>
        <source>Stopping after the write in progress has been verified…</source>
        <translation>実行中の書込みの照合後に停止します…</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="244"/>
        <location filename="../ui/files/RestoreDialog.cpp" line="325"/>
        <location filename="../ui/files/RestoreDialog.cpp" line="330"/>
        <source>Drive %1: %2</source>
        <translation>ドライバ %1: %2</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/RestoreDialog.cpp" line="247"/>
        <source>%n setting(s) to write</source>
        <translation>
            <numerusform>書き込む設定 %n 個</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="254"/>
        <source>  Note: %1</source>
        <translation>  注: %1</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="257"/>
        <source>Nothing written yet. Write to drives to apply.</source>
        <translation>まだ何も書き込んでいません。適用するには「ドライバに書込み」を押してください。</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="258"/>
        <source>Nothing written.</source>
        <translation>何も書き込んでいません。</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="306"/>
        <source>Restore from backup file</source>
        <translation>バックアップファイルから復元</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="307"/>
        <source>OpenTOP backups (*.json);;All files (*)</source>
        <translation>OpenTOP バックアップ (*.json);;すべてのファイル (*)</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/files/RestoreDialog.cpp" line="333"/>
        <source>Write %n setting(s) to drive(s) %1, each verified by reading it back?</source>
        <translation>
            <numerusform>ドライバ %1 に %n 個の設定を書き込み、それぞれ読み戻して照合しますか？</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="338"/>
        <source>Write to drives</source>
        <translation>ドライバに書込み</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="338"/>
        <source>&amp;Write</source>
        <translation>書込み(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="343"/>
        <source>Save restore report</source>
        <translation>復元レポートを保存</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="344"/>
        <source>Text (*.txt);;CSV (*.csv)</source>
        <translation>テキスト (*.txt);;CSV (*.csv)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreDialog.cpp" line="349"/>
        <source>Could not save %1: %2</source>
        <translation>%1 を保存できませんでした: %2</translation>
    </message>
</context>
<context>
    <name>opentop::RestorePlan</name>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="71"/>
        <source>the file holds a %1 drive (%2), but machine number %3 is a %4 drive; nothing written</source>
        <translation>ファイルには %1 ドライバ (%2) が含まれていますが、局番 %3 は %4 ドライバです。何も書き込んでいません</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="78"/>
        <source>the file is from a %1 (%2), but machine number %3 is a %4 (%5); their allowed values differ, nothing written</source>
        <translation>ファイルは %1 (%2) のものですが、局番 %3 は %4 (%5) です。許容値が異なるため、何も書き込んでいません</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="85"/>
        <source>the drive does not tell its variant: every value must suit all variants (name it with --variant to use its own ranges)</source>
        <translation>ドライバが機種を通知しません: すべての値が全機種に適合する必要があります（--variant で機種を指定すると、その機種の範囲を使用します）</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="143"/>
        <source>%1: the value cannot be written exactly</source>
        <translation>%1: 値を正確に書き込めません</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/files/RestorePlan.cpp" line="163"/>
        <source>%n value(s) of the file may not be written to this drive; nothing written</source>
        <translation>
            <numerusform>ファイルの %n 個の値はこのドライバに書き込めません。何も書き込んでいません</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="245"/>
        <source>%1 sent after the writes, so that the settings written survive power-off</source>
        <translation>書込み後に %1 を送信し、書き込んだ設定を電源オフ後も保持します</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="248"/>
        <source>%1 sent: settings written to this drive earlier (by an interrupted restore, a page or the command line) are not stored yet</source>
        <translation>%1 を送信：以前にこのドライバへ書き込んだ設定 (中断した復元、ページまたはコマンドライン) がまだ保存されていません</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="252"/>
        <source>%1 not sent: nothing it stores is written. What a drive has stored cannot be read back: if it loses settings at power-off, switch it off and on and restore again</source>
        <translation>%1 は送信していません：これが保存する設定は書き込んでいません。ドライバに保存された内容は読み戻せません。電源オフで設定が失われる場合は、電源を入れ直してから再度復元してください</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="286"/>
        <source>keep</source>
        <translation>維持</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="288"/>
        <source>write</source>
        <translation>書込み</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="290"/>
        <source>store</source>
        <translation>保存</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="301"/>
        <source>unchanged</source>
        <translation>変更なし</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="304"/>
        <source>written, not verified: %1</source>
        <translation>書込み済み、未確認: %1</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="305"/>
        <source>written</source>
        <translation>書込み済み</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="305"/>
        <source>written and verified</source>
        <translation>書込み・照合済み</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="307"/>
        <source>failed: %1</source>
        <translation>失敗: %1</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="309"/>
        <source>not attempted</source>
        <translation>未実行</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="311"/>
        <source>not confirmed (%1): the drive may or may not hold it; run the restore again to read it back</source>
        <translation>未確認 (%1): ドライバがその値を保持しているかどうか不明です。復元を再実行して読み戻してください</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="336"/>
        <source>planned</source>
        <translation>計画済み</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="338"/>
        <source>restored</source>
        <translation>復元済み</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="340"/>
        <source>refused</source>
        <translation>拒否</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="342"/>
        <source>communication failure</source>
        <translation>通信失敗</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="344"/>
        <source>verification mismatch</source>
        <translation>照合不一致</translation>
    </message>
    <message>
        <location filename="../model/files/RestorePlan.cpp" line="346"/>
        <source>interrupted</source>
        <translation>中断</translation>
    </message>
</context>
<context>
    <name>opentop::RestorePlanTable</name>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="14"/>
        <source>Drive</source>
        <translation>ドライバ</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="14"/>
        <source>Parameter</source>
        <translation>パラメータ</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="14"/>
        <source>Action</source>
        <translation>操作</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="14"/>
        <source>File value</source>
        <translation>ファイルの値</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="15"/>
        <source>Drive value before</source>
        <translation>変更前のドライバの値</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="15"/>
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="93"/>
        <source>&amp;Differences only</source>
        <translation>差異のみ(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestorePlanTable.cpp" line="95"/>
        <source>Show only the settings that would be written (or were), and what went wrong</source>
        <translation>書き込む (または書き込んだ) 設定と失敗した項目だけを表示</translation>
    </message>
</context>
<context>
    <name>opentop::RestoreReport</name>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="18"/>
        <source>%1 written and verified, %2 unchanged, %3 failed, %4 not attempted</source>
        <translation>%1 個を書込み・照合、%2 個は変更なし、%3 個は失敗、%4 個は未実行</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="24"/>
        <source>, %1 not confirmed</source>
        <translation>、%1 個は未確認</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="26"/>
        <source>; %1 of %2 store commands written</source>
        <translation>。保存コマンド %2 個中 %1 個を書込み</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="35"/>
        <source>OpenTOP restore report</source>
        <translation>OpenTOP 復元レポート</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="35"/>
        <source>File: %1</source>
        <translation>ファイル: %1</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="36"/>
        <source>Date: %1 (UTC)</source>
        <translation>日時: %1 (UTC)</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="39"/>
        <source>Written to the drives</source>
        <translation>ドライバに書込み済み</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="39"/>
        <source>Preview only: nothing written</source>
        <translation>プレビューのみ: 何も書き込んでいません</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="42"/>
        <source>Machine number %1 from %2: %3</source>
        <translation>局番 %1（%2 から）: %3</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="53"/>
        <source>  %1: %2</source>
        <translation>  %1: %2</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="55"/>
        <source>  %1: file %2, drive %3: %4</source>
        <translation>  %1: ファイル %2、ドライバ %3: %4</translation>
    </message>
    <message>
        <location filename="../ui/files/RestoreReport.cpp" line="61"/>
        <source>  Note: %1</source>
        <translation>  注: %1</translation>
    </message>
</context>
<context>
    <name>opentop::Restorer</name>
    <message>
        <location filename="../model/files/Restorer.cpp" line="51"/>
        <source>interrupted before anything was written</source>
        <translation>何も書き込む前に中断しました</translation>
    </message>
    <message>
        <location filename="../model/files/Restorer.cpp" line="66"/>
        <source>reading the drive failed, nothing written (%1)</source>
        <translation>ドライバの読出しに失敗しました。何も書き込んでいません (%1)</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/files/Restorer.cpp" line="119"/>
        <source>%n value(s) of the file may not be written to the drives of the communication group; nothing written</source>
        <translation>
            <numerusform>ファイルの %n 個の値は通信グループのドライバに書き込めません。何も書き込んでいません</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/files/Restorer.cpp" line="147"/>
        <source>interrupted after %1 of %2 writes; run the restore again to complete it</source>
        <translation>%2 回中 %1 回の書込み後に中断しました。完了するには復元を再実行してください</translation>
    </message>
    <message>
        <location filename="../model/files/Restorer.cpp" line="183"/>
        <source>%1 not confirmed (%2): the drive may or may not hold it; run the restore again, it reads the drive back first</source>
        <translation>%1 未確認 (%2): ドライバがその値を保持しているかどうか不明です。復元を再実行してください（先にドライバを読み戻します）</translation>
    </message>
    <message>
        <location filename="../model/files/Restorer.cpp" line="217"/>
        <source>after storing, the drive holds %1</source>
        <translation>保存後のドライバの値は %1 です</translation>
    </message>
    <message>
        <location filename="../model/files/Restorer.cpp" line="222"/>
        <source>the settings could not be read back after storing</source>
        <translation>保存後に設定を読み戻せませんでした</translation>
    </message>
    <message>
        <location filename="../model/files/Restorer.cpp" line="255"/>
        <source>communication settings changed (%1): they take effect when the drive is next powered on; connect with the new settings after that</source>
        <translation>通信設定が変更されました (%1): 次回のドライバの電源投入時に有効になります。その後は新しい設定で接続してください</translation>
    </message>
</context>
<context>
    <name>opentop::ResultDatabase</name>
    <message>
        <location filename="../model/eol/ResultDatabase.cpp" line="45"/>
        <source>results database %1: %2</source>
        <translation>結果データベース %1: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultDatabase.cpp" line="49"/>
        <source>the Qt SQL driver %1 is not installed (Debian: %2)</source>
        <translation>Qt SQL ドライバ %1 がインストールされていません (Debian: %2)</translation>
    </message>
</context>
<context>
    <name>opentop::ResultQueries</name>
    <message>
        <location filename="../model/eol/ResultQueries.cpp" line="207"/>
        <source>no unit record %1</source>
        <translation>製品の記録 %1 がありません</translation>
    </message>
</context>
<context>
    <name>opentop::ResultSchema</name>
    <message>
        <location filename="../model/eol/ResultSchema.cpp" line="242"/>
        <source>the results database has schema version %1, newer than this program knows (%2): update OpenTOP on this station; nothing was written</source>
        <translation>結果データベースのスキーマバージョン %1 は、このプログラムが対応するバージョン (%2) より新しいです: このステーションの OpenTOP を更新してください。何も書き込んでいません</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultSchema.cpp" line="277"/>
        <source>the migration left a record pointing at no unit (table %1)</source>
        <translation>マイグレーション後、どの製品も指していない記録が残っています（テーブル %1）</translation>
    </message>
</context>
<context>
    <name>opentop::ResultSink</name>
    <message>
        <location filename="../model/eol/ResultSink.cpp" line="137"/>
        <source>the results database is not open</source>
        <translation>結果データベースが開かれていません</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultSink.cpp" line="210"/>
        <source>the results database refuses unit %1 (serial %2): %3</source>
        <translation>結果データベースがユニット %1（シリアル番号 %2）を拒否しています: %3</translation>
    </message>
</context>
<context>
    <name>opentop::ResultSpool</name>
    <message>
        <location filename="../model/eol/ResultSpool.cpp" line="67"/>
        <location filename="../model/eol/ResultSpool.cpp" line="103"/>
        <source>the station&apos;s spool %1: %2</source>
        <translation>ステーションの保管ファイル %1: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultSpool.cpp" line="71"/>
        <source>its folder cannot be made</source>
        <translation>フォルダーを作成できません</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultSpool.cpp" line="131"/>
        <source>the station&apos;s spool %1: entry %2 cannot be read (%3)</source>
        <translation>ステーションの保管ファイル %1: 項目 %2 を読み取れません（%3）</translation>
    </message>
</context>
<context>
    <name>opentop::ResultStore</name>
    <message>
        <location filename="../model/eol/ResultStore.cpp" line="64"/>
        <source>interrupted: the station stopped before the unit was finished (killed, power lost or crashed); the unit was not proven</source>
        <translation>中断: 製品の試験が終わる前にステーションが停止しました（強制終了、停電、クラッシュ）。製品は検証されていません</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultStore.cpp" line="72"/>
        <source>a unit needs a serial number</source>
        <translation>製品にはシリアル番号が必要です</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultStore.cpp" line="197"/>
        <source>a unit is finished with pass, fail, error or aborted, not %1</source>
        <translation>製品の終了は pass、fail、error、aborted のいずれかで、%1 は使えません</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultStore.cpp" line="227"/>
        <source>unit %1 (serial %2) was never begun in the results database</source>
        <translation>製品 %1（シリアル %2）は結果データベースで開始されていません</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultStore.cpp" line="229"/>
        <source>unit %1 (serial %2) is already recorded as %3; its record is kept</source>
        <translation>製品 %1（シリアル %2）はすでに %3 として記録されています。その記録を保持します</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultStore.cpp" line="251"/>
        <source>unit %1 (serial %2) is not running in the results database: it was never begun, or was already finished or marked interrupted</source>
        <translation>製品 %1（シリアル %2）は結果データベースで実行中ではありません: 開始されていないか、すでに終了または中断としてマークされています</translation>
    </message>
</context>
<context>
    <name>opentop::ResultUrl</name>
    <message>
        <location filename="../model/eol/ResultUrl.cpp" line="45"/>
        <source>no database given: name a file or a postgresql:// URL</source>
        <translation>データベースが指定されていません: ファイルまたは postgresql:// URL を指定してください</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultUrl.cpp" line="53"/>
        <source>unknown database URL &quot;%1&quot;: use a file path, sqlite:PATH or postgresql://user@host/database</source>
        <translation>不明なデータベース URL &quot;%1&quot;: ファイルパス、sqlite:PATH、postgresql://user@host/database のいずれかを使用してください</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultUrl.cpp" line="57"/>
        <source>sqlite: needs a file path</source>
        <translation>sqlite: にはファイルパスが必要です</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultUrl.cpp" line="86"/>
        <source>the host in &quot;%1&quot; has no closing ]</source>
        <translation>&quot;%1&quot; のホストに閉じ括弧 ] がありません</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultUrl.cpp" line="114"/>
        <source>unknown connection option &quot;%1&quot; in the database URL; known: %2</source>
        <translation>データベース URL の不明な接続オプション &quot;%1&quot;。既知: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/ResultUrl.cpp" line="137"/>
        <source>the port &quot;%1&quot; in the database URL is not a number from 1 to 65535</source>
        <translation>データベース URL のポート &quot;%1&quot; が 1–65535 の数値ではありません</translation>
    </message>
</context>
<context>
    <name>opentop::ResultsBrowser</name>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="61"/>
        <source>End-of-line results</source>
        <translation>出荷検査結果</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="64"/>
        <source>Started</source>
        <translation>開始</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="64"/>
        <source>Serial</source>
        <translation>シリアル</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="64"/>
        <source>Recipe</source>
        <translation>レシピ</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="64"/>
        <source>Station</source>
        <translation>ステーション</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="65"/>
        <source>Operator</source>
        <translation>作業者</translation>
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
        <translation>最初の不合格</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="84"/>
        <source>Export CSV…</source>
        <translation>CSV エクスポート…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="85"/>
        <source>Certificate PDF…</source>
        <translation>検査成績書 PDF…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="136"/>
        <source>There is no results database at %1 yet: a station makes it when it records its first unit.</source>
        <translation>%1 にはまだ結果データベースがありません: ステーションが最初の製品を記録するときに作成されます。</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="142"/>
        <source>Opening the results database %1…</source>
        <translation>結果データベース %1 を開いています…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="154"/>
        <source>Results database %1</source>
        <translation>結果データベース %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="178"/>
        <source>Searching…</source>
        <translation>検索しています…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="189"/>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="278"/>
        <source>the results database is not open</source>
        <translation>結果データベースが開いていません</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="220"/>
        <source>%1 rev. %2</source>
        <translation>%1 rev. %2</translation>
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
            <numerusform>製品 %n 台: 合格 %1、不合格 %2、ステーションエラー %3 · %4</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="253"/>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="306"/>
        <source>no unit is selected</source>
        <translation>製品が選択されていません</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="258"/>
        <source>Reading unit %1…</source>
        <translation>製品 %1 を読み出しています…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="307"/>
        <source>the unit&apos;s record is still being read</source>
        <translation>製品の記録をまだ読み出しています</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="316"/>
        <source>Export units as CSV</source>
        <translation>製品を CSV でエクスポート</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="316"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV ファイル (*.csv)</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/eol/ResultsBrowser.cpp" line="321"/>
        <source>%n unit(s) written to %1</source>
        <translation>
            <numerusform>製品 %n 台を %1 に書き込みました</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="332"/>
        <source>Save certificate</source>
        <translation>検査成績書を保存</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="333"/>
        <source>PDF files (*.pdf)</source>
        <translation>PDF ファイル (*.pdf)</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsBrowser.cpp" line="338"/>
        <source>Certificate written to %1</source>
        <translation>検査成績書を %1 に書き込みました</translation>
    </message>
</context>
<context>
    <name>opentop::ResultsFilterBar</name>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="21"/>
        <source>SQLite file or postgresql://user@host/database</source>
        <translation>SQLite ファイルまたは postgresql://user@host/database</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="22"/>
        <source>Open</source>
        <translation>開く</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="23"/>
        <source>File…</source>
        <translation>ファイル…</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="30"/>
        <source>any; * and ? as wildcards (SN-10*)</source>
        <translation>すべて。* と ? をワイルドカードに使用（SN-10*）</translation>
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
        <translation>今日</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="37"/>
        <source>Last 24 hours</source>
        <translation>過去 24 時間</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="38"/>
        <source>Last 7 days</source>
        <translation>過去 7 日間</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="39"/>
        <source>Last 30 days</source>
        <translation>過去 30 日間</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="40"/>
        <source>All</source>
        <translation>すべて</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="43"/>
        <source>Any</source>
        <translation>指定なし</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="47"/>
        <source>Search</source>
        <translation>検索</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="51"/>
        <source>Serial:</source>
        <translation>シリアル:</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="52"/>
        <source>Recipe:</source>
        <translation>レシピ:</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="53"/>
        <source>Station:</source>
        <translation>ステーション:</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="54"/>
        <source>Period:</source>
        <translation>期間:</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="55"/>
        <source>Verdict:</source>
        <translation>判定:</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="63"/>
        <source>Database:</source>
        <translation>データベース:</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="105"/>
        <source>Open results database</source>
        <translation>結果データベースを開く</translation>
    </message>
    <message>
        <location filename="../ui/eol/ResultsFilterBar.cpp" line="106"/>
        <source>SQLite databases (*.db *.sqlite);;All files (*)</source>
        <translation>SQLite データベース (*.db *.sqlite);;すべてのファイル (*)</translation>
    </message>
</context>
<context>
    <name>opentop::RetestPolicy</name>
    <message>
        <location filename="../model/eol/RetestPolicy.cpp" line="20"/>
        <source>serial %1 has passed already; this recipe never tests a passed unit again</source>
        <translation>シリアル %1 はすでに合格しています。このレシピでは合格済みの製品を再試験しません</translation>
    </message>
    <message>
        <location filename="../model/eol/RetestPolicy.cpp" line="23"/>
        <source>serial %1 has passed already; testing it again needs a technician</source>
        <translation>シリアル %1 はすでに合格しています。再試験には技術者の許可が必要です</translation>
    </message>
    <message>
        <location filename="../model/eol/RetestPolicy.cpp" line="29"/>
        <source>serial %1 was tested %2 times under this recipe, its limit; another attempt needs a technician</source>
        <translation>シリアル %1 はこのレシピで %2 回試験され、上限に達しています。再試験には技術者の許可が必要です</translation>
    </message>
    <message>
        <location filename="../model/eol/RetestPolicy.cpp" line="50"/>
        <source>the results database is not open</source>
        <translation>結果データベースが開いていません</translation>
    </message>
    <message>
        <location filename="../model/eol/RetestPolicy.cpp" line="58"/>
        <source>earlier tests of %1 were not checked (%2): the result is kept in the station&apos;s spool</source>
        <translation>%1 の過去の試験を確認できませんでした（%2）。結果はステーションの保管ファイルに保管されます</translation>
    </message>
</context>
<context>
    <name>opentop::RoleEvaluator</name>
    <message>
        <location filename="../model/profile/RoleEvaluator.cpp" line="102"/>
        <source>%1 = %2 (%3, function %4)</source>
        <translation>%1 = %2 (%3、ファンクション %4)</translation>
    </message>
</context>
<context>
    <name>opentop::RunCommand</name>
    <message>
        <location filename="../cli/RunCommand.cpp" line="50"/>
        <source>Test run: start, stop, direction, running data, hold/free, speed (needs --yes)</source>
        <translation>試運転: 運転開始、停止、回転方向、運転データ、保持/フリー、速度（--yes が必要）</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="55"/>
        <source>Send the command (it moves or stops a motor).</source>
        <translation>コマンドを送信します（モータが動作または停止します）。</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="65"/>
        <source>error: usage: %1 (one machine number; a negative speed after --)</source>
        <translation>エラー: 使い方: %1（局番を 1 つ指定。負の速度は -- の後に指定）</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="73"/>
        <location filename="../cli/RunCommand.cpp" line="78"/>
        <location filename="../cli/RunCommand.cpp" line="83"/>
        <location filename="../cli/RunCommand.cpp" line="145"/>
        <source>error: %1</source>
        <translation>エラー: %1</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="88"/>
        <source>Would send to machine number %1: %2
This moves or stops a motor: add --yes to send it.</source>
        <translation>局番 %1 に送信する内容: %2
モータが動作または停止します: 送信するには --yes を付けてください。</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="109"/>
        <source>note: %1</source>
        <translation>注: %1</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="137"/>
        <source>Sent to machine number %1: %2</source>
        <translation>局番 %1 に送信しました: %2</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="139"/>
        <source>Sent to machine number %1, executed also by %2 (communication group): %3</source>
        <translation>局番 %1 に送信しました（%2 も実行、通信グループ）: %3</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="175"/>
        <source>(not read: %1)</source>
        <translation>（未読出し: %1）</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="184"/>
        <source>State of machine number %1:</source>
        <translation>局番 %1 の状態:</translation>
    </message>
    <message>
        <location filename="../cli/RunCommand.cpp" line="200"/>
        <source>Communication group of %1, read after the command:</source>
        <translation>%1 の通信グループ、コマンド後の読出し:</translation>
    </message>
</context>
<context>
    <name>opentop::RunControl</name>
    <message>
        <location filename="../model/run/RunControl.cpp" line="59"/>
        <source>%1 needs one value, e.g. &quot;%1 %2&quot;</source>
        <translation>%1 には値が 1 つ必要です。例: &quot;%1 %2&quot;</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="62"/>
        <source>%1 takes no value</source>
        <translation>%1 は値を取りません</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="70"/>
        <source>select needs a running data number, e.g. &quot;select 2&quot;; got &quot;%1&quot;</source>
        <translation>select には運転データ番号が必要です。例: &quot;select 2&quot;（指定値 &quot;%1&quot;）</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="80"/>
        <source>unknown run command &quot;%1&quot;; use start, stop, cw, ccw, select N, hold, free, coast or speed VALUE</source>
        <translation>不明な運転コマンド &quot;%1&quot;。start、stop、cw、ccw、select N、hold、free、coast、speed VALUE のいずれかを使用してください</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="127"/>
        <source>%1 drives have no &quot;%2&quot; command; they take: %3</source>
        <translation>%1 ドライバに &quot;%2&quot; コマンドはありません。使用可能: %3</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="148"/>
        <source>%1 has no selection codes</source>
        <translation>%1 に選択コードがありません</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="149"/>
        <source>select %1: choose %2–%3 (%4 … %5)</source>
        <translation>select %1: %2–%3 を選択してください (%4 … %5)</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="186"/>
        <source>cannot read %1 to check that the drive takes motion commands: %2</source>
        <translation>ドライバが運転コマンドを受け付けるかを確認するための %1 を読み出せません: %2</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="206"/>
        <source>machine number %1 is in &quot;%2&quot; (%3); nothing was sent</source>
        <translation>局番 %1 は &quot;%2&quot; (%3) です。何も送信していません</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="210"/>
        <source>In &quot;%1&quot; the drive takes run, stop, direction and speed selection from its input terminals and refuses motion commands over the bus. To test-run it from here, switch it to &quot;%2&quot;: opentop-cli set %3 %4=%5 (and back to &quot;%1&quot;, =%6, when the machine&apos;s own controls should run it again).</source>
        <translation>&quot;%1&quot; では、ドライバは運転、停止、回転方向、速度選択を入力端子から受け付け、バス経由の運転コマンドを拒否します。ここから試運転するには &quot;%2&quot; に切り替えてください: opentop-cli set %3 %4=%5（機械側の操作で再び運転する場合は &quot;%1&quot; (=%6) に戻してください）。</translation>
    </message>
    <message>
        <location filename="../model/run/RunControl.cpp" line="265"/>
        <source>An alarm is active: the drive refuses to run until it is cleared. See opentop-cli alarms %1, then alarms %1 --reset --yes.</source>
        <translation>アラームが発生しています: 解除するまでドライバは運転を拒否します。opentop-cli alarms %1 を確認し、alarms %1 --reset --yes を実行してください。</translation>
    </message>
</context>
<context>
    <name>opentop::RunLiveState</name>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="26"/>
        <source>The drive now</source>
        <translation>現在のドライバ</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="49"/>
        <source>State</source>
        <translation>状態</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="51"/>
        <source>Alarm</source>
        <translation>アラーム</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="58"/>
        <source>Running data</source>
        <translation>運転データ</translation>
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
        <translation>通知なし</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="143"/>
        <location filename="../ui/run/RunLiveState.cpp" line="146"/>
        <location filename="../ui/run/RunLiveState.cpp" line="156"/>
        <source>not read</source>
        <translation>未読出し</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="143"/>
        <source>SPno%1</source>
        <translation>SPno%1</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="148"/>
        <source>none</source>
        <translation>なし</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="151"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="153"/>
        <source>active</source>
        <translation>発生中</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="172"/>
        <source>waiting for the first answer…</source>
        <translation>最初の応答を待機中…</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="172"/>
        <source>not watched</source>
        <translation>監視対象外</translation>
    </message>
    <message>
        <location filename="../ui/run/RunLiveState.cpp" line="178"/>
        <source>Not live: %1</source>
        <translation>更新停止: %1</translation>
    </message>
</context>
<context>
    <name>opentop::RunningData</name>
    <message>
        <location filename="../model/profile/RunningData.cpp" line="76"/>
        <source>SPno%1 slows down from %2 r/min in %3 s: the manual asks for a deceleration time of more than %4 s when slowing down from high speed (about %5 r/min and above).</source>
        <translation>SPno%1 は %2 r/min から %3 s で減速します: マニュアルでは、高速（約 %5 r/min 以上）から減速する場合、減速時間を %4 s より長くするよう指示されています。</translation>
    </message>
    <message>
        <location filename="../model/profile/RunningData.cpp" line="144"/>
        <source>Short deceleration from high speed on %1 (%2 r/min in %3 s): the manual asks for a deceleration time of more than %4 s when slowing down from high speed (about %5 r/min and above).</source>
        <translation>%1 で高速からの減速が短すぎます（%2 r/min を %3 s）: マニュアルでは、高速（約 %5 r/min 以上）から減速する場合、減速時間を %4 s より長くするよう指示されています。</translation>
    </message>
</context>
<context>
    <name>opentop::RunningDataPage</name>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="40"/>
        <location filename="../ui/pages/RunningDataPage.cpp" line="55"/>
        <source>Running data</source>
        <translation>運転データ</translation>
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
        <translation>回転方向</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="69"/>
        <source>SPno%1</source>
        <translation>SPno%1</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="72"/>
        <source>Selected by the inputs M0 = %1, M1 = %2, M2 = %3 or by the running data selection command</source>
        <translation>入力 M0 = %1、M1 = %2、M2 = %3 または運転データ選択コマンドで選択</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="95"/>
        <source>SS trimmer</source>
        <translation>SS トリマ</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="96"/>
        <source>SPno1 has no acceleration register: the SS trimmer on the drive sets it (0.5–30 s); it is not stored in the drive</source>
        <translation>SPno1 には加速時間のレジスタがありません: ドライバの SS トリマで設定します (0.5–30 s)。ドライバには保存されません</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="99"/>
        <source>SD trimmer</source>
        <translation>SD トリマ</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="100"/>
        <source>SPno1 has no deceleration register: the SD trimmer on the drive sets it (0.5 s or 2–30 s); it is not stored in the drive</source>
        <translation>SPno1 には減速時間のレジスタがありません: ドライバの SD トリマで設定します（0.5 s または 2–30 s）。ドライバには保存されません</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="104"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="105"/>
        <source>This drive has no register for this value</source>
        <translation>このドライバにはこの値のレジスタがありません</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="112"/>
        <source>Initialize</source>
        <translation>初期化</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="114"/>
        <source>Reset SPno%1 on the drive to its factory defaults</source>
        <translation>ドライバの SPno%1 を工場出荷時設定に戻します</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="115"/>
        <location filename="../ui/pages/RunningDataPage.cpp" line="315"/>
        <location filename="../ui/pages/RunningDataPage.cpp" line="322"/>
        <source>Initialize SPno%1</source>
        <translation>SPno%1 の初期化</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="145"/>
        <source>SPno1 runs at the speed of the external speed-setting VR (CN3) with the SS/SD trimmer times; it is not stored in the drive</source>
        <translation>SPno1 は外部速度設定器 VR (CN3) の速度と SS/SD トリマの時間で運転します。ドライバには保存されません</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="255"/>
        <source>Allowed speed on this %1: %2 (0 stops the motor)</source>
        <translation>この %1 の許容速度: %2（0 でモータ停止）</translation>
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
        <translation>許容速度: %1</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="269"/>
        <source>The drive&apos;s variant is not known, so a speed must suit every variant (0 stops the motor): %1</source>
        <translation>ドライバの機種が不明なため、速度は全機種に適合する必要があります（0 でモータ停止）: %1</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="281"/>
        <source>its factory default</source>
        <translation>工場出荷時設定</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="303"/>
        <source>The SPno1 speed and times come from the external VR and the SS/SD trimmers; they do not change.</source>
        <translation>SPno1 の速度と時間は外部 VR と SS/SD トリマで決まるため、変更されません。</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="310"/>
        <source>Your unwritten edits in this row are discarded.</source>
        <translation>この行の未書込みの編集は破棄されます。</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="316"/>
        <source>Reset running data SPno%1 of drive %2 to these factory defaults?</source>
        <translation>ドライバ %2 の運転データ SPno%1 をこれらの工場出荷時設定に戻しますか？</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="328"/>
        <source>Initializing SPno%1…</source>
        <translation>SPno%1 を初期化中…</translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="343"/>
        <source>SPno%1 was not initialized: %2</source>
        <translation>SPno%1 は初期化されませんでした: %2</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/pages/RunningDataPage.cpp" line="359"/>
        <source>SPno%1 initialized; %n value(s) could not be read back</source>
        <translation>
            <numerusform>SPno%1 を初期化しました。%n 個の値を読み戻せませんでした</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/pages/RunningDataPage.cpp" line="361"/>
        <source>SPno%1 initialized to its factory defaults</source>
        <translation>SPno%1 を工場出荷時設定に初期化しました</translation>
    </message>
</context>
<context>
    <name>opentop::ScanCommand</name>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="66"/>
        <source>Find and identify the drives on the bus (machine numbers 1–247)</source>
        <translation>バス上のドライバを検出・識別します（局番 1–247）</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="72"/>
        <source>First machine number to ask, 1–247 (default 1).</source>
        <translation>問い合わせる最初の局番、1–247（既定 1）。</translation>
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
        <translation>問い合わせる最後の局番、1–247（既定 247）。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="75"/>
        <source>Wait per machine number in ms, 10–5000 (default: derived from the baud rate; raise it for slow adapters or gateways).</source>
        <translation>局番ごとの待ち時間 (ms)、10–5000（既定: ボーレートから算出。低速なアダプタやゲートウェイでは大きくしてください）。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="77"/>
        <source>MS</source>
        <translation>MS</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="79"/>
        <source>Also ask the machine numbers not found in every other line format a drive can be set to (a DC controller at 8E1 on a DBU bus at 8N1): one more pass per format, off by default.</source>
        <translation>見つからなかった局番を、ドライブが設定できるほかのすべての通信フォーマットでも問い合わせます（8N1 の DBU バス上の 8E1 の DC コントローラ）。形式ごとにスキャンが 1 回増えます。既定はオフ。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="94"/>
        <source>error: --%1 must be a number %2–%3, not &quot;%4&quot;</source>
        <translation>エラー: --%1 は %2–%3 の数値でなければなりません（&quot;%4&quot; は不可）</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="106"/>
        <source>error: scan takes no arguments; use --from N --to N</source>
        <translation>エラー: scan は引数を取りません。--from N --to N を使用してください</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="115"/>
        <source>error: --from %1 is after --to %2</source>
        <translation>エラー: --from %1 が --to %2 より後です</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="133"/>
        <source>Scanning machine numbers %1–%2 on %3, %4 ms each…</source>
        <translation>%3 で局番 %1–%2 をスキャン中（各 %4 ms）…</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="180"/>
        <source>Interrupted before any machine number was scanned.</source>
        <translation>局番をスキャンする前に中断しました。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="182"/>
        <source>Interrupted: machine numbers %1–%2 were scanned (%3 of %4); %5–%6 were not asked.</source>
        <translation>中断: 局番 %1–%2 をスキャンしました（%4 中 %3）。%5–%6 は未問い合わせです。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="196"/>
        <source>error: the scan stopped at machine number %1: %2</source>
        <translation>エラー: 局番 %1 でスキャンが停止しました: %2</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="208"/>
        <source>note: remembered for %1: %2; set, run and restore read their communication groups before a write</source>
        <translation>注意: %1 について記憶しました: %2。set・run・restore は書込みの前にそれらの通信グループを読み出します</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="217"/>
        <source>warning: %1</source>
        <translation>警告: %1</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="219"/>
        <source>note: %1 drive(s) answered only after the %2 ms wait and were asked again; if scans miss drives, give a longer --wait.</source>
        <translation>注: %1 台のドライバが %2 ms の待ち時間の後に応答したため、再度問い合わせました。スキャンでドライバが見つからない場合は、--wait を長くしてください。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="228"/>
        <source>warning: machine number %1 answered, but its identification failed, also when asked again %2 more times; it is not counted as a drive. Add it by hand: name it in a command (it is identified again then, within --timeout; raise it for a slow device), or check its line settings and scan again with a longer --wait.</source>
        <translation>警告: 局番 %1 は応答しましたが、さらに %2 回問い合わせても識別に失敗しました。ドライバとしては数えません。手動で追加してください: コマンドでこの局番を指定すると --timeout 内で再識別します (応答の遅い機器では長くしてください)。または通信設定を確認し、長めの --wait で再スキャンしてください。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="237"/>
        <source>No drive answered at machine numbers %1–%2. Check:
  - the wiring, and the A/B polarity (swap A and B if unsure);
  - baud rate and parity: the drives&apos; settings must match %3 (--baud, --parity, --family);
  - the termination (120 Ω at both ends of the bus) and that the drives are powered.</source>
        <translation>局番 %1–%2 で応答したドライバはありません。確認事項:
  - 配線と A/B の極性（不明な場合は A と B を入れ替える）
  - ボーレートとパリティ: ドライバの設定が %3 と一致している必要があります (--baud、--parity、--family)
  - 終端抵抗（バスの両端に 120 Ω）とドライバの電源</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="250"/>
        <source>hint: %1 Retry with the same connection and: %2</source>
        <translation>ヒント: %1 同じ接続に次を加えて再試行してください: %2</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="263"/>
        <source>Serial line: %1</source>
        <translation>シリアル回線: %1</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="266"/>
        <source>warning: %1 The scan waits up to %2 ms longer per machine number because of it.</source>
        <translation>警告: %1 このため、スキャンは局番ごとに最大 %2 ms 長く待ちます。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="390"/>
        <source>warning: machine number %1 (%2) answers with garbled replies: two drives probably have the same machine number. Check the address switches of the drives on this bus, give each drive its own machine number, power them off and on, and scan again.</source>
        <translation>警告：局番 %1 (%2) の応答が壊れています。2 台のドライバが同じ局番になっている可能性があります。このバスのドライバのアドレススイッチを確認し、各ドライバに別の局番を設定して電源を入れ直し、再度スキャンしてください。</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="276"/>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="276"/>
        <source>hex</source>
        <translation>16 進</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="276"/>
        <source>switches</source>
        <translation>スイッチ</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="276"/>
        <source>family</source>
        <translation>ファミリ</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="277"/>
        <source>model</source>
        <translation>型式</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="277"/>
        <source>firmware</source>
        <translation>ファームウェア</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="277"/>
        <source>state</source>
        <translation>状態</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="283"/>
        <source>name</source>
        <translation>名前</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="289"/>
        <source>comm. group</source>
        <translation>通信グループ</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="294"/>
        <source>line format</source>
        <translation>通信フォーマット</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="311"/>
        <source>the port&apos;s</source>
        <translation>ポートの形式</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="371"/>
        <source>1 drive found in %1 s</source>
        <translation>1 台のドライバを検出（%1 s）</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="372"/>
        <source>%1 drives found in %2 s</source>
        <translation>%1 台のドライバを検出（%2 s）</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="374"/>
        <source>; 1 possible duplicate machine number: %1</source>
        <translation>。局番重複の可能性 1 件: %1</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="376"/>
        <source>; %1 possible duplicate machine numbers: %2</source>
        <translation>。局番重複の可能性 %1 件: %2</translation>
    </message>
    <message>
        <location filename="../cli/ScanCommand.cpp" line="380"/>
        <source>; answered, identification failed: %1 (add by hand)</source>
        <translation>; 応答あり・識別失敗: %1 (手動で追加)</translation>
    </message>
</context>
<context>
    <name>opentop::ScanDrives</name>
    <message>
        <location filename="../cli/ScanDrives.cpp" line="43"/>
        <source>%1 — variant unknown</source>
        <translation>%1 — 機種不明</translation>
    </message>
    <message>
        <location filename="../cli/ScanDrives.cpp" line="44"/>
        <source>the drive does not report its variant; give it with --variant %1=VARIANT (%2)</source>
        <translation>ドライバが機種を通知しません。--variant %1=VARIANT で指定してください (%2)</translation>
    </message>
</context>
<context>
    <name>opentop::ScanFormats</name>
    <message>
        <location filename="../cli/ScanFormats.cpp" line="44"/>
        <source>Scanning machine numbers %1–%2 at %3 (--try-formats), %4 ms each…</source>
        <translation>%3 で局番 %1–%2 をスキャン中（--try-formats）、各 %4 ms…</translation>
    </message>
    <message>
        <location filename="../cli/ScanFormats.cpp" line="71"/>
        <source>Machine number %1 answered at %2: it is asked at that format from now on (--drive-format %1=%3).</source>
        <translation>局番 %1 が %2 で応答しました。以後はその形式で問い合わせます（--drive-format %1=%3）。</translation>
    </message>
    <message>
        <location filename="../cli/ScanFormats.cpp" line="99"/>
        <source>hint: %1 If one is on this bus, give its machine number its format with --drive-format ID=BAUD:FORMAT (e.g. 7=9600:8E1), or scan with --try-formats: %2 more passes, %3 more requests, about %4 s more.</source>
        <translation>ヒント: %1 このバスにそのようなドライブがある場合は、--drive-format ID=BAUD:FORMAT（例: 7=9600:8E1）でその局番の形式を指定するか、--try-formats でスキャンしてください: スキャン %2 回、要求 %3 件、約 %4 s 増えます。</translation>
    </message>
</context>
<context>
    <name>opentop::ScanProgress</name>
    <message>
        <location filename="../cli/ScanProgress.cpp" line="34"/>
        <source>scanning %1/%2 (%3 %), machine number %4, %5 found</source>
        <translation>スキャン中 %1/%2 (%3 %)、局番 %4、%5 台検出</translation>
    </message>
    <message>
        <location filename="../cli/ScanProgress.cpp" line="49"/>
        <source>scan: %1 % (%2 of %3 machine numbers), %4 found</source>
        <translation>スキャン: %1 %（%3 局番中 %2）、%4 台検出</translation>
    </message>
    <message>
        <location filename="../cli/ScanProgress.cpp" line="60"/>
        <source>scan: machine number %1 answered, identification failed: retrying (%2 of %3)…</source>
        <translation>スキャン: 局番 %1 は応答しましたが、識別に失敗しました: 再試行中 (%3 回中 %2 回目)…</translation>
    </message>
</context>
<context>
    <name>opentop::SerialEntry</name>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="28"/>
        <source>Scan or type the serial number, then Enter</source>
        <translation>シリアル番号をスキャンまたは入力し、Enter を押してください</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="29"/>
        <source>Cancel unit (Esc)</source>
        <translation>試験をキャンセル (Esc)</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="73"/>
        <source>Serial number NOT taken: %1.</source>
        <translation>シリアル番号は受け付けられませんでした: %1。</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="102"/>
        <source>Serial %1 was NOT taken: unit %2 is being tested. Scan it again once its verdict shows.</source>
        <translation>シリアル番号 %1 は受け付けられませんでした: ユニット %2 を検査中です。判定が表示されてから再度スキャンしてください。</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="104"/>
        <location filename="../ui/eol/SerialEntry.cpp" line="106"/>
        <source>another</source>
        <translation>別のユニット</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="105"/>
        <source>A serial number was NOT taken: %1. Unit %2 is being tested.</source>
        <translation>シリアル番号は受け付けられませんでした: %1。ユニット %2 を検査中です。</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="122"/>
        <source>Per-unit value</source>
        <translation>個別値</translation>
    </message>
    <message>
        <location filename="../ui/eol/SerialEntry.cpp" line="123"/>
        <source>Drive %1: %2 (%3–%4 %5)</source>
        <translation>ドライバ %1: %2 (%3–%4 %5)</translation>
    </message>
</context>
<context>
    <name>opentop::SerialLineFields</name>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="29"/>
        <source>Adapter switches itself</source>
        <translation>アダプタが自動切替</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="30"/>
        <source>Auto (kernel, else RTS)</source>
        <translation>自動（カーネル、不可なら RTS）</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="31"/>
        <source>Kernel RS-485 mode</source>
        <translation>カーネル RS-485 モード</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="32"/>
        <source>RTS from the program</source>
        <translation>プログラムによる RTS 制御</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="34"/>
        <source>Who switches the RS-485 transceiver between sending and receiving. USB–RS-485 adapters do it themselves; on-board RS-485 ports need the driver&apos;s RS-485 mode (kernel) or RTS switched by the program. The status bar says what the driver accepted.</source>
        <translation>RS-485 トランシーバの送信と受信を切り替えるもの。USB–RS-485 アダプタは自身で切り替えます。オンボードの RS-485 ポートでは、シリアルドライバの RS-485 モード（カーネル）か、プログラムによる RTS 切替が必要です。シリアルドライバが受け付けた設定はステータスバーに表示されます。</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="38"/>
        <source>RS-485 d&amp;irection:</source>
        <translation>RS-485 送受信切替(&amp;I):</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="43"/>
        <source>high while sending</source>
        <translation>送信中は High</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="44"/>
        <source>low while sending</source>
        <translation>送信中は Low</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="45"/>
        <source>The RTS level that enables the transceiver&apos;s driver</source>
        <translation>トランシーバの送信部を有効にする RTS レベル</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="50"/>
        <source>delay </source>
        <translation>遅延 </translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="51"/>
        <source> µs</source>
        <translation> µs</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="52"/>
        <source>default delay</source>
        <translation>既定の遅延</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="53"/>
        <source>Before and after sending. Default: the driver&apos;s own, or one character time from the program; the kernel rounds up to whole ms.</source>
        <translation>送信の前後に入れる遅延。既定: シリアルドライバ自身の遅延、またはプログラムによる 1 文字時間。カーネルは ms 単位に切り上げます。</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="58"/>
        <source>RTS le&amp;vel:</source>
        <translation>RTS レベル(&amp;V):</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="62"/>
        <source>&amp;Low latency (no 16 ms hold-back in USB adapters)</source>
        <translation>低レイテンシ（USB アダプタの 16 ms 保持なし）(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/connection/SerialLineFields.cpp" line="65"/>
        <source>Asks the driver to pass received bytes on at once. Many USB–serial chips otherwise hold them for up to 16 ms, which slows scans and polling.</source>
        <translation>受信したバイトをすぐに渡すようシリアルドライバに要求します。要求しないと、多くの USB–シリアル変換チップは最大 16 ms 保持するため、スキャンとポーリングが遅くなります。</translation>
    </message>
</context>
<context>
    <name>opentop::SerialLock</name>
    <message>
        <location filename="../model/session/SerialLock.cpp" line="39"/>
        <source>%1 = %2 prohibits configuration over the serial interface: OpenTOP may then no longer be able to change this drive&apos;s settings over the serial line it talks on. To undo it: write %1 = %3 again if the drive still accepts it; while it is not stored, switch the drive off and on; otherwise switch the controller to potentiometer/analog control, connect at 9600 bit/s, 8E1, address 1 and write %1 = %3 there.</source>
        <translation>%1 = %2 はシリアルインタフェース経由の設定を禁止します: その後、OpenTOP は通信中のシリアル回線でこのドライバの設定を変更できなくなる可能性があります。元に戻す方法: ドライバがまだ受け付ける場合は %1 = %3 を書き込み直します。保存されていなければドライバの電源を入れ直します。それ以外の場合は、コントローラをボリューム/アナログ制御に切り替え、9600 bit/s、8E1、アドレス 1 で接続して %1 = %3 を書き込みます。</translation>
    </message>
</context>
<context>
    <name>opentop::SerialRule</name>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="65"/>
        <source>no serial number</source>
        <translation>シリアル番号がありません</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="67"/>
        <source>a serial number has at most %1 characters; this one has %2</source>
        <translation>シリアル番号は最大 %1 文字です。このシリアル番号は %2 文字です</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="71"/>
        <source>a serial number may not hold control characters, format characters or line breaks; character %1 is %2</source>
        <translation>シリアル番号に制御文字、書式文字や改行は使えません。%1 文字目は %2 です</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="75"/>
        <source>serial number &quot;%1&quot; begins or ends with white space; a serial number is tested exactly as given</source>
        <translation>シリアル番号 &quot;%1&quot; の先頭または末尾に空白があります。シリアル番号は入力されたとおりに検査されます</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="85"/>
        <source>serial number &quot;%1&quot; does not match the recipe&apos;s serial pattern %2</source>
        <translation>シリアル番号 &quot;%1&quot; はレシピのシリアル番号パターン %2 に一致しません</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="87"/>
        <source>serial number &quot;%1&quot; does not match the recipe&apos;s serial pattern %2 (e.g. %3)</source>
        <translation>シリアル番号 &quot;%1&quot; はレシピのシリアル番号パターン %2 に一致しません (例: %3)</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="104"/>
        <source>&quot;serialPattern&quot; has %1 characters; at most %2 are allowed</source>
        <translation>&quot;serialPattern&quot; は %1 文字です。最大 %2 文字までです</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="108"/>
        <source>&quot;serialPattern&quot; may not hold control characters, format characters or line breaks (no serial number holds one); character %1 is %2</source>
        <translation>&quot;serialPattern&quot; に制御文字、書式文字や改行は使えません (シリアル番号には含まれません)。%1 文字目は %2 です</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="115"/>
        <source>&quot;serialPattern&quot; %1 is not a valid regular expression: %2 at character %3</source>
        <translation>&quot;serialPattern&quot; %1 は正しい正規表現ではありません: %3 文字目で %2</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="121"/>
        <source>&quot;serialPattern&quot; %1 cannot be matched against a whole serial number</source>
        <translation>&quot;serialPattern&quot; %1 はシリアル番号全体と照合できません</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="127"/>
        <source>&quot;serialExample&quot; needs a &quot;serialPattern&quot; that it matches</source>
        <translation>&quot;serialExample&quot; には一致する &quot;serialPattern&quot; が必要です</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="130"/>
        <source>&quot;serialExample&quot;: %1</source>
        <translation>&quot;serialExample&quot;: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="140"/>
        <source>any, at most %1 characters</source>
        <translation>任意、最大 %1 文字</translation>
    </message>
    <message>
        <location filename="../model/eol/SerialRule.cpp" line="143"/>
        <source>%1 (e.g. %2)</source>
        <translation>%1 (例: %2)</translation>
    </message>
</context>
<context>
    <name>opentop::SetCommand</name>
    <message>
        <location filename="../cli/SetCommand.cpp" line="43"/>
        <source>Write parameters by name, validated, read back and verified</source>
        <translation>パラメータを名前で書き込み、検証・読み戻し・照合します</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="53"/>
        <source>Write registers by address: ADDR=VALUE (repeatable; VALUE,VALUE... with --fc 16).</source>
        <translation>アドレスでレジスタに書き込みます: ADDR=VALUE（複数指定可。--fc 16 では VALUE,VALUE...）。</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="54"/>
        <source>ADDR=VALUE</source>
        <translation>ADDR=VALUE</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="55"/>
        <source>Function code for --raw writes: 6 (default) or 16.</source>
        <translation>--raw 書込みのファンクションコード: 6（既定）または 16。</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="55"/>
        <source>FC</source>
        <translation>FC</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="64"/>
        <source>error: usage: set ID NAME=VALUE... (e.g. set 1 spno2.accel=2.5), or set ID --raw ADDR=VALUE</source>
        <translation>エラー: 使い方: set ID NAME=VALUE...（例: set 1 spno2.accel=2.5）、または set ID --raw ADDR=VALUE</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="76"/>
        <source>error: &quot;%1&quot; is not NAME=VALUE</source>
        <translation>エラー: &quot;%1&quot; は NAME=VALUE ではありません</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="83"/>
        <location filename="../cli/SetCommand.cpp" line="92"/>
        <location filename="../cli/SetCommand.cpp" line="108"/>
        <source>error: %1</source>
        <translation>エラー: %1</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="105"/>
        <location filename="../cli/SetCommand.cpp" line="117"/>
        <source>warning: %1</source>
        <translation>警告: %1</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="50"/>
        <source>Confirm commands that move a motor, reset, erase, initialise or store, and setting the serial configuration lock.</source>
        <translation>モータの運転、リセット、消去、初期化、保存を行うコマンドと、シリアル設定ロックの設定を確定します。</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="149"/>
        <source>next: %1</source>
        <translation>次に: %1</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="151"/>
        <source>next: opentop-cli --baud %1 --parity %2 --stop-bits %3 ... (the factory line settings)</source>
        <translation>次に: opentop-cli --baud %1 --parity %2 --stop-bits %3 ...（工場出荷時の通信設定）</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="196"/>
        <source>Parameter</source>
        <translation>パラメータ</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="196"/>
        <source>Value</source>
        <translation>値</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="196"/>
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="202"/>
        <source>written, verified</source>
        <translation>書込み済み、照合済み</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="204"/>
        <source>written, not verified: %1</source>
        <translation>書込み済み、未確認: %1</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="205"/>
        <source>written (command, not readable)</source>
        <translation>書込み済み（コマンド、読出し不可）</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="207"/>
        <source>not confirmed (%1): the drive may or may not hold it; &quot;get&quot; reads it back</source>
        <translation>未確認 (%1): ドライバがその値を保持しているかどうか不明です。&quot;get&quot; で読み戻してください</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="218"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../cli/SetCommand.cpp" line="225"/>
        <source>note: the drive uses %1 from its next power-up on: switch the drive off and on, then connect with the new setting (--baud, --parity)</source>
        <translation>注: ドライバは次回の電源投入から %1 を使用します: ドライバの電源を入れ直し、新しい設定（--baud、--parity）で接続してください</translation>
    </message>
</context>
<context>
    <name>opentop::SetRaw</name>
    <message>
        <location filename="../cli/SetRaw.cpp" line="30"/>
        <source>error: --fc for raw writes is 6 or 16</source>
        <translation>エラー: raw 書込みの --fc は 6 または 16 です</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="56"/>
        <source>error: &quot;%1&quot; is not ADDR=VALUE (0x.. or decimal, 0–65535; several values, comma separated, only with --fc 16)</source>
        <translation>エラー: &quot;%1&quot; は ADDR=VALUE ではありません（0x.. または 10 進、0–65535。カンマ区切りの複数値は --fc 16 の場合のみ）</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="73"/>
        <source>error: 0x%1 is not a register the profile knows; add --yes to write it anyway; nothing was written</source>
        <translation>エラー: 0x%1 はプロファイルにないレジスタです。それでも書き込むには --yes を付けてください。何も書き込んでいません</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="83"/>
        <location filename="../cli/SetRaw.cpp" line="128"/>
        <source>error: %1; nothing was written</source>
        <translation>エラー: %1。何も書き込んでいません</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="84"/>
        <source>%1 is a %2 command; add --yes</source>
        <translation>%1 は %2 コマンドです。--yes を付けてください</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="91"/>
        <source>error: the write covers part of %1; add --yes to write it anyway; nothing was written</source>
        <translation>エラー: この書込みは %1 の一部にかかります。それでも書き込むには --yes を付けてください。何も書き込んでいません</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="141"/>
        <source>Address</source>
        <translation>アドレス</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="141"/>
        <source>Written</source>
        <translation>書込み</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="141"/>
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="174"/>
        <source>written</source>
        <translation>書込み済み</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="176"/>
        <source>written, verified</source>
        <translation>書込み済み、照合済み</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="178"/>
        <source>written, but reads back differently</source>
        <translation>書き込みましたが、読み戻した値が異なります</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="181"/>
        <source>written (not readable back: %1)</source>
        <translation>書込み済み（読み戻し不可: %1）</translation>
    </message>
    <message>
        <location filename="../cli/SetRaw.cpp" line="193"/>
        <source>Also written to %1 (communication group); not read back: no parameter of the profile</source>
        <translation>%1 にも書き込みました（通信グループ）。読み戻しなし: プロファイルのパラメータではありません</translation>
    </message>
</context>
<context>
    <name>opentop::SettingsWrite</name>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="29"/>
        <source>%1 is given twice (%2=%3 and %4); give each setting once; nothing written</source>
        <translation>%1 が 2 回指定されています（%2=%3 と %4）。各設定は 1 回だけ指定してください。何も書き込んでいません</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="76"/>
        <source>%1 has no parameter &quot;%2&quot;; see &quot;opentop-cli params --family %1&quot;</source>
        <translation>%1 にパラメータ &quot;%2&quot; はありません。&quot;opentop-cli params --family %1&quot; を参照してください</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="80"/>
        <source>%1 is read-only</source>
        <translation>%1 は読出し専用です</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="83"/>
        <source>%1 is a %2 command; add --yes to send it</source>
        <translation>%1 は %2 コマンドです。送信するには --yes を付けてください</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="105"/>
        <source>cannot read %1 to check the values; nothing written</source>
        <translation>値をチェックするための %1 を読み出せません。何も書き込んでいません</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="157"/>
        <source>Add --yes to set it.</source>
        <translation>設定するには --yes を付けてください。</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="229"/>
        <source>interrupted as it was sent</source>
        <translation>送信中に中断</translation>
    </message>
    <message>
        <location filename="../model/session/SettingsWrite.cpp" line="231"/>
        <source>not written (interrupted)</source>
        <translation>未書込み（中断）</translation>
    </message>
</context>
<context>
    <name>opentop::ShiftPlan</name>
    <message>
        <location filename="../model/eol/ShiftPlan.cpp" line="30"/>
        <source>&quot;%1&quot; is not a time of day such as 06:00</source>
        <translation>&quot;%1&quot; は 06:00 のような時刻ではありません</translation>
    </message>
    <message>
        <location filename="../model/eol/ShiftPlan.cpp" line="35"/>
        <source>shift starts must be in order from the day&apos;s first: %1</source>
        <translation>シフト開始時刻は 1 日の最初から順に指定してください: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/ShiftPlan.cpp" line="42"/>
        <source>no shift start given; e.g. 06:00,14:00,22:00</source>
        <translation>シフト開始時刻が指定されていません。例: 06:00,14:00,22:00</translation>
    </message>
</context>
<context>
    <name>opentop::ShortcutsDialog</name>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="63"/>
        <source>Main window</source>
        <translation>メインウィンドウ</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="36"/>
        <source>Everywhere, dialogs included</source>
        <translation>すべての場所（ダイアログを含む）</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="37"/>
        <source>STOP ALL (stop every drive on the bus)</source>
        <translation>全停止（バス上の全ドライバを停止）</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="73"/>
        <source>Keyboard shortcuts</source>
        <translation>キーボードショートカット</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="77"/>
        <source>Where</source>
        <translation>場所</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="77"/>
        <source>Command</source>
        <translation>コマンド</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="77"/>
        <source>Keys</source>
        <translation>キー</translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="87"/>
        <source> or </source>
        <translation> または </translation>
    </message>
    <message>
        <location filename="../ui/help/ShortcutsDialog.cpp" line="96"/>
        <source>STOP ALL&apos;s keys work in every window of the program, also while a dialog is open.</source>
        <translation>全停止のキーは、ダイアログ表示中も含め、プログラムのすべてのウィンドウで有効です。</translation>
    </message>
</context>
<context>
    <name>opentop::SimApp</name>
    <message>
        <location filename="../sim/SimApp.cpp" line="77"/>
        <source>opentop-sim: %1@%2 talks %3 (its own line settings): it answers only frames sent in that format</source>
        <translation>opentop-sim: %1@%2 は %3（自身の回線設定）で通信します。その形式で送られたフレームにのみ応答します</translation>
    </message>
    <message>
        <location filename="../sim/SimApp.cpp" line="83"/>
        <source>opentop-sim: warning: %1@%2 cannot use %3 %4 and will not answer</source>
        <translation>opentop-sim: 警告: %1@%2 は %3 %4 を使用できないため応答しません</translation>
    </message>
    <message>
        <location filename="../sim/SimApp.cpp" line="97"/>
        <source>opentop-sim: --defect %1:%2: no drive with machine number %1 on the bus %3</source>
        <translation>opentop-sim: --defect %1:%2: バス %3 に局番 %1 のドライバはありません</translation>
    </message>
    <message>
        <location filename="../sim/SimApp.cpp" line="104"/>
        <source>opentop-sim: --defect %1 (%2@%1): %3</source>
        <translation>opentop-sim: --defect %1 (%2@%1): %3</translation>
    </message>
    <message>
        <location filename="../sim/SimApp.cpp" line="138"/>
        <source>the port is unplugged already</source>
        <translation>ポートはすでに切断されています</translation>
    </message>
    <message>
        <location filename="../sim/SimApp.cpp" line="140"/>
        <source>unplugged</source>
        <translation>切断しました</translation>
    </message>
    <message>
        <location filename="../sim/SimApp.cpp" line="167"/>
        <source>error: %1</source>
        <translation>エラー: %1</translation>
    </message>
</context>
<context>
    <name>opentop::SimBackdoor</name>
    <message>
        <location filename="../sim/SimBackdoor.cpp" line="17"/>
        <source>usage: set ID ADDR VALUE [fc]</source>
        <translation>使い方: set ID ADDR VALUE [fc]</translation>
    </message>
    <message>
        <location filename="../sim/SimBackdoor.cpp" line="18"/>
        <source>usage: get ID ADDR [fc]</source>
        <translation>使い方: get ID ADDR [fc]</translation>
    </message>
    <message>
        <location filename="../sim/SimBackdoor.cpp" line="21"/>
        <source>address must be 0..0xFFFF, got &apos;%1&apos;</source>
        <translation>アドレスは 0..0xFFFF でなければなりません（指定値 &apos;%1&apos;）</translation>
    </message>
    <message>
        <location filename="../sim/SimBackdoor.cpp" line="27"/>
        <source>function must be 3, 4 or 6 (write-only), got &apos;%1&apos;</source>
        <translation>ファンクションは 3、4、6（書込み専用）のいずれかでなければなりません（指定値 &apos;%1&apos;）</translation>
    </message>
    <message>
        <location filename="../sim/SimBackdoor.cpp" line="40"/>
        <source>value must be -32768..65535, got &apos;%1&apos;</source>
        <translation>値は -32768..65535 でなければなりません（指定値 &apos;%1&apos;）</translation>
    </message>
</context>
<context>
    <name>opentop::SimBackend</name>
    <message>
        <location filename="../sim/SimBackend.cpp" line="24"/>
        <source>no simulated bus</source>
        <translation>シミュレーションバスがありません</translation>
    </message>
    <message>
        <location filename="../sim/SimBackend.cpp" line="47"/>
        <source>the simulated bus is not open</source>
        <translation>シミュレーションバスが開いていません</translation>
    </message>
    <message>
        <location filename="../sim/SimBackend.cpp" line="53"/>
        <source>the simulated adapter was unplugged</source>
        <translation>シミュレーションのアダプタが取り外されました</translation>
    </message>
    <message>
        <location filename="../sim/SimBackend.cpp" line="85"/>
        <source>interrupted while waiting</source>
        <translation>待機中に中断しました</translation>
    </message>
    <message>
        <location filename="../sim/SimBackend.cpp" line="92"/>
        <source>no reply within %1 ms</source>
        <translation>%1 ms 以内に応答がありません</translation>
    </message>
</context>
<context>
    <name>opentop::SimBus</name>
    <message>
        <location filename="../sim/SimBus.cpp" line="38"/>
        <source>unknown device type &apos;%1&apos;; known: %2</source>
        <translation>不明なデバイスタイプ &apos;%1&apos;。既知: %2</translation>
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
        <translation>局番 %1 のデバイスはありません</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="118"/>
        <source>baud=%1: this drive talks at %2 bit/s</source>
        <translation>baud=%1: このドライブの速度は %2 bit/s です</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="126"/>
        <source>format=%1: this drive offers %2 only</source>
        <translation>format=%1: このドライブは %2 のみです</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="132"/>
        <source>this simulated drive has no line settings of its own</source>
        <translation>このシミュレーションのドライブには自身の回線設定がありません</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="145"/>
        <source>machine number %1 is outside 1..247</source>
        <translation>局番 %1 が 1..247 の範囲外です</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="146"/>
        <source>machine number %1 is used twice</source>
        <translation>局番 %1 が 2 回使用されています</translation>
    </message>
    <message>
        <location filename="../sim/SimBus.cpp" line="317"/>
        <source>no device with machine number %1 (bus: %2)</source>
        <translation>局番 %1 のデバイスがありません（バス: %2）</translation>
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
        <translation>コマンド:
  help                      このテキスト
  list                      デバイスとその状態
  alarm ID CODE             アラームを発生させる (DBU)
  warning ID CODE           警告を発生させる。CODE 0 で解除 (DBU)
  load ID PERCENT           負荷率 (DBU) または電流 (DC) に加算
  vr ID RPM                 Ext-VR 速度。SPno1 で使用 (DBU)
  input ID MASK             入力端子: X0..X3 (DBU)、SQ1 SQ2 DE (DC)
  ignore-stop ID on|off     停止コマンドに応答するが運転を続ける (DBU)
  power-cycle ID            デバイスの電源をオフ/オンする
  get ID ADDR [fc]          レジスタを表示 (fc 3、4、書込み専用は 6)
  set ID ADDR VALUE [fc]    チェックなしでレジスタを変更
  defect ID DEFECT[,...]    ドライバに不具合を追加（--help を参照）。例:
                            defect 3 max_speed=800 または defect 4 alarm=0x07@2s
  defect ID clear           ドライバの不具合をなくす
  defects                   ドライバの不具合一覧
  motor ID [KEY=VALUE ...]  DC コントローラのモータと負荷を表示・変更。例:
                            motor 7 load=0.05 inertia=3e-4（--motor を参照）
  unplug                    クライアントの pty を閉じる（アダプタ抜去）
  replug                    同じシンボリックリンクの先に新しい pty を作成
  quit                      シミュレータを停止</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="66"/>
        <source>bye</source>
        <translation>終了します</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="71"/>
        <source>%1 needs the pty server (--pty)</source>
        <translation>%1 には pty サーバ (--pty) が必要です</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="82"/>
        <source>, defects: %1</source>
        <translation>、不具合: %1</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="95"/>
        <source>no drive has defects</source>
        <translation>不具合のあるドライバはありません</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="101"/>
        <source>unknown command &apos;%1&apos;; type help for the list</source>
        <translation>不明なコマンド &apos;%1&apos;。help と入力すると一覧を表示します</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="105"/>
        <source>usage: %1 ID ...; ID is a machine number on the bus (%2)</source>
        <translation>使い方: %1 ID ...。ID はバス上の局番です (%2)</translation>
    </message>
    <message>
        <location filename="../sim/SimConsole.cpp" line="111"/>
        <source>&apos;%1&apos; is not a machine number; the bus has %2</source>
        <translation>&apos;%1&apos; は局番ではありません。バス上の局番: %2</translation>
    </message>
</context>
<context>
    <name>opentop::SimDefectSpec</name>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="45"/>
        <source>firmware=MAJOR.MINOR (e.g. firmware=1.4), max_speed=N (e.g. max_speed=800), stall, load=+N, load=-N or load=xF (e.g. load=+40, load=x1.5), alarm=CODE@TIME (e.g. alarm=0x07@1500ms, alarm=overload@2s; DC: alarm=stall@1s), nostick=PARAM, nostore=PARAM (a parameter name or register address, e.g. nostick=spno2.speed, nostore=0x0081), turnaround=MS (e.g. turnaround=14), clear</source>
        <translation>firmware=MAJOR.MINOR（例: firmware=1.4）、max_speed=N（例: max_speed=800）、stall、load=+N、load=-N または load=xF（例: load=+40、load=x1.5）、alarm=CODE@TIME（例: alarm=0x07@1500ms、alarm=overload@2s。DC: alarm=stall@1s）、nostick=PARAM、nostore=PARAM（パラメータ名またはレジスタアドレス。例: nostick=spno2.speed、nostore=0x0081）、turnaround=MS（例: turnaround=14）、clear</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="123"/>
        <source>unknown defect &quot;%1&quot;; allowed: %2</source>
        <translation>不明な不具合 &quot;%1&quot;。使用可能: %2</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="126"/>
        <source>&quot;%1&quot; needs a value: %2=...</source>
        <translation>&quot;%1&quot; には値が必要です: %2=...</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="128"/>
        <source>&quot;%1&quot; takes no value; write %2</source>
        <translation>&quot;%1&quot; は値を取りません。%2 と記述してください</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="141"/>
        <source>firmware=%1: write MAJOR.MINOR with each 0..255, e.g. firmware=1.4</source>
        <translation>firmware=%1: MAJOR.MINOR（各 0..255）の形式で記述してください。例: firmware=1.4</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="148"/>
        <source>max_speed=%1: write a whole number 0..%2, e.g. max_speed=800</source>
        <translation>max_speed=%1: 0..%2 の整数を記述してください。例: max_speed=800</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="158"/>
        <source>load=%1: a factor is x0.1..x10, e.g. load=x1.5</source>
        <translation>load=%1: 係数は x0.1..x10 です。例: load=x1.5</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="163"/>
        <source>load=%1: an offset is -200..+200, e.g. load=+40</source>
        <translation>load=%1: オフセットは -200..+200 です。例: load=+40</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="166"/>
        <source>load=%1: write load=+N, load=-N (an offset) or load=xF (a factor), e.g. load=+40 or load=x1.5</source>
        <translation>load=%1: load=+N、load=-N（オフセット）または load=xF（係数）の形式で記述してください。例: load=+40 または load=x1.5</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="175"/>
        <source>alarm=%1: write alarm=CODE@TIME, e.g. alarm=0x07@1500ms or alarm=overload@2s</source>
        <translation>alarm=%1: alarm=CODE@TIME の形式で記述してください。例: alarm=0x07@1500ms または alarm=overload@2s</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="180"/>
        <source>alarm=%1: the time after the start is 0..3600 s, written 1500ms, 1.5s or 1500 (ms)</source>
        <translation>alarm=%1: 運転開始後の時間は 0..3600 s です。1500ms、1.5s または 1500 (ms) の形式で記述してください</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="189"/>
        <source>turnaround=%1: write the answer delay in ms, 0..1000, e.g. turnaround=14</source>
        <translation>turnaround=%1: 応答遅延を ms で 0..1000 の範囲で記述してください。例: turnaround=14</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="194"/>
        <source>%1=%2: name a parameter (e.g. spno2.speed) or a register address (e.g. 0x1102)</source>
        <translation>%1=%2: パラメータ名（例: spno2.speed）またはレジスタアドレス（例: 0x1102）を指定してください</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="210"/>
        <source>no defect given; allowed: %1</source>
        <translation>不具合が指定されていません。使用可能: %1</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="216"/>
        <source>empty item in &quot;%1&quot;</source>
        <translation>&quot;%1&quot; に空の項目があります</translation>
    </message>
    <message>
        <location filename="../sim/SimDefectSpec.cpp" line="234"/>
        <source>&quot;%1&quot;: write ID:DEFECT[,DEFECT...] with ID the machine number 1..247, e.g. 3:firmware=1.4 or 5:max_speed=800,load=+40</source>
        <translation>&quot;%1&quot;: ID:DEFECT[,DEFECT...] の形式で記述してください（ID は局番 1..247）。例: 3:firmware=1.4 または 5:max_speed=800,load=+40</translation>
    </message>
</context>
<context>
    <name>opentop::SimDefects</name>
    <message>
        <location filename="../sim/SimDefects.cpp" line="71"/>
        <source>a %1 reports no firmware version</source>
        <translation>%1 はファームウェアバージョンを通知しません</translation>
    </message>
    <message>
        <location filename="../sim/SimDefects.cpp" line="83"/>
        <source>alarm=%1: a %2 has no alarm codes; its protection is the stall stop: write alarm=stall@TIME</source>
        <translation>alarm=%1: %2 にはアラームコードがありません。保護機能はストール停止です: alarm=stall@TIME と記述してください</translation>
    </message>
    <message>
        <location filename="../sim/SimDefects.cpp" line="99"/>
        <source>alarm=%1: not an alarm of a %2; allowed: %3</source>
        <translation>alarm=%1: %2 のアラームではありません。使用可能: %3</translation>
    </message>
    <message>
        <location filename="../sim/SimDefects.cpp" line="110"/>
        <source>%1=%2: no writable parameter of a %3 has this name or address; e.g. %4</source>
        <translation>%1=%2: %3 にこの名前またはアドレスの書込み可能なパラメータはありません。例: %4</translation>
    </message>
</context>
<context>
    <name>opentop::SimDevice</name>
    <message>
        <location filename="../sim/SimDevice.cpp" line="248"/>
        <source>missing command</source>
        <translation>コマンドがありません</translation>
    </message>
    <message>
        <location filename="../sim/SimDevice.cpp" line="257"/>
        <source>slave %1 power cycled</source>
        <translation>局番 %1 の電源を再投入しました</translation>
    </message>
    <message>
        <location filename="../sim/SimDevice.cpp" line="299"/>
        <source>usage: defect ID DEFECT[,DEFECT...] or defect ID clear; DEFECT: %1</source>
        <translation>使い方: defect ID DEFECT[,DEFECT...] または defect ID clear。DEFECT: %1</translation>
    </message>
    <message>
        <location filename="../sim/SimDevice.cpp" line="306"/>
        <source>slave %1 defects: %2</source>
        <translation>局番 %1 の不具合: %2</translation>
    </message>
    <message>
        <location filename="../sim/SimDevice.cpp" line="308"/>
        <source>none</source>
        <translation>なし</translation>
    </message>
    <message>
        <location filename="../sim/SimDevice.cpp" line="313"/>
        <source>&apos;%1&apos; is not supported by a %2 device</source>
        <translation>&apos;%1&apos; は %2 デバイスではサポートされていません</translation>
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
        <translation>使い方: opentop-sim --devices SPEC [options]
疑似端末上、または Modbus TCP ゲートウェイとして Modbus RTU ドライバをシミュレートします。

  --devices SPEC     デバイスと局番。例: dbu200@1,dbu400@150,dcpid@7
                     ドライブ自身の回線設定は中かっこ内に。例:
                     dcpid@7{format=8E1,baud=19200}: その形式で送られた
                     フレームのみ受信（pty はクライアントの速度とパリティを渡す）
  --pty [PATH]       pty で提供（既定）。PATH: このシンボリックリンクも作成
  --tcp HOST:PORT    Modbus TCP で提供（HOST の既定は 127.0.0.1、PORT 0: 任意）
  --baud N           回線タイミングとデバイス設定の通信速度 (19200)。ドライブは
                     自身の速度とパリティのフレームのみ受信
  --parity N|E|O     回線のパリティ (N): 自身の設定を持たないドライブは
                     --baud と --parity に設定される
  --wire-timing      --baud の実回線と同様に応答を遅延させる
  --turnaround MS    --wire-timing 時のデバイスのターンアラウンド (2)
  --half-duplex      --wire-timing と併用: 回線上で要求が応答と重なると
                     両方が化け、応答から 3.5 文字以内の要求は失われる
  --faults LIST      例: drop=0.02,crc=0.01,late=0.01,busy=0.01,late_ms=1000
  --seed N           フォールト注入のシード (1)
  --defect ID:LIST   ドライバ ID の不具合（複数指定可）。LIST の要素:
                       firmware=MAJOR.MINOR  識別時にこのバージョンを通知
                       max_speed=N           モータは N で飽和 (DBU r/min、
                                             DC 転流回数/s)、負荷大
                       stall                 モータが回転しない、負荷大
                       load=+N|-N|xF         負荷率 (DC: 電流 %) にオフセットまたは倍率
                       alarm=CODE@TIME       運転して TIME 後にアラーム。例:
                                             0x07@1500ms、overload@2s (DC: stall@1s)
                       nostick=PARAM         書込みに応答するが、旧値のまま
                       nostore=PARAM         次の電源再投入で値が消える
                     例: --defect 3:firmware=1.4 --defect 5:max_speed=800,load=+40
  --motor LIST       DC コントローラのモータと負荷。例: inertia=2e-4,load=0.05。
                     supply (V)、resistance (ohm)、no_load（フルデューティ時の 1/s）、
                     commutations（1 回転あたりの転流回数）、inertia (kg m2)、viscous
                     (N m s/rad)、coulomb (N m)、load (N m)、gate (ms)、tacho (V s)
  --quiet            stderr にフレームトレースを出力しない
  --lang CODE        メッセージの言語: en, zh_TW, zh_CN, ko, ja
  --help             このテキスト
  --version          プログラムのバージョン

&quot;pty: PATH&quot;（および &quot;tcp: HOST:PORT&quot;）を出力した後、&quot;ready&quot; を出力します。コンソールコマンドを
標準入力から読み取ります (help と入力)。SIGINT、SIGTERM、quit で停止します。
</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="92"/>
        <source>--lang needs a language code such as ko</source>
        <translation>--lang には ko などの言語コードが必要です</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="95"/>
        <source>--devices needs a device list such as dbu200@1,dcpid@7</source>
        <translation>--devices には dbu200@1,dcpid@7 のようなデバイスリストが必要です</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="104"/>
        <source>--tcp needs HOST:PORT, e.g. 127.0.0.1:5020</source>
        <translation>--tcp には HOST:PORT が必要です。例: 127.0.0.1:5020</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="110"/>
        <source>--tcp needs HOST:PORT with PORT 0..65535, got &apos;%1&apos;</source>
        <translation>--tcp には PORT が 0..65535 の HOST:PORT が必要です（指定値 &apos;%1&apos;）</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="122"/>
        <source>--baud must be one of %1, got &apos;%2&apos;</source>
        <translation>--baud は %1 のいずれかでなければなりません（指定値 &apos;%2&apos;）</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="129"/>
        <source>--parity must be N, E or O, got &apos;%1&apos;</source>
        <translation>--parity は N、E、O のいずれかでなければなりません（指定値 &apos;%1&apos;）</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="139"/>
        <source>--turnaround must be 0..1000 ms, got &apos;%1&apos;</source>
        <translation>--turnaround は 0..1000 ms でなければなりません（指定値 &apos;%1&apos;）</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="143"/>
        <source>--faults needs a list such as drop=0.02,crc=0.01</source>
        <translation>--faults には drop=0.02,crc=0.01 のようなリストが必要です</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="147"/>
        <source>--faults: %1</source>
        <translation>--faults: %1</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="153"/>
        <source>--seed must be a whole number 0..4294967295, got &apos;%1&apos;</source>
        <translation>--seed は 0..4294967295 の整数でなければなりません（指定値 &apos;%1&apos;）</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="157"/>
        <source>--defect needs ID:DEFECT[,DEFECT...], e.g. 3:firmware=1.4; DEFECT: %1</source>
        <translation>--defect には ID:DEFECT[,DEFECT...] が必要です。例: 3:firmware=1.4。DEFECT: %1</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="164"/>
        <source>--defect: %1</source>
        <translation>--defect: %1</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="168"/>
        <source>--motor needs a list such as inertia=2e-4,load=0.05</source>
        <translation>--motor には inertia=2e-4,load=0.05 のようなリストが必要です</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="172"/>
        <source>--motor: %1</source>
        <translation>--motor: %1</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="177"/>
        <source>unknown argument &apos;%1&apos;; options: --devices, --pty, --tcp, --baud, --parity, --wire-timing, --half-duplex, --turnaround, --faults, --seed, --defect, --motor, --quiet, --help, --version</source>
        <translation>不明な引数 &apos;%1&apos;。オプション: --devices, --pty, --tcp, --baud, --parity, --wire-timing, --half-duplex, --turnaround, --faults, --seed, --defect, --motor, --quiet, --help, --version</translation>
    </message>
    <message>
        <location filename="../sim/SimOptions.cpp" line="186"/>
        <source>--devices SPEC is required, e.g. --devices dbu200@1,dcpid@7</source>
        <translation>--devices SPEC は必須です。例: --devices dbu200@1,dcpid@7</translation>
    </message>
</context>
<context>
    <name>opentop::SpeedDisplay</name>
    <message>
        <location filename="../model/profile/SpeedDisplay.cpp" line="90"/>
        <source>speed display settings not known: %1</source>
        <translation>速度表示の設定が不明です: %1</translation>
    </message>
    <message>
        <location filename="../model/profile/SpeedDisplay.cpp" line="92"/>
        <source>speed display unit code %1 is unknown (0–3)</source>
        <translation>速度表示の単位コード %1 は不明です (0–3)</translation>
    </message>
    <message>
        <location filename="../model/profile/SpeedDisplay.cpp" line="94"/>
        <source>speed display ratios must be positive (reduction %1, increase %2)</source>
        <translation>速度表示の比率は正の値でなければなりません（減速比 %1、増速比 %2）</translation>
    </message>
    <message>
        <location filename="../model/profile/SpeedDisplay.cpp" line="98"/>
        <source>speed display decimals %1 outside 0–3</source>
        <translation>速度表示の小数桁数 %1 が 0–3 の範囲外です</translation>
    </message>
</context>
<context>
    <name>opentop::SpeedUnitsPage</name>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="36"/>
        <source>Speed display</source>
        <translation>速度表示</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="52"/>
        <source>Unit shown</source>
        <translation>表示単位</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="53"/>
        <source>&amp;Unit:</source>
        <translation>単位(&amp;U):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="54"/>
        <source>Reduction r&amp;atio:</source>
        <translation>減速比(&amp;A):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="55"/>
        <source>&amp;Increasing ratio:</source>
        <translation>増速比(&amp;I):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="60"/>
        <source>Linear speed</source>
        <translation>線速度</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="61"/>
        <source>Roller diameter for &amp;yd/min:</source>
        <translation>yd/min 用ローラ径(&amp;Y):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="62"/>
        <source>Roller diameter for &amp;m/min:</source>
        <translation>m/min 用ローラ径(&amp;M):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="65"/>
        <source>Time for a distance</source>
        <translation>距離あたりの時間</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="66"/>
        <source>Roller &amp;diameter:</source>
        <translation>ローラ径(&amp;D):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="67"/>
        <source>Dis&amp;tance:</source>
        <translation>距離(&amp;T):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="68"/>
        <source>Distance u&amp;nit:</source>
        <translation>距離単位(&amp;N):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="69"/>
        <source>Time &amp;format (min = m:ss):</source>
        <translation>時間形式 (min = m:ss)(&amp;F):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="72"/>
        <source>Display</source>
        <translation>表示</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="73"/>
        <source>D&amp;ecimals (0–3):</source>
        <translation>小数桁数 (0–3)(&amp;E):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="74"/>
        <source>U&amp;pdate time:</source>
        <translation>更新時間(&amp;P):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="78"/>
        <source>Display corrections (motor r/min)</source>
        <translation>表示補正（モータ r/min）</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="79"/>
        <source>ro-&amp;0, 250 (300)–500 r/min:</source>
        <translation>ro-&amp;0, 250 (300)–500 r/min:</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="79"/>
        <source>ro-&amp;1, 501–1000 r/min:</source>
        <translation>ro-&amp;1, 501–1000 r/min:</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="80"/>
        <source>ro-&amp;2, 1001–2000 r/min:</source>
        <translation>ro-&amp;2, 1001–2000 r/min:</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="80"/>
        <source>ro-&amp;3, 2001–3000 r/min:</source>
        <translation>ro-&amp;3, 2001–3000 r/min:</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="85"/>
        <source>Preview of the drive&apos;s display</source>
        <translation>ドライバ表示のプレビュー</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="88"/>
        <source> r/min</source>
        <translation> r/min</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="89"/>
        <source>Motor speed for the preview</source>
        <translation>プレビュー用のモータ速度</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="90"/>
        <source>Motor &amp;speed:</source>
        <translation>モータ速度(&amp;S):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="93"/>
        <source>Forward</source>
        <translation>正転</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="94"/>
        <source>Reverse (shown with “-”)</source>
        <translation>逆転（“-” 付きで表示）</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="95"/>
        <source>Dire&amp;ction:</source>
        <translation>回転方向(&amp;C):</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="110"/>
        <source>Drive shows:</source>
        <translation>ドライバ表示:</translation>
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
        <translation>ドライバ表示 %1 %2</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="259"/>
        <source>Section ro-%1: correction %2 r/min, shaft speed %3 r/min.</source>
        <translation>区間 ro-%1: 補正 %2 r/min、軸速度 %3 r/min。</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="264"/>
        <source>%1 has more digits than the drive&apos;s %2-digit display can show.</source>
        <translation>%1 はドライバの %2 桁表示の桁数を超えています。</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="268"/>
        <source>Computed %1 %2; the %3-digit display drops the decimals that do not fit.</source>
        <translation>計算値 %1 %2。%3 桁表示では入りきらない小数部は表示されません。</translation>
    </message>
    <message>
        <location filename="../ui/pages/SpeedUnitsPage.cpp" line="275"/>
        <source>Includes edits not yet written.</source>
        <translation>未書込みの編集を含みます。</translation>
    </message>
</context>
<context>
    <name>opentop::SpnoSelector</name>
    <message>
        <location filename="../ui/run/SpnoSelector.cpp" line="29"/>
        <source>The running data that Select running data sends; &quot;The drive now&quot; shows the running data the drive runs</source>
        <translation>「運転データを選択」で送信する運転データです。ドライバが実行中の運転データは「現在のドライバ」に表示されます</translation>
    </message>
    <message>
        <location filename="../ui/run/SpnoSelector.cpp" line="70"/>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <location filename="../ui/run/SpnoSelector.cpp" line="84"/>
        <source>The running data that Select running data sends. The drive reported SPno%1 at %2; &quot;The drive now&quot; shows what it runs now.</source>
        <translation>「運転データを選択」で送信する運転データです。ドライバは %2 に SPno%1 と報告しました。現在の運転データは「現在のドライバ」に表示されます。</translation>
    </message>
</context>
<context>
    <name>opentop::StaleLook</name>
    <message>
        <location filename="../ui/widgets/StaleLook.cpp" line="52"/>
        <source>not read yet</source>
        <translation>未読出し</translation>
    </message>
    <message>
        <location filename="../ui/widgets/StaleLook.cpp" line="55"/>
        <source>updated %1 s ago</source>
        <translation>%1 s 前に更新</translation>
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
        <translation>%1 の通信グループ</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="182"/>
        <source>It runs with running data SPno%1</source>
        <translation>運転データ: SPno%1</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="184"/>
        <source> at %1</source>
        <translation> 速度 %1</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="187"/>
        <source>, direction %1 (the direction command sent since)</source>
        <translation>、回転方向 %1（その後に送信した回転方向指令）</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="188"/>
        <source>, direction %1</source>
        <translation>、回転方向 %1</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="191"/>
        <source>Which running data it runs with could not be read.</source>
        <translation>どの運転データで運転するかを読み出せませんでした。</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="194"/>
        <source>Warning: %1</source>
        <translation>警告: %1</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="196"/>
        <source>The start also reaches machine number(s) %1: %2.</source>
        <translation>運転開始は局番 %1 にも届きます: %2。</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="202"/>
        <source>Not read: %1.</source>
        <translation>未読出し: %1。</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="219"/>
        <source>This starts the motor of machine number %1.</source>
        <translation>局番 %1 のモータを起動します。</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="221"/>
        <source>This sets the speed command of machine number %1 to %2: its motor runs.</source>
        <translation>局番 %1 の速度指令を %2 に設定します: モータが運転します。</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="225"/>
        <source>Make sure that nobody is near the machine and that it may move. STOP ALL stops every drive at any time.</source>
        <translation>機械の近くに人がいないこと、機械が動いてもよいことを確認してください。全停止でいつでも全ドライバを停止できます。</translation>
    </message>
    <message>
        <location filename="../model/run/StartPreview.cpp" line="228"/>
        <source>You are asked once per drive while the program runs.</source>
        <translation>プログラム実行中、ドライバごとに 1 回確認します。</translation>
    </message>
</context>
<context>
    <name>opentop::StationAccess</name>
    <message>
        <location filename="../model/access/StationAccess.cpp" line="74"/>
        <location filename="../model/access/StationAccess.cpp" line="127"/>
        <source>the results database is not open</source>
        <translation>結果データベースが開いていません</translation>
    </message>
    <message>
        <location filename="../model/access/StationAccess.cpp" line="105"/>
        <source>the results database is not open, so nobody can be identified</source>
        <translation>結果データベースが開いていないため、誰も確認できません</translation>
    </message>
    <message>
        <location filename="../model/access/StationAccess.cpp" line="160"/>
        <source>the station&apos;s users are being read from the results database</source>
        <translation>結果データベースからステーションのユーザーを読み込み中です</translation>
    </message>
    <message>
        <location filename="../model/access/StationAccess.cpp" line="161"/>
        <source>the station&apos;s users cannot be read: %1</source>
        <translation>ステーションのユーザーを読み込めません: %1</translation>
    </message>
    <message>
        <location filename="../model/access/StationAccess.cpp" line="166"/>
        <source>nobody is logged in: log in with your user name and password (or badge)</source>
        <translation>誰もログインしていません: ユーザー名とパスワード (または社員証) でログインしてください</translation>
    </message>
    <message>
        <location filename="../model/access/StationAccess.cpp" line="170"/>
        <source>the recipe&apos;s approval is being read from the results database</source>
        <translation>結果データベースからレシピの承認を読み込み中です</translation>
    </message>
</context>
<context>
    <name>opentop::StationActions</name>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="24"/>
        <source>Reset alarm and test again</source>
        <translation>アラームリセットして再試験</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="25"/>
        <source>Technician: test again…</source>
        <translation>技術者: 再試験…</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="50"/>
        <source>A technician may allow unit %1 to be tested again.</source>
        <translation>技術者がユニット %1 の再試験を許可できます。</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="57"/>
        <source>Resetting the alarm of machine number %1…</source>
        <translation>局番 %1 のアラームをリセットしています…</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="66"/>
        <source>The alarm is not cleared; nothing was started:
%1</source>
        <translation>アラームが解除されていません。何も開始していません:
%1</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="76"/>
        <source>reset the alarm</source>
        <translation>アラームをリセットする</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="82"/>
        <source>serial %1</source>
        <translation>シリアル %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="91"/>
        <source>test serial %1 again</source>
        <translation>シリアル %1 を再試験する</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="105"/>
        <source>An alarm was active on machine number %1 before the test: nothing was written. Reset it (the drive&apos;s own reset; one that needs a power cycle says so) and the unit is tested again.</source>
        <translation>試験前に局番 %1 でアラームが発生していました。何も書き込んでいません。アラームをリセットすると（ドライバ自身のリセット。電源再投入が必要なアラームはその旨を表示します）、製品を再試験します。</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="134"/>
        <source>(no name)</source>
        <translation>（名前なし）</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="136"/>
        <source>Test again</source>
        <translation>再試験</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationActions.cpp" line="137"/>
        <source>%1

Test unit %2 again? It is recorded as allowed by %3.</source>
        <translation>%1

製品 %2 を再試験しますか？ %3 が許可したものとして記録されます。</translation>
    </message>
</context>
<context>
    <name>opentop::StationAlarmReset</name>
    <message>
        <location filename="../model/eol/StationAlarmReset.cpp" line="56"/>
        <source>machine number %1: not connected to a bus</source>
        <translation>局番 %1: バスに接続されていません</translation>
    </message>
    <message>
        <location filename="../model/eol/StationAlarmReset.cpp" line="57"/>
        <source>machine number %1 is not a position of the recipe</source>
        <translation>局番 %1 はレシピの位置にありません</translation>
    </message>
    <message>
        <location filename="../model/eol/StationAlarmReset.cpp" line="65"/>
        <source>machine number %1: %2 drives have no alarm reset command; switch the drive off and on</source>
        <translation>局番 %1: %2 ドライバにはアラームリセットコマンドがありません。ドライバの電源を入れ直してください</translation>
    </message>
    <message>
        <location filename="../model/eol/StationAlarmReset.cpp" line="75"/>
        <source>machine number %1: %2</source>
        <translation>局番 %1: %2</translation>
    </message>
</context>
<context>
    <name>opentop::StationFigures</name>
    <message>
        <location filename="../ui/eol/StationFigures.cpp" line="27"/>
        <source>This shift: no figures yet (%1)</source>
        <translation>このシフト: まだ集計なし（%1）</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationFigures.cpp" line="28"/>
        <source>results database not read</source>
        <translation>結果データベースをまだ読み込んでいません</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationFigures.cpp" line="31"/>
        <source>This shift: tested %1 · passed %2 · failed %3 · station errors %4 · %5</source>
        <translation>このシフト: 試験 %1 · 合格 %2 · 不合格 %3 · ステーションエラー %4 · %5</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationFigures.cpp" line="39"/>
        <source>This station, this recipe version, since %1 (read %2). The same figures: %3</source>
        <translation>このステーション、このレシピバージョン、%1 以降（%2 に読込み）。同じ数値を表示するコマンド: %3</translation>
    </message>
</context>
<context>
    <name>opentop::StationLogin</name>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="38"/>
        <source>operator</source>
        <translation>作業者</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="40"/>
        <source>Operator:</source>
        <translation>作業者:</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="44"/>
        <source>user name</source>
        <translation>ユーザー名</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="49"/>
        <source>password</source>
        <translation>パスワード</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="51"/>
        <source>Log in</source>
        <translation>ログイン</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="52"/>
        <source>Log in:</source>
        <translation>ログイン:</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="57"/>
        <source>Log out</source>
        <translation>ログアウト</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="104"/>
        <source>Not logged in: %1</source>
        <translation>ログインできません: %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="125"/>
        <source>Logged in: &lt;b&gt;%1&lt;/b&gt; (%2)</source>
        <translation>ログイン中: &lt;b&gt;%1&lt;/b&gt; (%2)</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationLogin.cpp" line="131"/>
        <source>No users set up: anyone can run, edit and leave; set up users with opentop-cli eol user add</source>
        <translation>ユーザーが設定されていません: 誰でも実行・編集・終了できます。opentop-cli eol user add でユーザーを設定してください</translation>
    </message>
</context>
<context>
    <name>opentop::StationNotice</name>
    <message numerus="yes">
        <location filename="../ui/eol/StationNotice.cpp" line="31"/>
        <source>%n result(s) kept on this station, not yet in the results database: %1. They are sent by themselves, in order, when it answers.</source>
        <translation>
            <numerusform>このステーションに結果 %n 件を保管中で、まだ結果データベースにありません: %1。データベースが応答すると順番に自動送信されます。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/eol/StationNotice.cpp" line="35"/>
        <source>it does not answer</source>
        <translation>データベースが応答しません</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationNotice.cpp" line="38"/>
        <source>Unit %1 (begun %2) was not finished: the station stopped during its test. It is recorded as interrupted; test it again.</source>
        <translation>ユニット %1（%2 開始）は完了していません: 検査中にステーションが停止しました。「中断」として記録されています。再検査してください。</translation>
    </message>
    <message>
        <location filename="../ui/eol/StationNotice.cpp" line="44"/>
        <source>Making the recipe&apos;s drives safe: reading each, stopping one left running, giving control back to their inputs…</source>
        <translation>レシピのドライブを安全な状態にしています: 1 台ずつ読み取り、運転中のものを停止し、制御を入力端子に戻します…</translation>
    </message>
</context>
<context>
    <name>opentop::StationRecipe</name>
    <message>
        <location filename="../model/station/StationRecipe.cpp" line="68"/>
        <source>this recipe takes per-unit values from a CSV file: open it first</source>
        <translation>このレシピは個別値を CSV ファイルから取得します: 先に CSV ファイルを開いてください</translation>
    </message>
</context>
<context>
    <name>opentop::StationResults</name>
    <message>
        <location filename="../model/station/StationResults.cpp" line="63"/>
        <source>opening the results database</source>
        <translation>結果データベースを開いています</translation>
    </message>
    <message>
        <location filename="../model/station/StationResults.cpp" line="65"/>
        <source>NOT REACHABLE (%1); trying again by itself</source>
        <translation>接続できません（%1）。自動で再試行中</translation>
    </message>
    <message>
        <location filename="../model/station/StationResults.cpp" line="66"/>
        <source>no results database</source>
        <translation>結果データベースがありません</translation>
    </message>
    <message>
        <location filename="../model/station/StationResults.cpp" line="72"/>
        <source>the result of unit %1 (%2) is not in the results database yet: nothing is tested until it is. The station tries again by itself (%3)</source>
        <translation>製品 %1 の結果（%2）はまだ結果データベースに記録されていません。記録されるまで試験しません。ステーションが自動で再試行します（%3）</translation>
    </message>
    <message>
        <location filename="../model/station/StationResults.cpp" line="77"/>
        <source>the results database is being opened; try again in a moment</source>
        <translation>結果データベースを開いています。しばらくしてからもう一度お試しください</translation>
    </message>
    <message>
        <location filename="../model/station/StationResults.cpp" line="79"/>
        <source>the results database is not open; nothing is tested unless it is recorded</source>
        <translation>結果データベースが開いていません。記録できない状態では試験しません</translation>
    </message>
    <message>
        <location filename="../model/station/StationResults.cpp" line="80"/>
        <source>the results database cannot be reached (%1); nothing is tested unless it is recorded. The station tries again by itself.</source>
        <translation>結果データベースに接続できません（%1）。記録できない状態では試験しません。ステーションが自動で再試行します。</translation>
    </message>
</context>
<context>
    <name>opentop::StationSafeState</name>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="44"/>
        <source>%1: no answer (%2); not checked</source>
        <translation>%1: 応答なし（%2）。確認していません</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="49"/>
        <source>%1 was RUNNING (%2)</source>
        <translation>%1 は運転中でした（%2）</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="52"/>
        <source>: stopped by the station</source>
        <translation>: ステーションが停止しました</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="55"/>
        <source>%1 stopped</source>
        <translation>%1 は停止中</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="58"/>
        <source>; control given back to its inputs (I/O priority)</source>
        <translation>。制御を入力端子に戻しました（I/O 優先）</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="99"/>
        <source>drive %1</source>
        <translation>ドライブ %1</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="100"/>
        <source>drive %1 (%2)</source>
        <translation>ドライブ %1（%2）</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="104"/>
        <source>the recipe&apos;s family %1 is not known</source>
        <translation>レシピの機種ファミリー %1 は不明です</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="148"/>
        <source>whether its motor runs cannot be read</source>
        <translation>モーターが運転中かどうかを読み取れません</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="159"/>
        <source>it runs from its input terminals (I/O priority): not the station&apos;s to stop; stop it at the machine</source>
        <translation>入力端子で運転しています（I/O 優先）: ステーションが停止するものではありません。機械側で停止してください</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="184"/>
        <source>the stop was refused: %1</source>
        <translation>停止指令が拒否されました: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="198"/>
        <source>NOT CONFIRMED STOPPED: %1</source>
        <translation>停止未確認: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/StationSafeState.cpp" line="240"/>
        <source>control could not be given back to its inputs: %1</source>
        <translation>制御を入力端子に戻せません: %1</translation>
    </message>
</context>
<context>
    <name>opentop::StationYield</name>
    <message>
        <location filename="../model/eol/StationYield.cpp" line="48"/>
        <source>the results database is not open</source>
        <translation>結果データベースが開いていません</translation>
    </message>
</context>
<context>
    <name>opentop::StatusLight</name>
    <message>
        <location filename="../ui/widgets/StatusLight.cpp" line="30"/>
        <source>Status not known yet</source>
        <translation>状態不明</translation>
    </message>
    <message>
        <location filename="../ui/widgets/StatusLight.cpp" line="44"/>
        <source>Status light %1: %2</source>
        <translation>ステータスランプ %1: %2</translation>
    </message>
    <message>
        <location filename="../ui/widgets/StatusLight.cpp" line="48"/>
        <source>The drive&apos;s manual: %1</source>
        <translation>ドライバのマニュアル: %1</translation>
    </message>
</context>
<context>
    <name>opentop::StepMeasure</name>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="85"/>
        <source>%1: the drive stopped answering: %2</source>
        <translation>%1: ドライバが応答しなくなりました: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="93"/>
        <source>%1: the drive raised an alarm while running</source>
        <translation>%1: 運転中にドライバでアラームが発生しました</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="113"/>
        <source>%1: %2 %3</source>
        <translation>%1: %2 %3</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="132"/>
        <source>%1: the drive has no speed to wait for</source>
        <translation>%1: 待機する速度がドライバにありません</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="155"/>
        <source>time to reach speed</source>
        <translation>速度到達時間</translation>
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
        <translation>不明</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="169"/>
        <source>%1: did not reach %2 %3 ±%4 %3 within %5 s (last read %6 %3)</source>
        <translation>%1: %5 s 以内に %2 %3 ±%4 %3 に到達しませんでした（最終読出し値 %6 %3）</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="170"/>
        <source>its target</source>
        <translation>目標値</translation>
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
        <translation>%1: ドライバはアラームなし</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="225"/>
        <source>alarms raised</source>
        <translation>発生したアラーム</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="227"/>
        <source>%1: the drive has an alarm</source>
        <translation>%1: ドライバでアラームが発生しています</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="234"/>
        <source>%1: nothing to read</source>
        <translation>%1: 読み出すものがありません</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="248"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="251"/>
        <source>%1: %2 reads &quot;%3&quot;, expected &quot;%4&quot;</source>
        <translation>%1: %2 の読出し値は &quot;%3&quot;、期待値は &quot;%4&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="259"/>
        <source>%1: %2 reads %3 %4, %5</source>
        <translation>%1: %2 の読出し値 %3 %4、%5</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="299"/>
        <source>time to stop</source>
        <translation>停止時間</translation>
    </message>
    <message>
        <location filename="../model/eol/StepMeasure.cpp" line="303"/>
        <source>%1: stopped after %2 s, allowed at most %3 s</source>
        <translation>%1: %2 s 後に停止、許容は最大 %3 s</translation>
    </message>
</context>
<context>
    <name>opentop::StepMetrics</name>
    <message>
        <location filename="../model/tuning/StepMetrics.cpp" line="18"/>
        <source>the step has no height (from = to)</source>
        <translation>ステップ幅が 0 です（from = to）</translation>
    </message>
    <message>
        <location filename="../model/tuning/StepMetrics.cpp" line="19"/>
        <source>too few samples after the step (%1)</source>
        <translation>ステップ後のサンプルが少なすぎます (%1)</translation>
    </message>
</context>
<context>
    <name>opentop::StepTest</name>
    <message>
        <location filename="../model/tuning/StepTest.cpp" line="39"/>
        <source>a step test runs forward from one speed to another: from and to must differ and be 0 or more</source>
        <translation>ステップ試験はある速度から別の速度へ正転で行います: 開始速度と目標速度は異なる値で、0 以上でなければなりません</translation>
    </message>
    <message>
        <location filename="../model/tuning/StepTest.cpp" line="47"/>
        <source>%1 %2 is beyond the test&apos;s speed limit %3 %2</source>
        <translation>%1 %2 は試験の速度制限値 %3 %2 を超えています</translation>
    </message>
    <message>
        <location filename="../model/tuning/StepTest.cpp" line="55"/>
        <source>Running to %1 %2</source>
        <translation>%1 %2 まで運転中</translation>
    </message>
    <message>
        <location filename="../model/tuning/StepTest.cpp" line="88"/>
        <source>Step to %1 %2</source>
        <translation>%1 %2 へステップ</translation>
    </message>
</context>
<context>
    <name>opentop::StepTestPanel</name>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="22"/>
        <source>Run step test…</source>
        <translation>ステップ試験を実行…</translation>
    </message>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="29"/>
        <source>From:</source>
        <translation>開始:</translation>
    </message>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="30"/>
        <source>To:</source>
        <translation>終了:</translation>
    </message>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="31"/>
        <source>Record time:</source>
        <translation>記録時間:</translation>
    </message>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="32"/>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="75"/>
        <source>Enter two different speeds of 0 %1 or more.</source>
        <translation>0 %1 以上の異なる 2 つの速度を入力してください。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/StepTestPanel.cpp" line="79"/>
        <source>Enter a record time of 100–60000 ms.</source>
        <translation>記録時間を 100–60000 ms で入力してください。</translation>
    </message>
</context>
<context>
    <name>opentop::StopAllButton</name>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="16"/>
        <location filename="../ui/run/StopAllButton.cpp" line="92"/>
        <source>STOP ALL</source>
        <translation>全停止</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="20"/>
        <source>Stops every drive on the bus at once (%1), then checks that each has stopped.</source>
        <translation>バス上の全ドライバを一斉に停止し (%1)、各ドライバの停止を確認します。</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="87"/>
        <source>STOPPING…</source>
        <translation>停止中…</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="103"/>
        <source>The stop broadcast to %1 drives FAILED: %2</source>
        <translation>%1 台のドライバへの停止ブロードキャストに失敗しました: %2</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="106"/>
        <source>Stop sent to every drive. No drives are known on the bus, so none was checked; scan the bus to have them checked.</source>
        <translation>全ドライバに停止を送信しました。バス上に既知のドライバがないため、停止は確認していません。確認するにはバスをスキャンしてください。</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="114"/>
        <source>Machine number %1: stopped after %2 s</source>
        <translation>局番 %1: %2 s 後に停止</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="117"/>
        <source>Machine number %1: STILL RUNNING (%2)</source>
        <translation>局番 %1: まだ運転中 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="120"/>
        <source>Machine number %1: NO ANSWER, not confirmed stopped</source>
        <translation>局番 %1: 応答なし、停止未確認</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="135"/>
        <source>STOP ALL: the stop broadcast FAILED</source>
        <translation>全停止: 停止ブロードキャストに失敗しました</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="136"/>
        <source>STOP ALL: stop sent, no drive checked</source>
        <translation>全停止: 停止を送信、ドライバは未確認</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="137"/>
        <source>STOP ALL: every drive stopped</source>
        <translation>全停止: 全ドライバ停止</translation>
    </message>
    <message>
        <location filename="../ui/run/StopAllButton.cpp" line="138"/>
        <source>STOP ALL: not every drive is confirmed stopped</source>
        <translation>全停止: 停止が確認できないドライバがあります</translation>
    </message>
</context>
<context>
    <name>opentop::StopAllCommand</name>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="54"/>
        <source>Broadcast stop to every drive, then confirm each has stopped (needs --yes)</source>
        <translation>全ドライバに停止をブロードキャストし、各ドライバの停止を確認します（--yes が必要）</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="60"/>
        <source>Send the stop broadcast.</source>
        <translation>停止ブロードキャストを送信します。</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="62"/>
        <source>Machine numbers to confirm, e.g. 1,2,5-7 (default on a simulated bus: its drives).</source>
        <translation>停止を確認する局番。例: 1,2,5-7（シミュレーションバスでの既定: そのバスのドライバ）。</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="63"/>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="72"/>
        <source>error: usage: %1 (no other arguments)</source>
        <translation>エラー: 使い方: %1（他の引数なし）</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="80"/>
        <source>error: --ids: %1</source>
        <translation>エラー: --ids: %1</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="87"/>
        <source>Would broadcast to every drive on the bus (machine number 0, no reply):</source>
        <translation>バス上の全ドライバにブロードキャストします（局番 0、応答なし）:</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="91"/>
        <source>Add --yes to send it.</source>
        <translation>送信するには --yes を付けてください。</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="119"/>
        <source>Broadcast %1: %2</source>
        <translation>ブロードキャスト %1: %2</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="120"/>
        <source>Broadcast %1 FAILED: %2: %3</source>
        <translation>ブロードキャスト %1 失敗: %2: %3</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="124"/>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="124"/>
        <source>Family</source>
        <translation>ファミリ</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="124"/>
        <source>State</source>
        <translation>状態</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="124"/>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="124"/>
        <source>After</source>
        <translation>経過時間</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="124"/>
        <source>Detail</source>
        <translation>詳細</translation>
    </message>
    <message>
        <location filename="../cli/StopAllCommand.cpp" line="156"/>
        <source>Only the broadcast was sent: drives do not answer a broadcast, so nothing confirms that they stopped. To confirm, pass the machine numbers on this bus, e.g. --ids 1,2,5-7 (opentop-cli scan finds them).</source>
        <translation>ブロードキャストのみ送信しました: ドライバはブロードキャストに応答しないため、停止を確認する手段がありません。確認するには、このバスの局番を指定してください。例: --ids 1,2,5-7（opentop-cli scan で検出できます）。</translation>
    </message>
</context>
<context>
    <name>opentop::StopConfirmer</name>
    <message>
        <location filename="../model/run/StopConfirmer.cpp" line="80"/>
        <source>%1 drives report neither running state nor speed</source>
        <translation>%1 ドライバは運転状態も速度も通知しません</translation>
    </message>
    <message>
        <location filename="../model/run/StopConfirmer.cpp" line="111"/>
        <source>%1 is %2: the drive does not take motion commands over the bus (it follows its input terminals)</source>
        <translation>%1 は %2 です: ドライバはバス経由の運転コマンドを受け付けません（入力端子に従います）</translation>
    </message>
    <message>
        <location filename="../model/run/StopConfirmer.cpp" line="185"/>
        <source>still at %1 after %2 s</source>
        <translation>%2 s 後も %1 のままです</translation>
    </message>
    <message>
        <location filename="../model/run/StopConfirmer.cpp" line="187"/>
        <source>still running after %1 s</source>
        <translation>%1 s 後も運転中</translation>
    </message>
</context>
<context>
    <name>opentop::TcpSimServer</name>
    <message>
        <location filename="../sim/TcpSimServer.cpp" line="36"/>
        <source>cannot listen on %1:%2: %3</source>
        <translation>%1:%2 で待ち受けできません: %3</translation>
    </message>
</context>
<context>
    <name>opentop::TerminalLamps</name>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="184"/>
        <source>n/a</source>
        <translation>N/A</translation>
    </message>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="185"/>
        <source>%1: not applicable (%2)</source>
        <translation>%1: 該当なし (%2)</translation>
    </message>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="188"/>
        <source>?</source>
        <translation>?</translation>
    </message>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="189"/>
        <source>%1: not read</source>
        <translation>%1: 未読出し</translation>
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
        <translation>%1 は ON</translation>
    </message>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="194"/>
        <source>%1 is OFF</source>
        <translation>%1 は OFF</translation>
    </message>
    <message>
        <location filename="../ui/monitor/TerminalLamps.cpp" line="196"/>
        <source>%1 (last state read, not live)</source>
        <translation>%1（最後に読み出した状態、更新停止）</translation>
    </message>
</context>
<context>
    <name>opentop::TestRunPanel</name>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="48"/>
        <source>&lt;b&gt;Test run of machine number %1&lt;/b&gt;</source>
        <translation>&lt;b&gt;局番 %1 の試運転&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="54"/>
        <source>Machine number %1 has not been identified as a drive of a known family; a test run needs one.</source>
        <translation>局番 %1 は既知のファミリのドライバとして識別されていません。試運転には識別が必要です。</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="31"/>
        <source>&amp;Start</source>
        <translation>運転開始(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="32"/>
        <source>S&amp;top</source>
        <translation>停止(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="33"/>
        <source>&amp;CW</source>
        <translation>&amp;CW</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="34"/>
        <source>CC&amp;W</source>
        <translation>CC&amp;W</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="35"/>
        <source>&amp;Hold</source>
        <translation>保持(&amp;H)</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="36"/>
        <source>&amp;Free</source>
        <translation>フリー(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="54"/>
        <source>Se&amp;lect running data</source>
        <translation>運転データ選択(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="67"/>
        <source>Return to &amp;I/O priority</source>
        <translation>I/O 優先に戻す(&amp;I)</translation>
    </message>
    <message>
        <location filename="../ui/run/DbuRunCommands.cpp" line="69"/>
        <source>Give run, stop, direction and speed selection back to the drive&apos;s input terminals</source>
        <translation>運転、停止、回転方向、速度選択をドライバの入力端子に戻します</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="161"/>
        <source>Cannot read %1 to check that the drive takes motion commands: %2</source>
        <translation>ドライバが運転コマンドを受け付けるかを確認するための %1 を読み出せません: %2</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="197"/>
        <source>Not started: the variant of %1 was not given.</source>
        <translation>起動していません：%1 の機種が指定されていません。</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="204"/>
        <source>Reading what the start will run…</source>
        <translation>運転開始時の動作を読出し中…</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="220"/>
        <source>Start the motor</source>
        <translation>モータの運転開始</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="234"/>
        <source>Sending %1…</source>
        <translation>%1 を送信中…</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="263"/>
        <source>Not every drive of its communication group runs: see below.</source>
        <translation>通信グループのすべてのドライバが運転しているわけではありません。下を参照してください。</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="281"/>
        <source>Sent: %1</source>
        <translation>送信済み: %1</translation>
    </message>
    <message>
        <location filename="../ui/run/TestRunPanel.cpp" line="350"/>
        <source>Polling is paused: the controller brakes the motor %1 s after the last frame it receives (%2). Resume polling to keep the motor running.</source>
        <translation>ポーリングが一時停止中です: コントローラは最後のフレームを受信してから %1 s 後にモータにブレーキをかけます (%2)。モータの運転を続けるにはポーリングを再開してください。</translation>
    </message>
</context>
<context>
    <name>opentop::TrafficDescriber</name>
    <message>
        <location filename="../model/traffic/TrafficDescriber.cpp" line="150"/>
        <source>broadcast: every drive executes it</source>
        <translation>ブロードキャスト: 全ドライバが実行</translation>
    </message>
    <message>
        <location filename="../model/traffic/TrafficDescriber.cpp" line="159"/>
        <source>to %1 (group parent: also %2)</source>
        <translation>%1 宛（グループ親局: %2 も実行）</translation>
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
        <translation>時刻</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="125"/>
        <source>Direction</source>
        <translation>方向</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="127"/>
        <source>Drive</source>
        <translation>ドライバ</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="129"/>
        <source>Function</source>
        <translation>ファンクション</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="131"/>
        <source>Bytes</source>
        <translation>バイト</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="133"/>
        <source>Meaning</source>
        <translation>意味</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogModel.cpp" line="135"/>
        <source>Error</source>
        <translation>エラー</translation>
    </message>
</context>
<context>
    <name>opentop::TrafficLogView</name>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="43"/>
        <source>&amp;Errors only</source>
        <translation>エラーのみ(&amp;E)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="44"/>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="171"/>
        <source>&amp;Pause</source>
        <translation>一時停止(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="53"/>
        <source>All drives</source>
        <translation>全ドライバ</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="55"/>
        <source>All</source>
        <translation>すべて</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="56"/>
        <source>Tx (requests)</source>
        <translation>Tx（要求）</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="57"/>
        <source>Rx (replies)</source>
        <translation>Rx（応答）</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="58"/>
        <source>Events (no reply)</source>
        <translation>イベント（応答なし）</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="62"/>
        <source>&amp;Clear</source>
        <translation>クリア(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="64"/>
        <source>&amp;Save…</source>
        <translation>保存(&amp;S)…</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="67"/>
        <source>&amp;Drive:</source>
        <translation>ドライバ(&amp;D):</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="69"/>
        <source>Di&amp;rection:</source>
        <translation>方向(&amp;R):</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="83"/>
        <source>Frames</source>
        <translation>フレーム</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="112"/>
        <source>Drive</source>
        <translation>ドライバ</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="112"/>
        <source>Requests</source>
        <translation>要求</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="112"/>
        <source>Replies</source>
        <translation>応答</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="112"/>
        <source>Timeouts</source>
        <translation>タイムアウト</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="112"/>
        <source>CRC errors</source>
        <translation>CRC エラー</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="113"/>
        <source>Exceptions</source>
        <translation>例外</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="113"/>
        <source>Wrong/garbled</source>
        <translation>不正/化け</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="113"/>
        <source>Mean ms</source>
        <translation>平均 ms</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="113"/>
        <source>Late replies</source>
        <translation>遅延応答</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="113"/>
        <source>Max ms</source>
        <translation>最大 ms</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="115"/>
        <source>Statistics per drive</source>
        <translation>ドライバ別統計</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="119"/>
        <source>Frames that answered nothing asked at the time: a reply to an earlier request that came too late, discarded and never taken as a value</source>
        <translation>その時点の要求に対する応答ではないフレーム: 以前の要求への応答が遅れて届いたもので、破棄され、値としては使われません</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="171"/>
        <source>&amp;Resume</source>
        <translation>再開(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="242"/>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="320"/>
        <source>Broadcast</source>
        <translation>ブロードキャスト</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="242"/>
        <source>Drive %1</source>
        <translation>ドライバ %1</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="309"/>
        <source>%1 addresses did not answer: %2</source>
        <translation>%1 個のアドレスが応答しませんでした: %2</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="311"/>
        <source>No reply from machine numbers %1</source>
        <translation>局番 %1 から応答なし</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="352"/>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="357"/>
        <source>Save traffic log</source>
        <translation>通信ログを保存</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="352"/>
        <source>Text files (*.txt)</source>
        <translation>テキストファイル (*.txt)</translation>
    </message>
    <message>
        <location filename="../ui/traffic/TrafficLogView.cpp" line="358"/>
        <source>Could not save %1: %2</source>
        <translation>%1 を保存できませんでした: %2</translation>
    </message>
</context>
<context>
    <name>opentop::Transport</name>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="16"/>
        <source>No serial port given: enter a device such as /dev/ttyUSB0 or COM3.</source>
        <translation>シリアルポートが指定されていません: /dev/ttyUSB0 や COM3 などのデバイスを入力してください。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="20"/>
        <source>Baud rate %1 is not supported: use 1200–115200 (e.g. 9600, 19200, 38400, 57600, 115200).</source>
        <translation>ボーレート %1 はサポートされていません: 1200–115200 を使用してください（例: 9600、19200、38400、57600、115200）。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="26"/>
        <source>Parity &apos;%1&apos; is not supported: use N (none), E (even) or O (odd).</source>
        <translation>パリティ &apos;%1&apos; はサポートされていません: N（なし）、E（偶数）、O（奇数）を使用してください。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="31"/>
        <source>%1 data bits are not supported: use 7 or 8.</source>
        <translation>データビット %1 はサポートされていません: 7 または 8 を使用してください。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="35"/>
        <source>%1 stop bits are not supported: use 1 or 2.</source>
        <translation>ストップビット %1 はサポートされていません: 1 または 2 を使用してください。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="39"/>
        <source>Byte timeout %1 ms is not allowed: use 1–10000 ms, or 0 to derive it from the baud rate.</source>
        <translation>バイトタイムアウト %1 ms は使用できません: 1–10000 ms、またはボーレートから算出する場合は 0 を使用してください。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="45"/>
        <source>RS-485 mode %1 is not supported: use off, auto, kernel or rts.</source>
        <translation>RS-485 モード %1 はサポートされていません: off、auto、kernel、rts のいずれかを使用してください。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="52"/>
        <source>Line format of machine number %1: %2 Use machine numbers 1–247.</source>
        <translation>局番 %1 の通信フォーマット: %2 局番は 1–247 を使ってください。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="60"/>
        <source>RTS delay %1 µs is not allowed: use 0–%2 µs (0: the driver&apos;s or libmodbus&apos; own).</source>
        <translation>RTS 遅延 %1 µs は使用できません: 0–%2 µs を使用してください（0: シリアルドライバまたは libmodbus 自身の遅延）。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="69"/>
        <source>No host given: enter the gateway&apos;s address, e.g. 192.168.1.10.</source>
        <translation>ホストが指定されていません: ゲートウェイのアドレスを入力してください。例: 192.168.1.10。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="73"/>
        <source>TCP port %1 is not allowed: use 1–65535 (Modbus TCP uses 502).</source>
        <translation>TCP ポート %1 は使用できません: 1–65535 を使用してください（Modbus TCP は 502）。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="80"/>
        <source>No simulated devices given: use a list such as dbu200@1,dcpid@7.</source>
        <translation>シミュレーションデバイスが指定されていません: dbu200@1,dcpid@7 のようなリストを使用してください。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="86"/>
        <source>Timeout %1 ms is not allowed: use 10–10000 ms.</source>
        <translation>タイムアウト %1 ms は使用できません: 10–10000 ms を使用してください。</translation>
    </message>
    <message>
        <location filename="../transport/ConnectionSettings.cpp" line="90"/>
        <source>%1 retries are not allowed: use 0–10.</source>
        <translation>リトライ %1 回は使用できません: 0–10 を使用してください。</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="56"/>
        <source>Vendor name</source>
        <translation>ベンダ名</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="58"/>
        <source>Product code</source>
        <translation>製品コード</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="60"/>
        <source>Revision</source>
        <translation>リビジョン</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="62"/>
        <source>Vendor URL</source>
        <translation>ベンダ URL</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="64"/>
        <source>Product name</source>
        <translation>製品名</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="66"/>
        <source>Model name</source>
        <translation>モデル名</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="68"/>
        <source>User application name</source>
        <translation>ユーザアプリケーション名</translation>
    </message>
    <message>
        <location filename="../transport/DeviceIdentification.cpp" line="70"/>
        <source>Object 0x%1</source>
        <translation>オブジェクト 0x%1</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="26"/>
        <source>Cannot open %1: %2</source>
        <translation>%1 を開けません: %2</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="89"/>
        <source>read twice: a read of the same length was unanswered, and the first reply could have been its late answer</source>
        <translation>2 回読み出し: 同じ長さの読み出しが未応答で、最初の応答はその遅延応答だった可能性があります</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="102"/>
        <source>replies disagree: late answers to earlier reads are likely</source>
        <translation>応答が一致しません: 以前の読み出しへの遅延応答の可能性が高いです</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="115"/>
        <location filename="../transport/ModbusClientWorker.cpp" line="373"/>
        <source>%1 is not open</source>
        <translation>%1 が開いていません</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="160"/>
        <source>send failed</source>
        <translation>送信失敗</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="186"/>
        <source>interrupted while waiting</source>
        <translation>待機中に中断しました</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="190"/>
        <location filename="../transport/MockBackend.cpp" line="101"/>
        <source>no reply within %1 ms</source>
        <translation>%1 ms 以内に応答がありません</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="226"/>
        <source>another reply followed: this one may have answered an earlier request</source>
        <translation>別の応答が続きました: この応答は以前の要求に対するものの可能性があります</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="253"/>
        <source>a drive&apos;s own line format needs a serial port; a Modbus TCP gateway sets its line itself</source>
        <translation>ドライブ自身の通信フォーマットにはシリアルポートが必要です。Modbus TCP ゲートウェイは回線を自分で設定します</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="269"/>
        <source>cannot switch the line to %1: %2</source>
        <translation>回線を %1 に切り替えられません: %2</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="312"/>
        <source>no reply within %1 ms (a late reply to an earlier request was discarded)</source>
        <translation>%1 ms 以内に応答なし（以前の要求への遅延応答は破棄しました）</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="334"/>
        <location filename="../transport/RtuFrame.cpp" line="140"/>
        <source>reply from slave %1, expected %2</source>
        <translation>局番 %1 からの応答（期待値 %2）</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusContext.cpp" line="140"/>
        <location filename="../transport/RtuBackend.cpp" line="191"/>
        <location filename="../transport/TcpBackend.cpp" line="112"/>
        <source>reply incomplete</source>
        <translation>応答が不完全です</translation>
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
        <translation>受信失敗</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="362"/>
        <source>late reply discarded: complete %1 ms after the request, where an answer needs at least %2 ms on the wire</source>
        <translation>遅延応答を破棄: 要求の %1 ms 後に受信完了。応答には線路上で少なくとも %2 ms かかります</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="378"/>
        <source> (connection closed)</source>
        <translation> (接続切断)</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="393"/>
        <source>stale bytes discarded before sending</source>
        <translation>送信前に残留バイトを破棄しました</translation>
    </message>
    <message>
        <location filename="../transport/LibmodbusBackend.cpp" line="440"/>
        <source>late bytes discarded after an error</source>
        <translation>エラー後に遅延バイトを破棄しました</translation>
    </message>
    <message>
        <location filename="../transport/MockBackend.cpp" line="57"/>
        <source>mock is not open</source>
        <translation>mock が開いていません</translation>
    </message>
    <message>
        <location filename="../transport/ModbusBackend.cpp" line="39"/>
        <source>→ %1 bytes</source>
        <translation>→ %1 バイト</translation>
    </message>
    <message>
        <location filename="../transport/ModbusBackend.cpp" line="51"/>
        <source>echo %1 = %2</source>
        <translation>エコー %1 = %2</translation>
    </message>
    <message>
        <location filename="../transport/ModbusBackend.cpp" line="54"/>
        <source>echo %1 ×%2</source>
        <translation>エコー %1 ×%2</translation>
    </message>
    <message>
        <location filename="../transport/ModbusClientWorker.cpp" line="220"/>
        <location filename="../transport/ModbusClientWorker.cpp" line="239"/>
        <source>cancelled before sending</source>
        <translation>送信前にキャンセルしました</translation>
    </message>
    <message>
        <location filename="../transport/ModbusClientWorker.cpp" line="285"/>
        <source>cannot open %1</source>
        <translation>%1 を開けません</translation>
    </message>
    <message>
        <location filename="../transport/ModbusClientWorker.cpp" line="327"/>
        <source>client closed</source>
        <translation>クライアントが切断しました</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="142"/>
        <source>Slave address %1 is not allowed: use 1–247, or 0 to broadcast a write.</source>
        <translation>スレーブアドレス %1 は使用できません: 1–247、または書込みのブロードキャストには 0 を使用してください。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="147"/>
        <source>Function code 0x%1 is not allowed: use 0x01–0x7F.</source>
        <translation>ファンクションコード 0x%1 は使用できません: 0x01–0x7F を使用してください。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="151"/>
        <source>Timeout %1 ms is not allowed: use 10–10000 ms, or -1 for the default.</source>
        <translation>タイムアウト %1 ms は使用できません: 10–10000 ms、または既定値には -1 を使用してください。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="156"/>
        <source>%1 retries are not allowed: use 0–10, or -1 for the default.</source>
        <translation>リトライ %1 回は使用できません: 0–10、または既定値には -1 を使用してください。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="169"/>
        <source>Function 0x%1 cannot be broadcast: only functions 06h and 10h (writes) may be sent to machine number 0; use slave address 1–247.</source>
        <translation>ファンクション 0x%1 はブロードキャストできません: 局番 0 に送信できるのはファンクション 06h と 10h（書込み）のみです。スレーブアドレス 1–247 を使用してください。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="176"/>
        <source>Function code 0x%1 must be sent as a raw request.</source>
        <translation>ファンクションコード 0x%1 は raw 要求として送信する必要があります。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="180"/>
        <source>Raw request data of %1 bytes is too long: at most %2 bytes.</source>
        <translation>%1 バイトの raw 要求データは長すぎます: 最大 %2 バイトです。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="193"/>
        <source>Cannot read %1 registers at once: use 1–125 registers.</source>
        <translation>%1 レジスタを一度に読み出せません: 1–125 レジスタを使用してください。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="200"/>
        <source>Write single register needs exactly 1 value, not %1.</source>
        <translation>単一レジスタ書込みには値が 1 つだけ必要です（%1 個ではなく）。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="206"/>
        <source>Cannot write %1 registers at once: use 1–123 registers.</source>
        <translation>%1 レジスタを一度に書き込めません: 1–123 レジスタを使用してください。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="211"/>
        <source>%1 values given for %2 registers.</source>
        <translation>%2 レジスタに対して %1 個の値が指定されています。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="220"/>
        <source>Registers %1 ×%2 run past the last address 0xFFFF.</source>
        <translation>レジスタ %1 ×%2 が最終アドレス 0xFFFF を超えています。</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="231"/>
        <source>device identification code %1 object %2</source>
        <translation>デバイス識別 コード %1 オブジェクト %2</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="239"/>
        <source>raw %1 %2</source>
        <translation>raw %1 %2</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="243"/>
        <source>read %1 %2 ×%3</source>
        <translation>読出し %1 %2 ×%3</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="247"/>
        <source>write %1 %2 = %3</source>
        <translation>書込み %1 %2 = %3</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="250"/>
        <source>write %1 %2 ×%3 = %4</source>
        <translation>書込み %1 %2 ×%3 = %4</translation>
    </message>
    <message>
        <location filename="../transport/ModbusRequest.cpp" line="256"/>
        <source>broadcast %1</source>
        <translation>ブロードキャスト %1</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="11"/>
        <source>ok</source>
        <translation>OK</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="13"/>
        <source>timeout</source>
        <translation>タイムアウト</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="15"/>
        <source>CRC error</source>
        <translation>CRC エラー</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="17"/>
        <source>reply from wrong slave</source>
        <translation>異なるスレーブからの応答</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="19"/>
        <source>exception</source>
        <translation>例外</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="21"/>
        <source>malformed reply</source>
        <translation>不正な応答</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="23"/>
        <source>port error</source>
        <translation>ポートエラー</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="25"/>
        <source>not connected</source>
        <translation>未接続</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="27"/>
        <source>invalid request</source>
        <translation>不正な要求</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="29"/>
        <source>cancelled</source>
        <translation>キャンセル</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="38"/>
        <source>Illegal function</source>
        <translation>不正なファンクション</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="40"/>
        <source>Illegal data address</source>
        <translation>不正なデータアドレス</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="42"/>
        <source>Illegal data value</source>
        <translation>不正なデータ値</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="44"/>
        <source>Slave device failure</source>
        <translation>スレーブデバイス障害</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="46"/>
        <source>Acknowledge (processing)</source>
        <translation>確認応答（処理中）</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="48"/>
        <source>Slave device busy</source>
        <translation>スレーブデバイスビジー</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="50"/>
        <source>Negative acknowledge</source>
        <translation>否定応答</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="52"/>
        <source>Memory parity error</source>
        <translation>メモリパリティエラー</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="54"/>
        <source>Gateway path unavailable</source>
        <translation>ゲートウェイパス使用不可</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="56"/>
        <source>Gateway target device failed to respond</source>
        <translation>ゲートウェイ先デバイス応答なし</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="60"/>
        <source>Prohibited action</source>
        <translation>禁止操作</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="62"/>
        <source>Undefined error</source>
        <translation>未定義エラー</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="64"/>
        <source>Unknown exception</source>
        <translation>不明な例外</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="74"/>
        <source>exception %1 %2</source>
        <translation>例外 %1 %2</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="79"/>
        <source>timeout after %1 attempts</source>
        <translation>%1 回試行後にタイムアウト</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="81"/>
        <source>timeout (no reply)</source>
        <translation>タイムアウト（応答なし）</translation>
    </message>
    <message>
        <location filename="../transport/ModbusResult.cpp" line="89"/>
        <source> (%1 attempts)</source>
        <translation> (%1 回試行)</translation>
    </message>
    <message>
        <location filename="../transport/PortLock.cpp" line="22"/>
        <source>%1 is in use by another program; close it first.</source>
        <translation>%1 は他のプログラムが使用中です。先に終了してください。</translation>
    </message>
    <message>
        <location filename="../transport/PortLock.cpp" line="27"/>
        <source>another program</source>
        <translation>他のプログラム</translation>
    </message>
    <message>
        <location filename="../transport/PortLock.cpp" line="29"/>
        <source>%1 is in use by %2 (PID %3); close it first.</source>
        <translation>%1 は %2 (PID %3) が使用中です。先に終了してください。</translation>
    </message>
    <message>
        <location filename="../transport/RtuBackend.cpp" line="127"/>
        <source>: your user may not open serial ports. Add it to the dialout group with
    sudo usermod -aG dialout $USER
then log out and in again (the group applies to new sessions only).</source>
        <translation>: このユーザはシリアルポートを開けません。次のコマンドで dialout グループに追加し
    sudo usermod -aG dialout $USER
ログアウトして再ログインしてください（グループは新しいセッションにのみ適用されます）。</translation>
    </message>
    <message>
        <location filename="../transport/RtuBackend.cpp" line="134"/>
        <source> (the device may not support this parity; ptys need N)</source>
        <translation> (デバイスがこのパリティに対応していない可能性があります。pty は N が必要です)</translation>
    </message>
    <message>
        <location filename="../transport/RtuBackend.cpp" line="169"/>
        <source>reply announces %1 bytes, more than an RTU frame holds</source>
        <translation>応答が %1 バイトを示していますが、RTU フレームの最大長を超えています</translation>
    </message>
    <message>
        <location filename="../transport/RtuBackend.cpp" line="190"/>
        <source>no reply</source>
        <translation>応答なし</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="127"/>
        <source>reply too short (%1 bytes)</source>
        <translation>応答が短すぎます (%1 バイト)</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="148"/>
        <source>exception reply of %1 bytes</source>
        <translation>%1 バイトの例外応答</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="159"/>
        <source>reply function %1, expected %2</source>
        <translation>応答ファンクション %1、期待値 %2</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="166"/>
        <source>reply ends inside its own data</source>
        <translation>応答がデータの途中で終わっています</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="171"/>
        <source>reply of %1 bytes, expected %2</source>
        <translation>応答 %1 バイト、期待値 %2</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="181"/>
        <source>MEI type %1, expected %2</source>
        <translation>MEI タイプ %1、期待値 %2</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="194"/>
        <source>byte count %1, expected %2</source>
        <translation>バイト数 %1、期待値 %2</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="207"/>
        <source>echo %1 = %2 differs from the write</source>
        <translation>エコー %1 = %2 が書込み内容と異なります</translation>
    </message>
    <message>
        <location filename="../transport/RtuFrame.cpp" line="218"/>
        <source>echo %1 ×%2 differs from the write</source>
        <translation>エコー %1 ×%2 が書込み内容と異なります</translation>
    </message>
    <message>
        <location filename="../transport/SerialPortList.cpp" line="87"/>
        <source>An adapter missing here has no driver: see Device Manager, Ports (COM &amp; LPT). A port can also be typed, e.g. COM12.</source>
        <translation>ここに表示されないアダプターにはドライバーがありません: デバイス マネージャーの「ポート (COM と LPT)」を確認してください。ポート名を直接入力することもできます（例: COM12）。</translation>
    </message>
    <message>
        <location filename="../transport/SerialPortList.cpp" line="92"/>
        <source>Pseudo-terminals (e.g. /dev/pts/3 or a socat link) are not listed: type their path.</source>
        <translation>疑似端末（例: /dev/pts/3 や socat のリンク）は一覧に表示されません: パスを入力してください。</translation>
    </message>
    <message>
        <location filename="../transport/TcpBackend.cpp" line="61"/>
        <source>Cannot open %1: the name %2 was not found (%3); check the gateway&apos;s name, or give its address</source>
        <translation>%1 を開けません: 名前 %2 が見つかりません（%3）。ゲートウェイの名前を確認するか、アドレスを指定してください</translation>
    </message>
    <message>
        <location filename="../transport/TcpBackend.cpp" line="128"/>
        <source>MBAP length %1</source>
        <translation>MBAP 長 %1</translation>
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
        <translation>エラー: %1</translation>
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
        <translation>送信中 RTS High</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="32"/>
        <source>RTS low while sending</source>
        <translation>送信中 RTS Low</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="35"/>
        <source>, %1 before and after</source>
        <translation>、送信前後 %1</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="37"/>
        <source>, %1 before, %2 after</source>
        <translation>、送信前 %1、送信後 %2</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="43"/>
        <source>RS-485: switched by the adapter</source>
        <translation>RS-485: アダプタが切替</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="45"/>
        <source>RS-485: kernel mode left on by the driver (%1)</source>
        <translation>RS-485: シリアルドライバがカーネルモードをオンのまま維持（%1）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="49"/>
        <source>RS-485: kernel (%1)</source>
        <translation>RS-485: カーネル（%1）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="52"/>
        <source>RS-485: RTS from the program (%1; kernel mode refused: %2)</source>
        <translation>RS-485: プログラムによる RTS 制御（%1。カーネルモードは拒否: %2）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="56"/>
        <source>RS-485: RTS from the program (%1)</source>
        <translation>RS-485: プログラムによる RTS 制御（%1）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="61"/>
        <source>RS-485: not available (kernel mode refused: %1; RTS not switchable: %2)</source>
        <translation>RS-485: 使用不可（カーネルモードは拒否: %1。RTS は切替不可: %2）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="66"/>
        <source>RS-485: RTS not switchable on this port (%1)</source>
        <translation>RS-485: このポートでは RTS を切替不可（%1）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="69"/>
        <source>RS-485: kernel mode refused by the driver (%1)</source>
        <translation>RS-485: シリアルドライバがカーネルモードを拒否（%1）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="78"/>
        <source>latency timer %1 ms</source>
        <translation>レイテンシタイマ %1 ms</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="86"/>
        <source>low latency: not a UART, no adapter latency</source>
        <translation>低レイテンシ: UART ではない、アダプタ遅延なし</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="90"/>
        <source>low latency: on (but %1)</source>
        <translation>低レイテンシ: オン（ただし %1）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="92"/>
        <source>low latency: on</source>
        <translation>低レイテンシ: オン</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="95"/>
        <source>low latency: the driver&apos;s setting (FTDI: Latency Timer 1 ms in Device Manager)</source>
        <translation>低遅延: ドライバーの設定（FTDI: デバイス マネージャーで Latency Timer を 1 ms に）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="100"/>
        <source>low latency: not offered by the driver (%1)</source>
        <translation>低レイテンシ: シリアルドライバが非対応（%1）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="104"/>
        <source>low latency: not offered by the driver (USB adapter: up to %1 ms assumed)</source>
        <translation>低レイテンシ: シリアルドライバが非対応（USB アダプタ: 最大 %1 ms と想定）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="108"/>
        <source>low latency: not offered by the driver</source>
        <translation>低レイテンシ: シリアルドライバが非対応</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="112"/>
        <source>low latency: off</source>
        <translation>低レイテンシ: オフ</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="113"/>
        <source>low latency: off (%1)</source>
        <translation>低レイテンシ: オフ（%1）</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="137"/>
        <source>low latency is off</source>
        <translation>低レイテンシがオフ</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="139"/>
        <source>the driver took low latency but kept its latency timer</source>
        <translation>シリアルドライバは低レイテンシを受け付けたが、レイテンシタイマはそのまま</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="142"/>
        <source>the driver did not take low latency</source>
        <translation>シリアルドライバが低レイテンシを受け付けなかった</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="145"/>
        <source>see docs/hardware.md, or use an adapter whose driver offers low latency</source>
        <translation>docs/hardware.md を参照するか、シリアルドライバが低レイテンシに対応したアダプタを使用してください</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="149"/>
        <source>as root: echo 1 &gt; %1, or the udev rule in docs/hardware.md</source>
        <translation>root で実行: echo 1 &gt; %1、または docs/hardware.md の udev ルールを使用</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineReport.cpp" line="153"/>
        <source>The adapter holds received bytes for up to %1 ms before passing them on (%2). Fix: %3.</source>
        <translation>アダプタは受信したバイトを最大 %1 ms 保持してから渡します（%2）。対処: %3。</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineSetup.cpp" line="131"/>
        <source>the driver left it off</source>
        <translation>シリアルドライバがオフのままにした</translation>
    </message>
    <message>
        <location filename="../transport/SerialLineSetup.cpp" line="200"/>
        <source>the port does not take %1</source>
        <translation>ポートが %1 を受け付けません</translation>
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
        <translation>時刻 (hh:mm:ss)</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendChart.cpp" line="109"/>
        <source>Drive %1</source>
        <translation>ドライバ %1</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendChart.cpp" line="300"/>
        <source>There is no trend data to export yet.</source>
        <translation>エクスポートするトレンドデータがまだありません。</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendChart.cpp" line="313"/>
        <source>Cannot write the picture %1.</source>
        <translation>画像 %1 を書き込めません。</translation>
    </message>
</context>
<context>
    <name>opentop::TrendCsv</name>
    <message>
        <location filename="../model/monitor/TrendCsv.cpp" line="28"/>
        <source>time</source>
        <translation>時刻</translation>
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
        <translation>一時停止</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="51"/>
        <source>Live</source>
        <translation>ライブ</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="54"/>
        <source>How often each charted drive is polled. Commands you give always go first; the drives take turns on the bus.</source>
        <translation>グラフ表示中の各ドライバをポーリングする頻度。操作したコマンドは常に優先され、各ドライバは順番にバスを使用します。</translation>
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
        <translation>グラフを停止します。値の記録は続けます。</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="78"/>
        <source>Resume</source>
        <translation>再開</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="81"/>
        <source>Back to the latest values after zooming or pausing.</source>
        <translation>ズームや一時停止の後、最新の値に戻ります。</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="86"/>
        <source>Clear markers</source>
        <translation>マーカをクリア</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="89"/>
        <source>Export CSV…</source>
        <translation>CSV エクスポート…</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="92"/>
        <source>Export PNG…</source>
        <translation>PNG エクスポート…</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="97"/>
        <source>Drive / quantity</source>
        <translation>ドライバ / 測定項目</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="111"/>
        <source>Poll rate:</source>
        <translation>ポーリング頻度:</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="113"/>
        <source>Window:</source>
        <translation>表示範囲:</translation>
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
        <translation>トレンドを CSV でエクスポート</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="253"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV ファイル (*.csv)</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="256"/>
        <source>Export CSV</source>
        <translation>CSV エクスポート</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="262"/>
        <source>Export trend as picture</source>
        <translation>トレンドを画像でエクスポート</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="263"/>
        <source>PNG pictures (*.png)</source>
        <translation>PNG 画像 (*.png)</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendPanel.cpp" line="266"/>
        <source>Export PNG</source>
        <translation>PNG エクスポート</translation>
    </message>
</context>
<context>
    <name>opentop::TrendReadout</name>
    <message>
        <location filename="../ui/trends/TrendReadout.cpp" line="25"/>
        <source>Markers: click in the chart to set marker A, click again to set marker B.</source>
        <translation>マーカ: グラフをクリックするとマーカ A、もう一度クリックするとマーカ B を設定します。</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendReadout.cpp" line="28"/>
        <source>A %1   B %2   Δt = B − A = %3 s</source>
        <translation>A %1   B %2   Δt = B − A = %3 s</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendReadout.cpp" line="31"/>
        <source>A %1   (click in the chart to set marker B)</source>
        <translation>A %1   （グラフをクリックしてマーカ B を設定）</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendReadout.cpp" line="32"/>
        <source>B %1   (click in the chart to set marker A)</source>
        <translation>B %1   （グラフをクリックしてマーカ A を設定）</translation>
    </message>
    <message>
        <location filename="../ui/trends/TrendReadout.cpp" line="34"/>
        <source>no data</source>
        <translation>データなし</translation>
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
        <translation>DC コントローラの速度ループのステップ試験とリレーオートチューニング（--yes が必要）</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="88"/>
        <source>Run the test (it moves the motor).</source>
        <translation>試験を実行します（モータが動きます）。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="89"/>
        <source>step: speed before the step (default 0).</source>
        <translation>step: ステップ前の速度（既定 0）。</translation>
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
        <translation>step: ステップ後の速度。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="91"/>
        <source>step: record this long after the step (default 1500).</source>
        <translation>step: ステップ後に記録する時間（既定 1500）。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="92"/>
        <source>MS</source>
        <translation>MS</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="93"/>
        <source>autotune: operating speed of the relay test.</source>
        <translation>autotune: リレー試験の運転速度。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="94"/>
        <source>autotune: output swing, % of full output (default 10).</source>
        <translation>autotune: 出力の振り幅。フル出力に対する %（既定 10）。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="95"/>
        <source>PERCENT</source>
        <translation>PERCENT</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="97"/>
        <source>autotune: soft, medium (default), stiff, tyreus-luyben or zn-pi.</source>
        <translation>autotune: soft、medium（既定）、stiff、tyreus-luyben、zn-pi のいずれか。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="97"/>
        <source>RULE</source>
        <translation>RULE</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="98"/>
        <source>autotune: write the proposed gains, then run a step test from half the operating speed to it.</source>
        <translation>autotune: 提案ゲインを書き込み、運転速度の半分から運転速度までのステップ試験を実行します。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="101"/>
        <source>autotune: with --accept, store the gains in the drive if the step measured with them passes the check.</source>
        <translation>autotune: --accept と併用すると、そのゲインで測定したステップが確認に合格した場合にゲインをドライバに保存します。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="104"/>
        <source>autotune: with --accept, keep (and with --store, store) gains whose measured step failed the check; without it they are written back to what the drive had.</source>
        <translation>autotune: --accept と併用すると、測定したステップが確認に不合格でもゲインを残します（--store があれば保存します）。指定しなければドライバの元のゲインを書き戻します。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="107"/>
        <source>Stop at once beyond this speed (default 120 % of the test&apos;s highest).</source>
        <translation>速度がこの値を超えたら直ちに停止します（既定: 試験の最高速度の 120 %）。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="108"/>
        <source>Stop at once beyond this current in A (default 20).</source>
        <translation>電流がこの値 (A) を超えたら直ちに停止します（既定 20）。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="109"/>
        <source>A</source>
        <translation>A</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="110"/>
        <source>Write the samples to FILE.</source>
        <translation>サンプルを FILE に書き出します。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="110"/>
        <source>FILE</source>
        <translation>FILE</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="124"/>
        <source>error: usage: %1</source>
        <translation>エラー: 使い方: %1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="134"/>
        <source>error: --%1 must be a number 0 or more, got &apos;%2&apos;</source>
        <translation>エラー: --%1 は 0 以上の数値でなければなりません（指定値 &apos;%2&apos;）</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="156"/>
        <location filename="../cli/TuneCommand.cpp" line="167"/>
        <location filename="../cli/TuneCommand.cpp" line="172"/>
        <location filename="../cli/TuneCommand.cpp" line="375"/>
        <source>error: %1</source>
        <translation>エラー: %1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="157"/>
        <source>step needs --to SPEED</source>
        <translation>step には --to SPEED が必要です</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="158"/>
        <source>--rule must be one of %1</source>
        <translation>--rule は %1 のいずれかでなければなりません</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="160"/>
        <source>autotune needs --speed SPEED</source>
        <translation>autotune には --speed SPEED が必要です</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="176"/>
        <source>Would run the motor of machine number %1 from %2 to %3 and record the step response.</source>
        <translation>局番 %1 のモータを %2 から %3 へ運転し、ステップ応答を記録します。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="181"/>
        <source>Would run the motor of machine number %1 in a relay test around %2 (output ±%3 %).</source>
        <translation>局番 %1 のモータを %2 付近でリレー試験運転します（出力 ±%3 %）。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="187"/>
        <source>This moves the motor: add --yes to run it.</source>
        <translation>モータが動きます: 実行するには --yes を付けてください。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="236"/>
        <source>Machine number %1, gains %2</source>
        <translation>局番 %1、ゲイン %2</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="238"/>
        <source>  rise time (10–90 %): %1</source>
        <translation>  立ち上がり時間 (10–90 %): %1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="239"/>
        <source>  overshoot: %1 %</source>
        <translation>  オーバーシュート: %1 %</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="240"/>
        <source>  settling time (2 %): %1</source>
        <translation>  整定時間 (2 %): %1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="241"/>
        <source>  steady-state error: %1 %2</source>
        <translation>  定常偏差: %1 %2</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="242"/>
        <source>  peak current: %1 A</source>
        <translation>  ピーク電流: %1 A</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="268"/>
        <source>Step %1 → %2 %3:</source>
        <translation>ステップ %1 → %2 %3:</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="273"/>
        <source>Relay test: Ku %1, Tu %2 ms measured (amplitude ±%3 %4, %5 cycles, %6 readings per period, one every %7 ms)</source>
        <translation>リレー試験: Ku %1、Tu %2 ms（実測、振幅 ±%3 %4、%5 周期、1 周期あたり読出し %6 回、%7 ms ごと）</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="365"/>
        <source>What to change: %1</source>
        <translation>変更すべき点: %1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="282"/>
        <source>Model: gain %1, time constant %2 ms, dead time %3 ms (the bus&apos;s %4 ms left out)</source>
        <translation>モデル: ゲイン %1、時定数 %2 ms、むだ時間 %3 ms（バスの %4 ms は除外）</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="288"/>
        <source>The drive&apos;s own loop on the model: Ku %1, Tu %2 ms</source>
        <translation>モデル上のドライバ自身のループ: Ku %1、Tu %2 ms</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="291"/>
        <source>Proposed (%1): %2</source>
        <translation>提案値 (%1): %2</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="292"/>
        <source>  the rule&apos;s P × %1, Ti × %2; predicted step %3 → %4 %5: overshoot %6 %, settling time %7</source>
        <translation>  ルールの P × %1、Ti × %2。予測ステップ %3 → %4 %5: オーバーシュート %6 %、整定時間 %7</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="308"/>
        <source>Writing the proposed gains failed: %1</source>
        <translation>提案ゲインの書込みに失敗しました: %1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="311"/>
        <source>Proposed gains written (not stored).</source>
        <translation>提案ゲインを書き込みました（未保存）。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="314"/>
        <source>Measured step %1 → %2 %3 with them:</source>
        <translation>このゲインで測定したステップ %1 → %2 %3:</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="322"/>
        <source>interrupted</source>
        <translation>中断</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="325"/>
        <source>Check after Accept: passed. %1</source>
        <translation>採用後の確認: 合格。%1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="326"/>
        <source>Check after Accept: FAILED. %1</source>
        <translation>採用後の確認: 不合格。%1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="335"/>
        <source>The gains before were written back (%1); nothing was stored. --override-check keeps the proposal (and with --store stores it) all the same.</source>
        <translation>元のゲインを書き戻しました (%1)。何も保存していません。--override-check を付けると、それでも提案値を残します（--store があれば保存します）。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="339"/>
        <source>Writing back the gains before failed: %1; the proposal is still in the drive (not stored).</source>
        <translation>元のゲインの書き戻しに失敗しました: %1。提案値はドライバに残っています（未保存）。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="346"/>
        <source>Storing although the check failed (--override-check).</source>
        <translation>確認は不合格ですが保存します (--override-check)。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="355"/>
        <source>Gains stored in the drive.</source>
        <translation>ゲインをドライバに保存しました。</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="356"/>
        <source>Storing the gains failed: %1</source>
        <translation>ゲインの保存に失敗しました: %1</translation>
    </message>
    <message>
        <location filename="../cli/TuneCommand.cpp" line="363"/>
        <source>Test ended: %1</source>
        <translation>試験終了: %1</translation>
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
        <translation>チューニング試験がすでに実行中です</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="88"/>
        <source>Reading the drive&apos;s settings</source>
        <translation>ドライバの設定を読出し中</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="98"/>
        <source>could not read the drive&apos;s settings: %1</source>
        <translation>ドライバの設定を読み出せませんでした: %1</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="139"/>
        <source>the drive is not in a closed-loop speed mode: set %1 (%2) to %3 first</source>
        <translation>ドライバが閉ループ速度モードではありません: 先に %1 (%2) を %3 に設定してください</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="141"/>
        <source> or </source>
        <translation> または </translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="146"/>
        <source>Setting the communication-loss braking time to %1 s</source>
        <translation>通信断停止時間を %1 s に設定中</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="201"/>
        <source>the drive stopped answering: %1</source>
        <translation>ドライバが応答しなくなりました: %1</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="221"/>
        <source>speed %1 %2 beyond the test&apos;s limit %3 %2: stopped at once</source>
        <translation>速度 %1 %2 が試験の制限値 %3 %2 を超えました: 即時停止</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="228"/>
        <source>current %1 A beyond the test&apos;s limit %2 A: stopped at once</source>
        <translation>電流 %1 A が試験の制限値 %2 A を超えました: 即時停止</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="234"/>
        <source>cancelled</source>
        <translation>キャンセル</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="271"/>
        <source>Stopping the motor</source>
        <translation>モータを停止中</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="303"/>
        <source>motor stopped (confirmed)</source>
        <translation>モータ停止（確認済み）</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningDrive.cpp" line="304"/>
        <source>the motor could not be confirmed stopped: check it</source>
        <translation>モータの停止を確認できません: モータを点検してください</translation>
    </message>
</context>
<context>
    <name>opentop::TuningDriveSettings</name>
    <message>
        <location filename="../ui/tuning/TuningDriveSettings.cpp" line="53"/>
        <source>Could not read the speed mode: %1</source>
        <translation>速度モードを読み出せませんでした: %1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningDriveSettings.cpp" line="56"/>
        <source>The drive is not in a closed-loop speed mode (now: %1). Choose one on its settings page first.</source>
        <translation>ドライバが閉ループ速度モードではありません（現在: %1）。先に設定ページで閉ループモードを選択してください。</translation>
    </message>
</context>
<context>
    <name>opentop::TuningGains</name>
    <message>
        <location filename="../ui/tuning/TuningGains.cpp" line="43"/>
        <source>Writing the gains failed: %1</source>
        <translation>ゲインの書込みに失敗しました: %1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningGains.cpp" line="62"/>
        <source>Proposal written (temporary until stored).</source>
        <translation>提案値を書き込みました（保存するまでは一時的）。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningGains.cpp" line="83"/>
        <source>%1: the gains before were written back (%2).</source>
        <translation>%1: 元のゲインを書き戻しました (%2)。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningGains.cpp" line="102"/>
        <source>Gains stored in the drive.</source>
        <translation>ゲインをドライバに保存しました。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningGains.cpp" line="104"/>
        <source>Storing the gains failed: %1</source>
        <translation>ゲインの保存に失敗しました: %1</translation>
    </message>
</context>
<context>
    <name>opentop::TuningLimitsBox</name>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="12"/>
        <source>Limits</source>
        <translation>制限値</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="17"/>
        <source>Beyond it the motor is stopped at once. Empty: 125 % of the step test&apos;s highest speed, 150 % of the autotune&apos;s speed</source>
        <translation>この値を超えるとモータを即時停止します。空欄: ステップ試験の最高速度の 125 %、オートチューニング速度の 150 %</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="19"/>
        <source>Beyond it the motor is stopped at once. Empty: 1.2 × the drive&apos;s maximum current</source>
        <translation>この値を超えるとモータを即時停止します。空欄: 1.2 × ドライバの最大電流</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="22"/>
        <source>Max. speed:</source>
        <translation>最高速度:</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="23"/>
        <source>Max. current:</source>
        <translation>最大電流:</translation>
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
        <translation>自動: %1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="39"/>
        <source>none</source>
        <translation>なし</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="48"/>
        <source>Enter a speed limit above 0 %1, or leave it empty.</source>
        <translation>0 %1 より大きい速度制限値を入力するか、空欄にしてください。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningLimitsBox.cpp" line="52"/>
        <source>Enter a current limit above 0 A, or leave it empty.</source>
        <translation>0 A より大きい電流制限値を入力するか、空欄にしてください。</translation>
    </message>
</context>
<context>
    <name>opentop::TuningMetricsView</name>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="25"/>
        <source>Rise time (10–90 %):</source>
        <translation>立ち上がり時間 (10–90 %):</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="26"/>
        <source>Overshoot:</source>
        <translation>オーバーシュート:</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="27"/>
        <source>Settling time (2 %):</source>
        <translation>整定時間 (2 %):</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="28"/>
        <source>Steady-state error:</source>
        <translation>定常偏差:</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="29"/>
        <source>Peak current:</source>
        <translation>ピーク電流:</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="40"/>
        <source>No run yet</source>
        <translation>まだ実行していません</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="41"/>
        <source>%1: recording</source>
        <translation>%1: 記録中</translation>
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
        <translation>未到達</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="54"/>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningMetricsView.cpp" line="56"/>
        <source>not settled</source>
        <translation>未整定</translation>
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
        <translation>立ち上がり時間 %1、オーバーシュート %2、整定時間 %3、定常偏差 %4、ピーク電流 %5</translation>
    </message>
</context>
<context>
    <name>opentop::TuningPage</name>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="53"/>
        <location filename="../ui/tuning/TuningPage.cpp" line="213"/>
        <source>Step test</source>
        <translation>ステップ試験</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="54"/>
        <location filename="../ui/tuning/TuningPage.cpp" line="234"/>
        <source>Relay autotune</source>
        <translation>リレーオートチューニング</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="112"/>
        <source>Ready. Nothing moves until you confirm a test.</source>
        <translation>準備完了。試験を確認するまでモータは動きません。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="191"/>
        <source>Limits: %1 %2, %3.</source>
        <translation>制限値: %1 %2、%3。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="193"/>
        <source>%1 A</source>
        <translation>%1 A</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="193"/>
        <source>no current limit</source>
        <translation>電流制限なし</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="208"/>
        <source>The motor of %1 will run from %2 to %3 %4 in its present speed mode, for about %5 s, and then stop.</source>
        <translation>%1 のモータが現在の速度モードで %2 から %3 %4 まで約 %5 s 運転し、その後停止します。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="213"/>
        <location filename="../ui/tuning/TuningPage.cpp" line="234"/>
        <source>Run</source>
        <translation>実行</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="229"/>
        <source>The motor of %1 will run in open loop (the speed loop off) around %2 %3, its output switching by ±%4 %, for up to %5 s, and then stop.</source>
        <translation>%1 のモータが開ループ（速度ループ無効）で %2 %3 付近を運転し、出力を ±%4 % で切り替えます。最大 %5 s 後に停止します。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="252"/>
        <source>Stop command sent.</source>
        <translation>停止コマンドを送信しました。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="253"/>
        <source>Stop command failed: %1</source>
        <translation>停止コマンドが失敗しました: %1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="263"/>
        <source>Stopping…</source>
        <translation>停止中…</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="277"/>
        <source>Run %1: %2 → %3 %4</source>
        <translation>実行 %1: %2 → %3 %4</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="296"/>
        <source>Step test done.</source>
        <translation>ステップ試験が完了しました。</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="297"/>
        <source>Step test ended: %1</source>
        <translation>ステップ試験終了: %1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="302"/>
        <source>The test was stopped</source>
        <translation>試験が停止されました</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="333"/>
        <source>Autotune ended: %1</source>
        <translation>オートチューニング終了: %1</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="335"/>
        <source>The autotune was stopped</source>
        <translation>オートチューニングが停止されました</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="344"/>
        <source>Predicted: %1 → %2 %3</source>
        <translation>予測: %1 → %2 %3</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningPage.cpp" line="347"/>
        <source>Autotune done: proposal %1. Accept writes it to the drive.</source>
        <translation>オートチューニング完了: 提案値 %1。採用するとドライバに書き込みます。</translation>
    </message>
</context>
<context>
    <name>opentop::TuningRules</name>
    <message>
        <location filename="../model/tuning/TuningRules.cpp" line="61"/>
        <source>Soft (no overshoot)</source>
        <translation>ソフト（オーバーシュートなし）</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningRules.cpp" line="63"/>
        <source>Medium (some overshoot)</source>
        <translation>標準（若干のオーバーシュート）</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningRules.cpp" line="65"/>
        <source>Stiff (Ziegler–Nichols)</source>
        <translation>高剛性（Ziegler–Nichols）</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningRules.cpp" line="67"/>
        <source>Tyreus–Luyben (robust)</source>
        <translation>Tyreus–Luyben（ロバスト）</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningRules.cpp" line="69"/>
        <source>PI only (Ziegler–Nichols)</source>
        <translation>PI のみ（Ziegler–Nichols）</translation>
    </message>
</context>
<context>
    <name>opentop::TuningRunList</name>
    <message>
        <location filename="../ui/tuning/TuningRunList.cpp" line="14"/>
        <source>Run</source>
        <translation>実行</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunList.cpp" line="14"/>
        <source>Gains</source>
        <translation>ゲイン</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunList.cpp" line="43"/>
        <source>%1 (recording)</source>
        <translation>%1（記録中）</translation>
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
        <translation>CSV を保存…</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="39"/>
        <source>Save PNG…</source>
        <translation>PNG を保存…</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="44"/>
        <source>Saves the selected run: its samples, gains and metrics</source>
        <translation>選択した実行結果を保存します: サンプル、ゲイン、指標</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="45"/>
        <source>Saves the chart as it is shown</source>
        <translation>表示どおりにグラフを保存します</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="46"/>
        <source>solid: speed · dotted: command · dash-dot: current (right axis) · dashed: predicted speed</source>
        <translation>実線: 速度 · 点線: 指令 · 一点鎖線: 電流（右軸） · 破線: 予測速度</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="220"/>
        <source>no run to save</source>
        <translation>保存する実行結果がありません</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="233"/>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="237"/>
        <source>Save run as CSV</source>
        <translation>実行結果を CSV で保存</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="234"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV ファイル (*.csv)</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="242"/>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="245"/>
        <source>Save chart as PNG</source>
        <translation>グラフを PNG で保存</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="243"/>
        <source>PNG images (*.png)</source>
        <translation>PNG 画像 (*.png)</translation>
    </message>
    <message>
        <location filename="../ui/tuning/TuningRunsView.cpp" line="245"/>
        <source>Could not write %1.</source>
        <translation>%1 に書き込めませんでした。</translation>
    </message>
</context>
<context>
    <name>opentop::TuningSpec</name>
    <message>
        <location filename="../model/tuning/TuningSpec.cpp" line="23"/>
        <source>%1 has no speed loop to tune</source>
        <translation>%1 にはチューニングする速度ループがありません</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningSpec.cpp" line="51"/>
        <source>%1: the profile&apos;s tuning needs the roles pidP, pidI, pidD, pidDPeriod, pidStore, speedMode, speedCommand, commLossTime, loadCurrent and output</source>
        <translation>%1: プロファイルのチューニングにはロール pidP、pidI、pidD、pidDPeriod、pidStore、speedMode、speedCommand、commLossTime、loadCurrent、output が必要です</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningSpec.cpp" line="61"/>
        <source>%1: the profile&apos;s tuning section needs periodMs ≥ 1, outputFullScale &gt; 0, openLoopMode and closedLoopModes with known feedback parameters</source>
        <translation>%1: プロファイルのチューニングセクションには periodMs ≥ 1、outputFullScale &gt; 0、openLoopMode、およびフィードバックパラメータが既知の closedLoopModes が必要です</translation>
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
        <translation>実行中の試験を中止します: モータを停止し、停止を確認します</translation>
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
        <translation>記録時間内になし</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningVerdict.cpp" line="20"/>
        <source>no step was measured to its end with these gains: %1</source>
        <translation>このゲインでステップを最後まで測定できませんでした: %1</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningVerdict.cpp" line="46"/>
        <source>the speed did not settle within %1 ms (±2 % of the step)</source>
        <translation>速度が %1 ms 以内に整定しませんでした（ステップの ±2 %）</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningVerdict.cpp" line="49"/>
        <source>it overshot by %1 % where %2 % was predicted (at most %3 points more are accepted)</source>
        <translation>オーバーシュートが %1 % でした（予測 %2 %、許容は予測 +%3 ポイントまで）</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningVerdict.cpp" line="60"/>
        <source>Measured: overshoot %1 % (predicted %2 %), settling time %3 (predicted %4), peak current %5 A.</source>
        <translation>実測: オーバーシュート %1 %（予測 %2 %）、整定時間 %3（予測 %4）、ピーク電流 %5 A。</translation>
    </message>
    <message>
        <location filename="../model/tuning/TuningVerdict.cpp" line="70"/>
        <source>Check failed: %1.</source>
        <translation>確認不合格: %1。</translation>
    </message>
</context>
<context>
    <name>opentop::UnitLog</name>
    <message>
        <location filename="../ui/eol/UnitLog.cpp" line="19"/>
        <source>Time</source>
        <translation>時刻</translation>
    </message>
    <message>
        <location filename="../ui/eol/UnitLog.cpp" line="19"/>
        <source>Serial</source>
        <translation>シリアル</translation>
    </message>
    <message>
        <location filename="../ui/eol/UnitLog.cpp" line="19"/>
        <source>Verdict</source>
        <translation>判定</translation>
    </message>
    <message>
        <location filename="../ui/eol/UnitLog.cpp" line="19"/>
        <source>Reason</source>
        <translation>理由</translation>
    </message>
    <message>
        <location filename="../ui/eol/UnitLog.cpp" line="32"/>
        <source>%1, NOT RECORDED</source>
        <translation>%1、未記録</translation>
    </message>
    <message>
        <location filename="../ui/eol/UnitLog.cpp" line="34"/>
        <source>%1 (kept on this station)</source>
        <translation>%1（このステーションに保管）</translation>
    </message>
</context>
<context>
    <name>opentop::UnitRecordJson</name>
    <message>
        <location filename="../model/eol/UnitRecordJson.cpp" line="115"/>
        <source>not a unit record (format is not &quot;%1&quot;)</source>
        <translation>製品の記録ではありません（format が &quot;%1&quot; ではありません）</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitRecordJson.cpp" line="118"/>
        <source>unit record version %1 is not known to this program (it reads up to %2)</source>
        <translation>製品記録のバージョン %1 はこのプログラムでは不明です（%2 まで読込み可能）</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitRecordJson.cpp" line="125"/>
        <source>the unit record has no serial number</source>
        <translation>製品記録にシリアル番号がありません</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitRecordJson.cpp" line="139"/>
        <source>unknown unit status &quot;%1&quot;</source>
        <translation>不明な製品ステータス &quot;%1&quot;</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitRecordJson.cpp" line="153"/>
        <source>unknown variant source &quot;%1&quot;</source>
        <translation>不明な機種の確認方法「%1」</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitRecordJson.cpp" line="192"/>
        <source>not JSON: %1</source>
        <translation>JSON ではありません: %1</translation>
    </message>
</context>
<context>
    <name>opentop::UnitStartGate</name>
    <message>
        <location filename="../model/station/UnitStartGate.cpp" line="45"/>
        <source>cancelled before it started</source>
        <translation>開始前に取り消されました</translation>
    </message>
    <message>
        <location filename="../model/station/UnitStartGate.cpp" line="80"/>
        <source>not connected to a bus</source>
        <translation>バスに接続されていません</translation>
    </message>
    <message>
        <location filename="../model/station/UnitStartGate.cpp" line="85"/>
        <source>a drive of the station is not safe: %1</source>
        <translation>ステーションのドライブが安全ではありません: %1</translation>
    </message>
</context>
<context>
    <name>opentop::UnitValuesCsv</name>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="74"/>
        <source>the CSV file is larger than %1 MB</source>
        <translation>CSV ファイルが %1 MB を超えています</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="76"/>
        <source>not a CSV text file (it holds NUL bytes)</source>
        <translation>CSV テキストファイルではありません（NUL バイトを含みます）</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="97"/>
        <source>line %1: a quoted field is not closed properly</source>
        <translation>%1 行目: 引用符で囲まれたフィールドが正しく閉じられていません</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="101"/>
        <source>line %1: the header must start with &quot;serial&quot;, not &quot;%2&quot;</source>
        <translation>%1 行目: ヘッダは &quot;%2&quot; ではなく &quot;serial&quot; で始まる必要があります</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="105"/>
        <source>line %1: the header names no per-unit value</source>
        <translation>%1 行目: ヘッダに個別値の名前がありません</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="107"/>
        <source>line %1: more than %2 columns</source>
        <translation>%1 行目: 列が %2 個を超えています</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="111"/>
        <source>line %1: column %2 has no name</source>
        <translation>%1 行目: 列 %2 に名前がありません</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="113"/>
        <source>line %1: column &quot;%2&quot; appears twice</source>
        <translation>%1 行目: 列 &quot;%2&quot; が 2 回出現しています</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="122"/>
        <source>line %1: %2 fields, but the header has %3</source>
        <translation>%1 行目: フィールドが %2 個ですが、ヘッダは %3 個です</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="128"/>
        <source>line %1: no serial number</source>
        <translation>%1 行目: シリアル番号がありません</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="130"/>
        <source>line %1: serial number &quot;%2&quot; is already on line %3</source>
        <translation>%1 行目: シリアル番号 &quot;%2&quot; はすでに %3 行目にあります</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="137"/>
        <source>the CSV file is empty; it needs a header &quot;serial,&lt;parameter&gt;,...&quot;</source>
        <translation>CSV ファイルが空です。ヘッダ &quot;serial,&lt;parameter&gt;,...&quot; が必要です</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="151"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="193"/>
        <source>serial number &quot;%1&quot; is not in the CSV file</source>
        <translation>シリアル番号 &quot;%1&quot; は CSV ファイルにありません</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="206"/>
        <source>%1: column &quot;%2&quot; is ambiguous, several positions have this per-unit value; name the column &quot;%3:%2&quot;</source>
        <translation>%1: 列 &quot;%2&quot; があいまいです（複数の位置にこの個別値があります）。列名を &quot;%3:%2&quot; にしてください</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="210"/>
        <source>%1: the CSV file has no column &quot;%2&quot; (or &quot;%3:%2&quot;) for this per-unit value</source>
        <translation>%1: CSV ファイルにこの個別値の列 &quot;%2&quot;（または &quot;%3:%2&quot;）がありません</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="215"/>
        <source>line %1, column &quot;%2&quot;: no value for serial number &quot;%3&quot;</source>
        <translation>%1 行目、列 &quot;%2&quot;: シリアル番号 &quot;%3&quot; の値がありません</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="225"/>
        <source>line %1, column &quot;%2&quot;: &quot;%3&quot; is not a number</source>
        <translation>%1 行目、列 &quot;%2&quot;: &quot;%3&quot; は数値ではありません</translation>
    </message>
    <message>
        <location filename="../model/eol/UnitValuesCsv.cpp" line="231"/>
        <source>line %1: %2</source>
        <translation>%1 行目: %2</translation>
    </message>
</context>
<context>
    <name>opentop::UserGuideDialog</name>
    <message>
        <location filename="../ui/help/UserGuideDialog.cpp" line="26"/>
        <source>OpenTOP user guide</source>
        <translation>OpenTOP ユーザガイド</translation>
    </message>
    <message>
        <location filename="../ui/help/UserGuideDialog.cpp" line="28"/>
        <source> or </source>
        <translation> または </translation>
    </message>
    <message>
        <location filename="../ui/help/UserGuideDialog.cpp" line="31"/>
        <source>&lt;h2&gt;Commissioning a drive with OpenTOP&lt;/h2&gt;&lt;ol&gt;&lt;li&gt;&lt;b&gt;Connect.&lt;/b&gt; Bus ▸ Connect… chooses the serial port (or USB to RS-485 adapter), a Modbus TCP gateway or a simulated bus, with the bus&apos;s baud rate, parity and stop bits. The status bar says what the program is connected to; a simulated bus is marked as such.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Find the drives.&lt;/b&gt; Bus ▸ Scan bus (F5) asks every machine number 1–247; the drives that answer are identified and listed on the left with their state and control priority.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Select a drive.&lt;/b&gt; Its pages open on the right: Monitor (live values), the parameter pages of its profile, Test run and Alarms.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Edit settings.&lt;/b&gt; An edited field is marked as pending until it is written. Write page (or Drive ▸ Write all pending, Ctrl+W) writes and reads every value back to verify it; Revert drops the edits; Re-read (Ctrl+R) reads the drive again. A value the drive would refuse is never sent: the field says why.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Test-run the motor.&lt;/b&gt; The Test run page starts, stops and reverses the drive in communication priority and asks before the first start of each drive. Return the drive to I/O priority when done, so that the machine&apos;s own inputs control it again.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Stop.&lt;/b&gt; STOP ALL on the toolbar, or %1, stops every drive on the bus at once, from any window of the program.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Watch.&lt;/b&gt; View ▸ Trends (Ctrl+G) charts speeds and loads; View ▸ Bus overview shows every drive at a glance; View ▸ Traffic log (Ctrl+T) shows each frame on the bus with its meaning.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Keep the settings.&lt;/b&gt; Files ▸ Back up saves the settings of one drive or the whole bus to a file; Files ▸ Compare shows differences between drives, files and factory defaults; Files ▸ Restore writes a backup back after a preview.&lt;/li&gt;&lt;/ol&gt;&lt;p&gt;Every keyboard shortcut is listed in Help ▸ Keyboard shortcuts.&lt;/p&gt;&lt;h3&gt;More documentation&lt;/h3&gt;&lt;p&gt;The command line and the simulator: &lt;code&gt;man opentop&lt;/code&gt;, &lt;code&gt;man opentop-cli&lt;/code&gt;, &lt;code&gt;man opentop-sim&lt;/code&gt;.&lt;/p&gt;</source>
        <translation>&lt;h2&gt;OpenTOP によるドライバの立上げ&lt;/h2&gt;&lt;ol&gt;&lt;li&gt;&lt;b&gt;接続。&lt;/b&gt;バス ▸ 接続… で、シリアルポート（または USB–RS-485 変換アダプタ）、Modbus TCP ゲートウェイ、シミュレーションバスのいずれかを、バスのボーレート、パリティ、ストップビットとともに選択します。ステータスバーに接続先が表示されます。シミュレーションバスの場合はその旨が表示されます。&lt;/li&gt;&lt;li&gt;&lt;b&gt;ドライバの検出。&lt;/b&gt;バス ▸ バスをスキャン (F5) で局番 1–247 に問い合わせます。応答したドライバが識別され、状態と制御優先とともに左側に一覧表示されます。&lt;/li&gt;&lt;li&gt;&lt;b&gt;ドライバの選択。&lt;/b&gt;右側にそのドライバのページが開きます: モニタ（ライブ値）、プロファイルのパラメータページ、試運転、アラーム。&lt;/li&gt;&lt;li&gt;&lt;b&gt;設定の編集。&lt;/b&gt;編集した項目は、書き込むまで未書込みとしてマークされます。「ページ書込み」（またはドライバ ▸ 未書込みをすべて書込み、Ctrl+W）で書き込み、すべての値を読み戻して照合します。「元に戻す」で編集を破棄し、「再読出し」(Ctrl+R) でドライバを再度読み出します。ドライバが拒否する値は送信されず、項目に理由が表示されます。&lt;/li&gt;&lt;li&gt;&lt;b&gt;モータの試運転。&lt;/b&gt;試運転ページでは、通信優先でドライバの運転開始、停止、逆転を行います。各ドライバの最初の運転開始前に確認します。終了したらドライバを I/O 優先に戻し、機械側の入力で再び制御できるようにしてください。&lt;/li&gt;&lt;li&gt;&lt;b&gt;停止。&lt;/b&gt;ツールバーの全停止、または %1 で、プログラムのどのウィンドウからでもバス上の全ドライバを一斉に停止します。&lt;/li&gt;&lt;li&gt;&lt;b&gt;監視。&lt;/b&gt;表示 ▸ トレンド (Ctrl+G) で速度と負荷をグラフ表示します。表示 ▸ バス一覧で全ドライバの状態を一覧できます。表示 ▸ 通信ログ (Ctrl+T) でバス上の各フレームとその意味を表示します。&lt;/li&gt;&lt;li&gt;&lt;b&gt;設定の保管。&lt;/b&gt;ファイル ▸ バックアップで 1 台またはバス全体の設定をファイルに保存します。ファイル ▸ 比較でドライバ、ファイル、工場出荷時設定の差異を表示します。ファイル ▸ 復元で、プレビューの後にバックアップを書き戻します。&lt;/li&gt;&lt;/ol&gt;&lt;p&gt;すべてのキーボードショートカットは、ヘルプ ▸ キーボードショートカットに一覧表示されます。&lt;/p&gt;&lt;h3&gt;その他のドキュメント&lt;/h3&gt;&lt;p&gt;コマンドラインとシミュレータ: &lt;code&gt;man opentop&lt;/code&gt;、&lt;code&gt;man opentop-cli&lt;/code&gt;、&lt;code&gt;man opentop-sim&lt;/code&gt;。&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../ui/help/UserGuideDialog.cpp" line="66"/>
        <source>&lt;h3&gt;Leaving a bus, and coming back after the link drops&lt;/h3&gt;&lt;p&gt;&lt;b&gt;Leaving.&lt;/b&gt; Quitting, Bus ▸ Disconnect or connecting elsewhere while drives run or are in communication priority names each of them and what will happen to it. The default stops every running drive, reads it back to confirm the stop, and then gives each drive back to its own inputs (I/O priority, read back), so that the machine works without OpenTOP. You may instead give control back only, leave the drives as they are, or stay.&lt;/p&gt;&lt;p&gt;&lt;b&gt;A lost link.&lt;/b&gt; When the adapter is pulled out or the gateway goes, every live value turns grey and a message says which drives were running or in communication priority when the link dropped, with the age of what is known. OpenTOP cannot stop them over a lost link: check the drive&apos;s STOP input, the emergency stop and the power on the machine. Bus ▸ Reconnect (Ctrl+R, also in the message and in the red bar) opens the same port again with the same drives, selected drive and page, reads every drive again and says at once if one is running. While connected, Ctrl+R re-reads the drive&apos;s pages.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;バスから離れるとき、接続が切れた後に再接続するとき&lt;/h3&gt;&lt;p&gt;&lt;b&gt;離れるとき。&lt;/b&gt;ドライバが運転中または通信優先のときに終了、バス ▸ 切断、または別の接続先への接続を行うと、各ドライバとそれに対して行う処理が表示されます。既定では、運転中のドライバをすべて停止し、読み出して停止を確認してから、各ドライバを自身の入力端子に戻し（I/O 優先、読み戻しで確認）、OpenTOP なしでも機械が動作するようにします。代わりに、制御を戻すだけ、ドライバをそのままにする、またはとどまることもできます。&lt;/p&gt;&lt;p&gt;&lt;b&gt;接続が切れたとき。&lt;/b&gt;アダプタが抜かれたりゲートウェイがなくなったりすると、すべてのライブ値がグレーになり、接続が切れた時点で運転中または通信優先だったドライバが、把握している値の経過時間とともにメッセージで示されます。切れた接続では OpenTOP はドライバを停止できません: 機械側でドライバの停止入力端子、非常停止、電源を確認してください。バス ▸ 再接続（Ctrl+R、メッセージと赤いバーにもあります）は、同じドライバ、選択中のドライバとページで同じポートを開き直し、すべてのドライバを読み出し直して、運転中のドライバがあればすぐに知らせます。接続中は、Ctrl+R でドライバのページを読み出し直します。&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../ui/help/UserGuideDialog.cpp" line="86"/>
        <source>&lt;p&gt;The full description of the program: &lt;a href=&quot;%1&quot;&gt;%2&lt;/a&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;プログラムの詳細な説明: &lt;a href=&quot;%1&quot;&gt;%2&lt;/a&gt;&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>opentop::UserStore</name>
    <message>
        <location filename="../model/access/UserStore.cpp" line="43"/>
        <source>a user name is 1 to 64 letters, digits or . _ @ - (no spaces): &quot;%1&quot;</source>
        <translation>ユーザー名は 1〜64 文字の英字、数字、. _ @ - です (空白なし): &quot;%1&quot;</translation>
    </message>
</context>
<context>
    <name>opentop::ValueCodec</name>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="63"/>
        <source>%1: %2 is outside the recommended range %3; it is allowed and will be written</source>
        <translation>%1: %2 は推奨範囲 %3 外です。許容される値のため書き込みます</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="80"/>
        <source> (the variant is not known, so the value must suit %1; name the variant to use its own range)</source>
        <translation> (機種が不明なため、値は %1 に適合する必要があります。機種を指定するとその機種の範囲を使用します)</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="90"/>
        <source>%1: the allowed values depend on %2, which has not been read</source>
        <translation>%1: 許容値が依存する %2 をまだ読み出していません</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="95"/>
        <source>%1: value out of the register&apos;s range; allowed: %2</source>
        <translation>%1: 値がレジスタの範囲外です。許容値: %2</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="107"/>
        <source>%1: %2 is not allowed; allowed: %3</source>
        <translation>%1: %2 は許可されていません。許容値: %3</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="119"/>
        <source>%1: expected %2 registers, got %3</source>
        <translation>%1: %2 レジスタが必要ですが、%3 レジスタでした</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="149"/>
        <source>%1 is text, not a number</source>
        <translation>%1 はテキストで、数値ではありません</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="162"/>
        <source>%1: %2 is finer than the step of %3 %4; allowed: %5</source>
        <translation>%1: %2 は %3 %4 の刻みより細かい値です。許容値: %5</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="195"/>
        <source>%1: at most %2 characters</source>
        <translation>%1: 最大 %2 文字</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="200"/>
        <source>%1: only printable ASCII characters are allowed</source>
        <translation>%1: 印字可能な ASCII 文字のみ使用できます</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="210"/>
        <source>%1: no value given; allowed: %2</source>
        <translation>%1: 値が指定されていません。許容値: %2</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="250"/>
        <source>%1: &quot;%2&quot; is only available when %3 is %4; allowed now: %5</source>
        <translation>%1: &quot;%2&quot; は %3 が %4 の場合のみ使用できます。現在の許容値: %5</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueCodec.cpp" line="263"/>
        <location filename="../model/profile/ValueCodec.cpp" line="283"/>
        <source>%1: &quot;%2&quot; is not a valid value; allowed: %3</source>
        <translation>%1: &quot;%2&quot; は有効な値ではありません。許容値: %3</translation>
    </message>
</context>
<context>
    <name>opentop::ValueFormat</name>
    <message>
        <location filename="../model/profile/ValueFormat.cpp" line="45"/>
        <source> or </source>
        <translation> または </translation>
    </message>
    <message>
        <location filename="../model/profile/ValueFormat.cpp" line="65"/>
        <source>depends on %1, which is not known yet</source>
        <translation>%1 に依存しますが、まだ不明です</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueFormat.cpp" line="67"/>
        <source>text of up to %1 characters</source>
        <translation>最大 %1 文字のテキスト</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueFormat.cpp" line="73"/>
        <source>, or </source>
        <translation>、または </translation>
    </message>
    <message>
        <location filename="../model/profile/ValueFormat.cpp" line="74"/>
        <source>any value</source>
        <translation>任意の値</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueFormat.cpp" line="81"/>
        <source>(invalid)</source>
        <translation>（無効）</translation>
    </message>
    <message>
        <location filename="../model/profile/ValueFormat.cpp" line="92"/>
        <source>unknown code %1</source>
        <translation>不明なコード %1</translation>
    </message>
</context>
<context>
    <name>opentop::VariantCheck</name>
    <message>
        <location filename="../model/eol/VariantCheck.cpp" line="23"/>
        <source>proving the variant (%1)</source>
        <translation>機種を確認中（%1）</translation>
    </message>
</context>
<context>
    <name>opentop::VariantDecision</name>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="39"/>
        <source>the variant probe left the drive changed: %1</source>
        <translation>機種判定でドライバが変更されたままになった: %1</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="44"/>
        <source>reported by the drive</source>
        <translation>ドライバが応答</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="53"/>
        <source>%1; named by %2</source>
        <translation>%1、%2 が指定</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="57"/>
        <source>given for the unit by %1 (eol run --variant)</source>
        <translation>%1 がこの製品に指定（eol run --variant）</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="62"/>
        <source>confirmed by the operator %1 (the recipe asks the operator)</source>
        <translation>作業者 %1 が確認（レシピが作業者の確認を求める）</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="67"/>
        <source>the recipe&apos;s only variant, not proven on the bus</source>
        <translation>レシピの唯一の機種、バス上では未確認</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="74"/>
        <source>the family has no variant probe</source>
        <translation>このシリーズには機種判定がない</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="76"/>
        <source>the probe leaves %1 (%2)</source>
        <translation>判定結果は %1 のいずれか（%2）</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="81"/>
        <source>the drive does not report its variant and it was not proven (%1)</source>
        <translation>ドライバは機種を応答せず、確認もできなかった（%1）</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="82"/>
        <source>the drive does not report its variant and it was not proven (%1); the recipe allows %2 and needs proof</source>
        <translation>ドライバは機種を応答せず、確認もできなかった（%1）。レシピは %2 を許可し、確認を必要とする</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="90"/>
        <source>the drive is a %1 (%2), but %3 was given for it</source>
        <translation>ドライバは %1（%2）だが、%3 が指定された</translation>
    </message>
    <message>
        <location filename="../model/eol/VariantDecision.cpp" line="93"/>
        <source>a %1 (%2), the recipe allows %3</source>
        <translation>%1（%2）、レシピが許可するのは %3</translation>
    </message>
</context>
<context>
    <name>opentop::VariantNeed</name>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="19"/>
        <source>%1 and %2 more</source>
        <translation>%1 ほか %2 件</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="69"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="77"/>
        <source>Allowed %1 — %2</source>
        <translation>許容値 %1 — %2</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="94"/>
        <source>The allowed values of the settings you are changing depend on it.</source>
        <translation>変更しようとしている設定の許容値は機種によって異なります。</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="97"/>
        <source>The backup file records it, and a restore checks the values against it.</source>
        <translation>バックアップファイルに機種が記録され、復元時にはそれに基づいて値を検査します。</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="100"/>
        <source>The speeds the motor may run at depend on it.</source>
        <translation>モータが運転できる速度は機種によって異なります。</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="104"/>
        <source>Which drive is %1? It reports only &quot;%2&quot;, not whether it is a %3.</source>
        <translation>%1 はどのドライバですか？「%2」としか報告せず、%3 のどれかは報告しません。</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="105"/>
        <source> or </source>
        <translation> または </translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="108"/>
        <source>Read it on the drive&apos;s rating plate. It is kept for this bus and asked once; without it every value must suit all of them.</source>
        <translation>ドライバの銘板で確認してください。このバスに保存され、一度だけ尋ねます。指定しない場合は、すべての値がすべての機種に適合する必要があります。</translation>
    </message>
    <message>
        <location filename="../model/bus/VariantNeed.cpp" line="112"/>
        <source>Last time on this bus it was set as %1.</source>
        <translation>前回このバスでは %1 に設定されていました。</translation>
    </message>
</context>
<context>
    <name>opentop::VariantProbe</name>
    <message>
        <location filename="../model/profile/VariantProbe.cpp" line="51"/>
        <source>unknown key &quot;%1&quot;</source>
        <translation>不明なキー「%1」</translation>
    </message>
    <message>
        <location filename="../model/profile/VariantProbe.cpp" line="58"/>
        <source>needs &quot;parameter&quot;, a number &quot;value&quot; and &quot;refusedCode&quot;</source>
        <translation>&quot;parameter&quot;、数値の &quot;value&quot; と &quot;refusedCode&quot; が必要</translation>
    </message>
    <message>
        <location filename="../model/profile/VariantProbe.cpp" line="63"/>
        <source>no parameter &quot;%1&quot;</source>
        <translation>パラメータ「%1」がない</translation>
    </message>
    <message>
        <location filename="../model/profile/VariantProbe.cpp" line="67"/>
        <source>%1 must be a readable, writable setting that no role names (never a command or a motion register)</source>
        <translation>%1 は読出し・書込みでき、どの役割にも使われていない設定であること（コマンドや運転レジスタは不可）</translation>
    </message>
    <message>
        <location filename="../model/profile/VariantProbe.cpp" line="77"/>
        <source>%1 = %2 must be allowed on some variants and refused on others</source>
        <translation>%1 = %2 は一部の機種で許可され、他の機種で拒否される値であること</translation>
    </message>
</context>
<context>
    <name>opentop::VariantProber</name>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="47"/>
        <location filename="../model/session/VariantProber.cpp" line="85"/>
        <source>%1 cannot be read: %2</source>
        <translation>%1 を読み出せない: %2</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="63"/>
        <source>%1 still holds %2 from a variant probe that was interrupted, and cannot be set back to %3 (%4): set it to %3 before this drive is used</source>
        <translation>%1 に中断した機種判定の %2 が残っており、%3 に戻せません (%4): このドライバを使う前に %3 に設定してください</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="71"/>
        <source>%1 set back from %2 to %3, left by a variant probe that was interrupted</source>
        <translation>%1 を %2 から %3 に戻しました (中断した機種判定が残した値)</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="102"/>
        <source>not probed: the original value cannot be kept while it is (%1)</source>
        <translation>判定していません: 判定中に元の値を保存できません (%1)</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="123"/>
        <source>the probe %1 was not answered as the manual says: %2</source>
        <translation>機種判定 %1 への応答がマニュアルどおりでない: %2</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="147"/>
        <source>%1 could not be set back to %2 after the variant probe (%3): set it to %2 before this drive is used</source>
        <translation>機種判定の後、%1 を %2 に戻せなかった（%3）: このドライバを使う前に %2 に設定してください</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="152"/>
        <source>%1 accepted, %2 written back</source>
        <translation>%1 を受付、%2 に書き戻し済み</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="160"/>
        <source>%1 refused (%2)</source>
        <translation>%1 を拒否（%2）</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="171"/>
        <source>%1 does not read back as %2 after the variant probe (%3): set it to %2 before this drive is used</source>
        <translation>機種判定の後、%1 の読出し値が %2 でない（%3）: このドライバを使う前に %2 に設定してください</translation>
    </message>
    <message>
        <location filename="../model/session/VariantProber.cpp" line="181"/>
        <source>the probe did not decide</source>
        <translation>判定できなかった</translation>
    </message>
</context>
<context>
    <name>opentop::VariantQuestion</name>
    <message>
        <location filename="../ui/bus/VariantQuestion.cpp" line="29"/>
        <source>Which drive is it?</source>
        <translation>どのドライバですか？</translation>
    </message>
    <message>
        <location filename="../ui/bus/VariantQuestion.cpp" line="42"/>
        <source>Not known: check against every variant</source>
        <translation>不明：すべての機種で検査</translation>
    </message>
    <message>
        <location filename="../ui/bus/VariantQuestion.cpp" line="65"/>
        <source>the variant of %1 was not given</source>
        <translation>%1 の機種が指定されていません</translation>
    </message>
</context>
<context>
    <name>opentop::VerdictLook</name>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="16"/>
        <source>READY</source>
        <translation>準備完了</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="17"/>
        <source>TESTING</source>
        <translation>試験中</translation>
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
        <translation>ステーションエラー</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="24"/>
        <source>ABORTED</source>
        <translation>中止</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="25"/>
        <source>NOT RECORDED</source>
        <translation>未記録</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="66"/>
        <source>Unit %1</source>
        <translation>製品 %1</translation>
    </message>
    <message>
        <location filename="../ui/eol/VerdictLook.cpp" line="69"/>
        <source>%1
Not a verdict on the unit: fix the cause and test it again.</source>
        <translation>%1
製品の判定ではありません。原因を取り除いてから再試験してください。</translation>
    </message>
</context>
<context>
    <name>opentop::YieldReport</name>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="100"/>
        <source>%1 rev. %2</source>
        <translation>%1 rev. %2</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="105"/>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="111"/>
        <source>first-pass yield – (no serial tested yet)</source>
        <translation>直行率 –（まだ試験したシリアルなし）</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="112"/>
        <source>first-pass yield %1 (%2 of %3 serials) · second-pass %4 · last-pass %5</source>
        <translation>直行率 %1（%3 シリアル中 %2）· 2 回目までの合格率 %4 · 最終合格率 %5</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="125"/>
        <source>still running (or its station has not restarted since it stopped)</source>
        <translation>まだ実行中（または停止後にステーションが再起動していません）</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="127"/>
        <source>interrupted</source>
        <translation>中断</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="129"/>
        <source>aborted</source>
        <translation>中止</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="131"/>
        <source>station error, no reason recorded</source>
        <translation>ステーションエラー、理由の記録なし</translation>
    </message>
    <message>
        <location filename="../model/eol/YieldReport.cpp" line="133"/>
        <source>failed, no reason recorded</source>
        <translation>不合格、理由の記録なし</translation>
    </message>
</context>
</TS>
