#include "model/eol/CertificateHtml.h"

#include "model/io/DisplayText.h"

namespace opentop {

namespace {

// Every text on the certificate, the record's from stations, operators and recipes: control
// characters and bidi overrides shown as escapes (DisplayText), then made safe for HTML.
QString esc(const QString& text)
{
    return DisplayText::escaped(text).toHtmlEscaped();
}

// Seven significant digits for reading; the JSON certificate keeps every digit.
QString num(double value)
{
    return QString::number(value, 'g', 7);
}

QString withUnit(const QString& number, const QString& unit)
{
    return unit.isEmpty() ? number : number + QChar(0x00a0) + unit;
}

QString row(const QStringList& cells, bool header = false)
{
    const QString tag = header ? QStringLiteral("th") : QStringLiteral("td");
    QString html = QStringLiteral("<tr>");
    for (const QString& c : cells)
        html += QStringLiteral("<%1>%2</%1>").arg(tag, esc(c));
    return html + QStringLiteral("</tr>");
}

QString timeText(const QDateTime& time)
{
    return time.isValid() ? time.toUTC().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss 'UTC'"))
                          : QStringLiteral("—");
}

} // namespace

QString CertificateHtml::verdictText(UnitStatus status)
{
    switch (status) {
    case UnitStatus::Pass:
        return tr("PASS");
    case UnitStatus::Fail:
        return tr("FAIL");
    case UnitStatus::Aborted:
        return tr("ABORTED");
    case UnitStatus::Error:
        return tr("STATION ERROR");
    case UnitStatus::Interrupted:
        return tr("INTERRUPTED");
    case UnitStatus::Running:
        return tr("NOT FINISHED");
    }
    return QString();
}

QString CertificateHtml::limitsText(const Measurement& m)
{
    if (m.lower && m.upper)
        return withUnit(num(*m.lower) + QStringLiteral(" … ") + num(*m.upper), m.unit);
    if (m.lower)
        return withUnit(QStringLiteral("≥ ") + num(*m.lower), m.unit);
    if (m.upper)
        return withUnit(QStringLiteral("≤ ") + num(*m.upper), m.unit);
    return tr("none");
}

QString CertificateHtml::html(const UnitRecord& r, const QVector<UnitRecord>& earlier)
{
    const QString colour = r.isPass() ? QStringLiteral("#1b7e2b") : QStringLiteral("#b3261e");
    QString h = QStringLiteral("<html><body style=\"font-family: 'DejaVu Sans'; font-size: 9pt\">");
    h += QStringLiteral("<h2>%1</h2>").arg(esc(tr("End-of-line test certificate")));
    h += QStringLiteral("<table cellspacing=\"0\" cellpadding=\"2\">");
    const QList<QPair<QString, QString>> head{
        {tr("Serial number"), r.serial},
        {tr("Recipe"), tr("%1, revision %2").arg(r.recipeName, r.recipeRevision)},
        {tr("Recipe checksum"), r.recipeChecksum},
        {tr("Recipe approved by"), r.approver.isEmpty()
                                       ? tr("not approved (station without users)")
                                       : tr("%1 (approval %2)").arg(r.approver, r.approvalId)},
        {tr("Station"), r.station},
        {tr("Operator"), r.operatorName},
        {tr("Attempt"), r.attempt > 0
                            ? tr("%1 (tests of this serial under this recipe)").arg(r.attempt)
                            : tr("not counted (recorded before attempts were)")},
        {tr("Started"), timeText(r.started)},
        {tr("Ended"), timeText(r.ended)},
        {tr("Record"), r.id},
    };
    for (const auto& [label, value] : head)
        h += QStringLiteral("<tr><td><b>%1</b></td><td>%2</td></tr>").arg(esc(label), esc(value));
    h += QStringLiteral("</table>");
    h += QStringLiteral("<p style=\"font-size: 28pt; font-weight: bold; color: %1\">%2</p>")
             .arg(colour, esc(verdictText(r.status)));
    if (!r.failureReason.isEmpty())
        h += QStringLiteral("<p><b>%1</b> %2</p>")
                 .arg(esc(tr("First failure:")), esc(r.failureReason));
    // A heading is the first row of its table's repeated header: never alone at the foot of
    // a page, and every continued page says what its rows are.
    const auto section = [&h](const QString& title, const QStringList& headers) {
        h += QStringLiteral("<table border=\"1\" cellspacing=\"0\" cellpadding=\"3\" "
                            "width=\"100%\"><thead><tr><td colspan=\"%1\" style=\"border: "
                            "none; font-size: 11pt; font-weight: bold; padding-top: 8px\">%2"
                            "</td></tr>")
                 .arg(headers.size())
                 .arg(esc(title));
        h += row(headers, true) + QStringLiteral("</thead>");
    };
    if (!earlier.isEmpty()) {
        int fails = 0;
        for (const UnitRecord& e : earlier)
            fails += e.status == UnitStatus::Fail ? 1 : 0;
        if (fails > 0)
            h += QStringLiteral("<p><b>%1</b></p>")
                     .arg(esc(tr("This serial failed %n earlier test(s); they are listed below.",
                                 nullptr, fails)));
    }
    section(tr("Drives"),
            {tr("Machine number"), tr("Model"), tr("Variant"), tr("How known"), tr("Firmware")});
    for (const UnitDrive& d : r.drives)
        h += row({QString::number(d.machineNumber), d.model, variantText(d),
                  d.variantProof.isEmpty()
                      ? variantSourceText(d.variantSource)
                      : tr("%1: %2").arg(variantSourceText(d.variantSource), d.variantProof),
                  d.firmware});
    h += QStringLiteral("</table>");
    section(tr("Settings"), {tr("Drive"), tr("Setting"), tr("Value"), tr("Written"),
                             tr("Read back"), tr("Verified")});
    for (const WrittenValue& w : r.writtenValues)
        h += row({QString::number(w.machineNumber), w.label, w.value,
                  w.written ? tr("written") : tr("already set"), w.readBack,
                  w.verified ? tr("yes") : tr("NO")});
    h += QStringLiteral("</table>");
    section(tr("Measurements"),
            {tr("Drive"), tr("Step"), tr("Quantity"), tr("Value"), tr("Limits"), tr("Verdict")});
    for (const Measurement& m : r.measurements)
        h += row({QString::number(m.machineNumber), m.step, m.quantity,
                  withUnit(num(m.value), m.unit), limitsText(m), m.pass ? tr("pass") : tr("FAIL")});
    h += QStringLiteral("</table>");
    if (!earlier.isEmpty()) {
        section(tr("Earlier tests of this serial"),
                {tr("Started"), tr("Recipe"), tr("Attempt"), tr("Verdict"), tr("Reason")});
        for (const UnitRecord& e : earlier)
            h += row({timeText(e.started), tr("%1 rev. %2").arg(e.recipeName, e.recipeRevision),
                      e.attempt > 0 ? QString::number(e.attempt) : tr("–"), verdictText(e.status),
                      e.failureReason});
        h += QStringLiteral("</table>");
    }
    if (!r.traffic.isEmpty()) {
        // A line a row (pre-wrap): a long line wraps at the page margin instead of running past
        // it, and the heading stays with the first line.
        h += QStringLiteral("<table cellspacing=\"0\" cellpadding=\"1\" width=\"100%\"><thead>"
                            "<tr><td style=\"font-size: 11pt; font-weight: bold; padding-top: "
                            "8px\">%1</td></tr></thead>")
                 .arg(esc(tr("Bus traffic around the failure")));
        for (const QString& line : r.traffic)
            h += QStringLiteral("<tr><td style=\"font-family: 'DejaVu Sans Mono'; font-size: 7pt; "
                                "white-space: pre-wrap\">%1</td></tr>")
                     .arg(esc(line));
        h += QStringLiteral("</table>");
    }
    h += QStringLiteral("</body></html>");
    return h;
}

QString CertificateHtml::variantSourceText(VariantSource source)
{
    switch (source) {
    case VariantSource::Read:
        return tr("read from the drive");
    case VariantSource::Probed:
        return tr("proven by the variant probe");
    case VariantSource::Confirmed:
        return tr("confirmed by a person");
    case VariantSource::Assumed:
        return tr("ASSUMED, not proven");
    case VariantSource::None:
        break;
    }
    return tr("not known");
}

QString CertificateHtml::variantText(const UnitDrive& drive)
{
    if (drive.variant.isEmpty())
        return tr("not known");
    // An assumed variant is never shown as if it were known.
    return drive.variantSource == VariantSource::Assumed ? tr("%1 (assumed)").arg(drive.variant)
                                                         : drive.variant;
}

} // namespace opentop
