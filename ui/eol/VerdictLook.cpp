#include "ui/eol/VerdictLook.h"

namespace opentop {

namespace {

struct Look
{
    VerdictLook::State state;
    const char* text;
    const char* colour;
};

// Green is only ever a pass; red a fail or a result not recorded.
constexpr Look kLooks[] = {
    {VerdictLook::State::Ready, QT_TRANSLATE_NOOP("opentop::VerdictLook", "READY"), "#5f6b76"},
    {VerdictLook::State::Testing, QT_TRANSLATE_NOOP("opentop::VerdictLook", "TESTING"), "#1f5fa8"},
    {VerdictLook::State::NotStarted, QT_TRANSLATE_NOOP("opentop::VerdictLook", "NOT STARTED"),
     "#8a6d00"},
    {VerdictLook::State::Pass, QT_TRANSLATE_NOOP("opentop::VerdictLook", "PASS"), "#1e7b34"},
    {VerdictLook::State::Fail, QT_TRANSLATE_NOOP("opentop::VerdictLook", "FAIL"), "#b3261e"},
    {VerdictLook::State::StationError, QT_TRANSLATE_NOOP("opentop::VerdictLook", "STATION ERROR"),
     "#8a6d00"},
    {VerdictLook::State::Aborted, QT_TRANSLATE_NOOP("opentop::VerdictLook", "ABORTED"), "#b35c00"},
    {VerdictLook::State::NotRecorded, QT_TRANSLATE_NOOP("opentop::VerdictLook", "NOT RECORDED"),
     "#b3261e"},
};

const Look& lookOf(VerdictLook::State state)
{
    for (const Look& l : kLooks)
        if (l.state == state)
            return l;
    return kLooks[0];
}

} // namespace

QString VerdictLook::text(State state)
{
    return tr(lookOf(state).text);
}

QString VerdictLook::colour(State state)
{
    return QString::fromLatin1(lookOf(state).colour);
}

VerdictLook::State VerdictLook::of(UnitStatus status)
{
    switch (status) {
    case UnitStatus::Pass:
        return State::Pass;
    case UnitStatus::Fail:
        return State::Fail;
    case UnitStatus::Error:
        return State::StationError;
    default:
        return State::Aborted;
    }
}

QString VerdictLook::reason(const UnitRecord& record, const QString& reason)
{
    if (record.status == UnitStatus::Pass && reason.isEmpty())
        return tr("Unit %1").arg(record.serial);
    if (record.status == UnitStatus::Error)
        // The station could not test it: no verdict on the unit, and not counted as one.
        return tr("%1\nNot a verdict on the unit: fix the cause and test it again.").arg(reason);
    return reason;
}

QFont VerdictLook::scaled(QFont font, double factor, bool bold)
{
    font.setPointSizeF(font.pointSizeF() * factor);
    font.setBold(bold);
    return font;
}

} // namespace opentop
