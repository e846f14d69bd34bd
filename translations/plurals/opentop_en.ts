<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en" sourcelanguage="en">
<context>
    <name>opentop::AlarmBanner</name>
    <message numerus="yes">
        <location filename="../../ui/alarms/AlarmBanner.cpp" line="98"/>
        <source>(%n more drive(s) with an alarm)</source>
        <translation>
            <numerusform>(%n more drive with an alarm)</numerusform>
            <numerusform>(%n more drives with an alarm)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::AlarmExport</name>
    <message numerus="yes">
        <location filename="../../ui/alarms/AlarmExport.cpp" line="132"/>
        <source>%n record(s) of %1 drive(s) written to %2.</source>
        <translation>
            <numerusform>%n record of %1 drive(s) written to %2.</numerusform>
            <numerusform>%n records of %1 drive(s) written to %2.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::BackupDialog</name>
    <message numerus="yes">
        <location filename="../../ui/files/BackupDialog.cpp" line="112"/>
        <source>Reading the settings of %n drive(s)…</source>
        <translation>
            <numerusform>Reading the settings of %n drive…</numerusform>
            <numerusform>Reading the settings of %n drives…</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/files/BackupDialog.cpp" line="153"/>
        <source>%n setting(s) read in %1 ms</source>
        <translation>
            <numerusform>%n setting read in %1 ms</numerusform>
            <numerusform>%n settings read in %1 ms</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/files/BackupDialog.cpp" line="190"/>
        <source>Save the %n drive(s) that were read?</source>
        <translation>
            <numerusform>Save the %n drive that was read?</numerusform>
            <numerusform>Save the %n drives that were read?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/files/BackupDialog.cpp" line="214"/>
        <source>Saved %n drive(s) to %1.</source>
        <translation>
            <numerusform>Saved %n drive to %1.</numerusform>
            <numerusform>Saved %n drives to %1.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::BackupViewer</name>
    <message numerus="yes">
        <location filename="../../ui/files/BackupViewer.cpp" line="133"/>
        <source>%n setting(s)</source>
        <translation>
            <numerusform>%n setting</numerusform>
            <numerusform>%n settings</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::BusDriveList</name>
    <message numerus="yes">
        <location filename="../../cli/BusDriveList.cpp" line="16"/>
        <source>%n day(s) ago</source>
        <translation>
            <numerusform>%n day ago</numerusform>
            <numerusform>%n days ago</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::BusLeaving</name>
    <message numerus="yes">
        <location filename="../../ui/main/BusLeaving.cpp" line="78"/>
        <source>%n edit(s) have not been written to the drives. Quit and discard them?</source>
        <translation>
            <numerusform>%n edit has not been written to the drives. Quit and discard it?</numerusform>
            <numerusform>%n edits have not been written to the drives. Quit and discard them?</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::BusPanel</name>
    <message numerus="yes">
        <location filename="../../ui/bus/BusPanel.cpp" line="272"/>
        <source>Scan cancelled after machine numbers %1–%2 (%3 of %4): %n drive(s) found.</source>
        <translation>
            <numerusform>Scan cancelled after machine numbers %1–%2 (%3 of %4): %n drive found.</numerusform>
            <numerusform>Scan cancelled after machine numbers %1–%2 (%3 of %4): %n drives found.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/bus/BusPanel.cpp" line="280"/>
        <source>%n drive(s) found on machine numbers %1–%2 in %3 s.</source>
        <translation>
            <numerusform>%n drive found on machine numbers %1–%2 in %3 s.</numerusform>
            <numerusform>%n drives found on machine numbers %1–%2 in %3 s.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::CertificateHtml</name>
    <message numerus="yes">
        <location filename="../../model/eol/CertificateHtml.cpp" line="121"/>
        <source>This serial failed %n earlier test(s); they are listed below.</source>
        <translation>
            <numerusform>This serial failed %n earlier test; they are listed below.</numerusform>
            <numerusform>This serial failed %n earlier tests; they are listed below.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::CompareDialog</name>
    <message numerus="yes">
        <location filename="../../ui/files/CompareDialog.cpp" line="258"/>
        <source>%n difference(s)</source>
        <translation>
            <numerusform>%n difference</numerusform>
            <numerusform>%n differences</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::DeviceParameters</name>
    <message numerus="yes">
        <location filename="../../model/session/DeviceParameters.cpp" line="286"/>
        <source>%n write(s) failed: %1</source>
        <translation>
            <numerusform>%n write failed: %1</numerusform>
            <numerusform>%n writes failed: %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../model/session/DeviceParameters.cpp" line="292"/>
        <source>%n value(s) written and verified</source>
        <translation>
            <numerusform>%n value written and verified</numerusform>
            <numerusform>%n values written and verified</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::DriveStatus</name>
    <message numerus="yes">
        <location filename="../../model/bus/DriveStatus.cpp" line="12"/>
        <source>no answer (%n poll(s) in a row)</source>
        <translation>
            <numerusform>no answer (%n poll in a row)</numerusform>
            <numerusform>no answer (%n polls in a row)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../model/bus/DriveStatus.cpp" line="13"/>
        <source>communication error (%n in a row)</source>
        <translation>
            <numerusform>communication error (%n in a row)</numerusform>
            <numerusform>communication errors (%n in a row)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::DriveWorkspace</name>
    <message numerus="yes">
        <location filename="../../ui/workspace/DriveWorkspace.cpp" line="152"/>
        <source>Every edit is accepted now. Nothing has been written yet: Write all pending sends %n value(s).</source>
        <translation>
            <numerusform>Every edit is accepted now. Nothing has been written yet: Write all pending sends %n value.</numerusform>
            <numerusform>Every edit is accepted now. Nothing has been written yet: Write all pending sends %n values.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/workspace/DriveWorkspace.cpp" line="192"/>
        <source>%n value(s) could not be read</source>
        <translation>
            <numerusform>%n value could not be read</numerusform>
            <numerusform>%n values could not be read</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/workspace/DriveWorkspace.cpp" line="233"/>
        <source>Write %n pending value(s) to machine number %1</source>
        <translation>
            <numerusform>Write %n pending value to machine number %1</numerusform>
            <numerusform>Write %n pending values to machine number %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/workspace/DriveWorkspace.cpp" line="238"/>
        <source>Writing %n value(s)…</source>
        <translation>
            <numerusform>Writing %n value…</numerusform>
            <numerusform>Writing %n values…</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::EolRecipeCheckCommand</name>
    <message numerus="yes">
        <location filename="../../cli/EolRecipeCheckCommand.cpp" line="93"/>
        <source>%1 is not valid: %n problem(s); nothing may be run with it</source>
        <translation>
            <numerusform>%1 is not valid: %n problem; nothing may be run with it</numerusform>
            <numerusform>%1 is not valid: %n problems; nothing may be run with it</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../cli/EolRecipeCheckCommand.cpp" line="107"/>
        <source>; %n unit(s) of %1 checked</source>
        <translation>
            <numerusform>; %n unit of %1 checked</numerusform>
            <numerusform>; %n units of %1 checked</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::EolRecipeSignCommand</name>
    <message numerus="yes">
        <location filename="../../cli/EolRecipeSignCommand.cpp" line="49"/>
        <source>error: %1 does not pass check (%n problem(s)); not signed</source>
        <translation>
            <numerusform>error: %1 does not pass check (%n problem); not signed</numerusform>
            <numerusform>error: %1 does not pass check (%n problems); not signed</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::EolSupport</name>
    <message numerus="yes">
        <location filename="../../cli/EolSupport.cpp" line="140"/>
        <source>%n position(s)</source>
        <translation>
            <numerusform>%n position</numerusform>
            <numerusform>%n positions</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../cli/EolSupport.cpp" line="141"/>
        <source>%n setting(s)</source>
        <translation>
            <numerusform>%n setting</numerusform>
            <numerusform>%n settings</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../cli/EolSupport.cpp" line="143"/>
        <source>%n per-unit value(s)</source>
        <translation>
            <numerusform>%n per-unit value</numerusform>
            <numerusform>%n per-unit values</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../cli/EolSupport.cpp" line="144"/>
        <source>%n step(s)</source>
        <translation>
            <numerusform>%n step</numerusform>
            <numerusform>%n steps</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::GetCommand</name>
    <message numerus="yes">
        <location filename="../../cli/GetCommand.cpp" line="168"/>
        <source>error: %n parameter(s) could not be read</source>
        <translation>
            <numerusform>error: %n parameter could not be read</numerusform>
            <numerusform>error: %n parameters could not be read</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::GroupsView</name>
    <message numerus="yes">
        <location filename="../../ui/groups/GroupsView.cpp" line="248"/>
        <source>%n drive(s) did not answer</source>
        <translation>
            <numerusform>%n drive did not answer</numerusform>
            <numerusform>%n drives did not answer</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/groups/GroupsView.cpp" line="280"/>
        <source>Write the planned communication group to %n drive(s)?</source>
        <translation>
            <numerusform>Write the planned communication group to %n drive?</numerusform>
            <numerusform>Write the planned communication group to %n drives?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/groups/GroupsView.cpp" line="366"/>
        <source>Not as planned: %1 (read back; %n drive(s) did not answer).</source>
        <translation>
            <numerusform>Not as planned: %1 (read back; %n drive did not answer).</numerusform>
            <numerusform>Not as planned: %1 (read back; %n drives did not answer).</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::LinkLoss</name>
    <message numerus="yes">
        <location filename="../../model/run/LinkLoss.cpp" line="102"/>
        <source>%n drive(s) never read.</source>
        <translation>
            <numerusform>%n drive never read.</numerusform>
            <numerusform>%n drives never read.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::MultiDriveWriteDialog</name>
    <message numerus="yes">
        <location filename="../../ui/workspace/MultiDriveWriteDialog.cpp" line="323"/>
        <source>Set it on %n drive(s) anyway?</source>
        <translation>
            <numerusform>Set it on %n drive anyway?</numerusform>
            <numerusform>Set it on %n drives anyway?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/workspace/MultiDriveWriteDialog.cpp" line="353"/>
        <source>Writing %1 to %n drive(s)…</source>
        <translation>
            <numerusform>Writing %1 to %n drive…</numerusform>
            <numerusform>Writing %1 to %n drives…</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/workspace/MultiDriveWriteDialog.cpp" line="365"/>
        <source>Written and verified on %1 of %n drive(s).</source>
        <translation>
            <numerusform>Written and verified on %1 of %n drive.</numerusform>
            <numerusform>Written and verified on %1 of %n drives.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::ParameterInitBox</name>
    <message numerus="yes">
        <location filename="../../ui/workspace/ParameterInitBox.cpp" line="117"/>
        <source>Your %n unwritten edit(s) of this drive are discarded.</source>
        <translation>
            <numerusform>Your %n unwritten edit of this drive is discarded.</numerusform>
            <numerusform>Your %n unwritten edits of this drive are discarded.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/workspace/ParameterInitBox.cpp" line="184"/>
        <source>Drive %1 initialised; %n value(s) could not be read back (it may answer only at the default communication settings now).</source>
        <translation>
            <numerusform>Drive %1 initialised; %n value could not be read back (it may answer only at the default communication settings now).</numerusform>
            <numerusform>Drive %1 initialised; %n values could not be read back (it may answer only at the default communication settings now).</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::ParameterPage</name>
    <message numerus="yes">
        <location filename="../../ui/workspace/ParameterPage.cpp" line="167"/>
        <source>%n value(s) could not be read</source>
        <translation>
            <numerusform>%n value could not be read</numerusform>
            <numerusform>%n values could not be read</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/workspace/ParameterPage.cpp" line="116"/>
        <source>Nothing was written: %n field(s) not accepted. %1</source>
        <translation>
            <numerusform>Nothing was written: %n field not accepted. %1</numerusform>
            <numerusform>Nothing was written: %n fields not accepted. %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/workspace/ParameterPage.cpp" line="137"/>
        <source>Every field is accepted now. Nothing has been written yet: Write page sends %n value(s).</source>
        <translation>
            <numerusform>Every field is accepted now. Nothing has been written yet: Write page sends %n value.</numerusform>
            <numerusform>Every field is accepted now. Nothing has been written yet: Write page sends %n values.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/workspace/ParameterPage.cpp" line="208"/>
        <source>Write %n value(s) of the page %1 to machine number %2</source>
        <translation>
            <numerusform>Write %n value of the page %1 to machine number %2</numerusform>
            <numerusform>Write %n values of the page %1 to machine number %2</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/workspace/ParameterPage.cpp" line="217"/>
        <source>Writing %n value(s)…</source>
        <translation>
            <numerusform>Writing %n value…</numerusform>
            <numerusform>Writing %n values…</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::ProductionView</name>
    <message numerus="yes">
        <location filename="../../ui/eol/ProductionView.cpp" line="242"/>
        <source>&lt;b&gt;%1&lt;/b&gt; rev. %2 — %n drive(s)</source>
        <translation>
            <numerusform>&lt;b&gt;%1&lt;/b&gt; rev. %2 — %n drive</numerusform>
            <numerusform>&lt;b&gt;%1&lt;/b&gt; rev. %2 — %n drives</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::RecipeEditor</name>
    <message numerus="yes">
        <location filename="../../ui/eol/RecipeEditor.cpp" line="256"/>
        <source>%n problem(s): the recipe cannot be saved until they are fixed.</source>
        <translation>
            <numerusform>%n problem: the recipe cannot be saved until it is fixed.</numerusform>
            <numerusform>%n problems: the recipe cannot be saved until they are fixed.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/eol/RecipeEditor.cpp" line="268"/>
        <source>the recipe does not pass check (%n problem(s)); nothing was saved</source>
        <translation>
            <numerusform>the recipe does not pass check (%n problem); nothing was saved</numerusform>
            <numerusform>the recipe does not pass check (%n problems); nothing was saved</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::RestoreDialog</name>
    <message numerus="yes">
        <location filename="../../ui/files/RestoreDialog.cpp" line="124"/>
        <source>%n drive(s) in the file. Choose what to restore, then Preview.</source>
        <translation>
            <numerusform>%n drive in the file. Choose what to restore, then Preview.</numerusform>
            <numerusform>%n drives in the file. Choose what to restore, then Preview.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/files/RestoreDialog.cpp" line="247"/>
        <source>%n setting(s) to write</source>
        <translation>
            <numerusform>%n setting to write</numerusform>
            <numerusform>%n settings to write</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/files/RestoreDialog.cpp" line="333"/>
        <source>Write %n setting(s) to drive(s) %1, each verified by reading it back?</source>
        <translation>
            <numerusform>Write %n setting to drive(s) %1, each verified by reading it back?</numerusform>
            <numerusform>Write %n settings to drive(s) %1, each verified by reading it back?</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::RestorePlan</name>
    <message numerus="yes">
        <location filename="../../model/files/RestorePlan.cpp" line="163"/>
        <source>%n value(s) of the file may not be written to this drive; nothing written</source>
        <translation>
            <numerusform>%n value of the file may not be written to this drive; nothing written</numerusform>
            <numerusform>%n values of the file may not be written to this drive; nothing written</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::Restorer</name>
    <message numerus="yes">
        <location filename="../../model/files/Restorer.cpp" line="119"/>
        <source>%n value(s) of the file may not be written to the drives of the communication group; nothing written</source>
        <translation>
            <numerusform>%n value of the file may not be written to the drives of the communication group; nothing written</numerusform>
            <numerusform>%n values of the file may not be written to the drives of the communication group; nothing written</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::ResultsBrowser</name>
    <message numerus="yes">
        <location filename="../../ui/eol/ResultsBrowser.cpp" line="239"/>
        <source>%n unit(s): %1 passed, %2 failed, %3 station errors · %4</source>
        <translation>
            <numerusform>%n unit: %1 passed, %2 failed, %3 station errors · %4</numerusform>
            <numerusform>%n units: %1 passed, %2 failed, %3 station errors · %4</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/eol/ResultsBrowser.cpp" line="321"/>
        <source>%n unit(s) written to %1</source>
        <translation>
            <numerusform>%n unit written to %1</numerusform>
            <numerusform>%n units written to %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::RunningDataPage</name>
    <message numerus="yes">
        <location filename="../../ui/pages/RunningDataPage.cpp" line="359"/>
        <source>SPno%1 initialized; %n value(s) could not be read back</source>
        <translation>
            <numerusform>SPno%1 initialized; %n value could not be read back</numerusform>
            <numerusform>SPno%1 initialized; %n values could not be read back</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>opentop::StationNotice</name>
    <message numerus="yes">
        <location filename="../../ui/eol/StationNotice.cpp" line="31"/>
        <source>%n result(s) kept on this station, not yet in the results database: %1. They are sent by themselves, in order, when it answers.</source>
        <translation>
            <numerusform>%n result kept on this station, not yet in the results database: %1. They are sent by themselves, in order, when it answers.</numerusform>
            <numerusform>%n results kept on this station, not yet in the results database: %1. They are sent by themselves, in order, when it answers.</numerusform>
        </translation>
    </message>
</context>
</TS>
