#include "model/bus/DriveName.h"

#include "model/io/DisplayText.h"
#include "model/session/DeviceSession.h"

#include <QRegularExpression>

namespace opentop {

QString DriveName::cleaned(const QString& name)
{
    return name.trimmed();
}

QString DriveName::problem(const QString& name)
{
    const QString kept = cleaned(name);
    if (kept.size() > kMaxLength)
        return tr("A machine's name has at most %1 characters; \"%2\" has %3.")
            .arg(kMaxLength)
            .arg(DisplayText::escaped(kept.left(kMaxLength)) + QChar(0x2026))
            .arg(kept.size());
    for (const QChar c : kept) {
        // Control characters and line or paragraph breaks would break a question, a list, a
        // file's line or a CSV row.
        const QChar::Category category = c.category();
        if (category == QChar::Other_Control || category == QChar::Other_Format ||
            category == QChar::Separator_Line || category == QChar::Separator_Paragraph ||
            category == QChar::Other_Surrogate || category == QChar::Other_NotAssigned)
            return tr("A machine's name may not hold control characters or line breaks "
                      "(U+%1).")
                .arg(c.unicode(), 4, 16, QLatin1Char('0'));
    }
    // Messages put the name into translated sentences with arg(): "%2" in a name would be
    // taken for the sentence's own place-holder and replaced.
    static const QRegularExpression placeHolder(QStringLiteral("%\\d"));
    if (const QRegularExpressionMatch m = placeHolder.match(kept); m.hasMatch())
        return tr("A machine's name may not hold %1 (a percent sign directly before a digit).")
            .arg(m.captured());
    return QString();
}

// Names and models are shown escaped (DisplayText): a name kept before names were checked, or a
// backup file's name or model, may hold control characters.
QString DriveName::text(int slave, const QString& name)
{
    return name.isEmpty() ? tr("machine number %1").arg(slave)
                          : tr("machine number %1 (%2)").arg(slave).arg(DisplayText::escaped(name));
}

QString DriveName::title(int slave, const QString& name)
{
    return name.isEmpty() ? tr("Machine number %1").arg(slave)
                          : tr("Machine number %1 (%2)").arg(slave).arg(DisplayText::escaped(name));
}

QString DriveName::listed(int slave, const QString& name)
{
    return name.isEmpty() ? QString::number(slave)
                          : QStringLiteral("%1 (%2)").arg(slave).arg(DisplayText::escaped(name));
}

QString DriveName::nameAndModel(const QString& name, const QString& model)
{
    if (name.isEmpty() || model.isEmpty())
        return DisplayText::escaped(name.isEmpty() ? model : name);
    return QStringLiteral("%1, %2").arg(DisplayText::escaped(name), DisplayText::escaped(model));
}

QString DriveName::withModel(int slave, const QString& name, const QString& model)
{
    return tr("drive %1 (%2)").arg(slave).arg(nameAndModel(name, model));
}

QString DriveName::text(const DeviceSession* session)
{
    return session ? text(session->slave(), session->machineName()) : QString();
}

QString DriveName::title(const DeviceSession* session)
{
    return session ? title(session->slave(), session->machineName()) : QString();
}

QString DriveName::listed(const DeviceSession* session)
{
    return session ? listed(session->slave(), session->machineName()) : QString();
}

} // namespace opentop
