#include "eol/CertificateHtml.h"

namespace opentop {

namespace {

QString esc(const QString& text)
{
    return text.toHtmlEscaped();
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

QString CertificateHtml::html(const UnitRecord& r)
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
    const QString table =
        QStringLiteral("<table border=\"1\" cellspacing=\"0\" cellpadding=\"3\" width=\"100%\">");
    h += QStringLiteral("<h3>%1</h3>").arg(esc(tr("Drives")));
    h += table + row({tr("Machine number"), tr("Model"), tr("Variant"), tr("Firmware")}, true);
    for (const UnitDrive& d : r.drives)
        h += row({QString::number(d.machineNumber), d.model, d.variant, d.firmware});
    h += QStringLiteral("</table>");
    h += QStringLiteral("<h3>%1</h3>").arg(esc(tr("Settings")));
    h += table + row({tr("Drive"), tr("Setting"), tr("Value"), tr("Written"), tr("Read back"),
                      tr("Verified")},
                     true);
    for (const WrittenValue& w : r.writtenValues)
        h += row({QString::number(w.machineNumber), w.label, w.value,
                  w.written ? tr("written") : tr("already set"), w.readBack,
                  w.verified ? tr("yes") : tr("NO")});
    h += QStringLiteral("</table>");
    h += QStringLiteral("<h3>%1</h3>").arg(esc(tr("Measurements")));
    h += table +
         row({tr("Drive"), tr("Step"), tr("Quantity"), tr("Value"), tr("Limits"), tr("Verdict")},
             true);
    for (const Measurement& m : r.measurements)
        h += row({QString::number(m.machineNumber), m.step, m.quantity,
                  withUnit(num(m.value), m.unit), limitsText(m), m.pass ? tr("pass") : tr("FAIL")});
    h += QStringLiteral("</table>");
    if (!r.traffic.isEmpty()) {
        h += QStringLiteral("<h3>%1</h3><pre style=\"font-size: 7pt\">")
                 .arg(esc(tr("Bus traffic around the failure")));
        h += esc(r.traffic.join(QLatin1Char('\n')));
        h += QStringLiteral("</pre>");
    }
    h += QStringLiteral("</body></html>");
    return h;
}

} // namespace opentop
