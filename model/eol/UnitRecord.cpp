#include "model/eol/UnitRecord.h"

namespace opentop {

namespace {

struct StatusName
{
    UnitStatus status;
    const char* name;
};

constexpr StatusName kStatusNames[] = {
    {UnitStatus::Running, "running"}, {UnitStatus::Interrupted, "interrupted"},
    {UnitStatus::Pass, "pass"},       {UnitStatus::Fail, "fail"},
    {UnitStatus::Aborted, "aborted"}, {UnitStatus::Error, "error"},
};

struct SourceName
{
    VariantSource source;
    const char* name;
};

constexpr SourceName kSourceNames[] = {
    {VariantSource::None, ""},           {VariantSource::Read, "read"},
    {VariantSource::Probed, "probed"},   {VariantSource::Confirmed, "confirmed"},
    {VariantSource::Assumed, "assumed"},
};

} // namespace

QString variantSourceName(VariantSource source)
{
    for (const auto& s : kSourceNames)
        if (s.source == source)
            return QLatin1String(s.name);
    return QString();
}

std::optional<VariantSource> variantSourceFromName(const QString& name)
{
    for (const auto& s : kSourceNames)
        if (name == QLatin1String(s.name))
            return s.source;
    return std::nullopt;
}

QString unitStatusName(UnitStatus status)
{
    for (const auto& s : kStatusNames)
        if (s.status == status)
            return QLatin1String(s.name);
    return QString();
}

std::optional<UnitStatus> unitStatusFromName(const QString& name)
{
    for (const auto& s : kStatusNames)
        if (name == QLatin1String(s.name))
            return s.status;
    return std::nullopt;
}

bool UnitDrive::operator==(const UnitDrive& o) const
{
    return machineNumber == o.machineNumber && model == o.model && variant == o.variant &&
           firmware == o.firmware && variantSource == o.variantSource &&
           variantProof == o.variantProof;
}

bool WrittenValue::operator==(const WrittenValue& o) const
{
    return machineNumber == o.machineNumber && parameter == o.parameter && label == o.label &&
           value == o.value && written == o.written && verified == o.verified &&
           readBack == o.readBack;
}

bool Measurement::operator==(const Measurement& o) const
{
    return machineNumber == o.machineNumber && step == o.step && quantity == o.quantity &&
           value == o.value && unit == o.unit && lower == o.lower && upper == o.upper &&
           pass == o.pass;
}

bool UnitRecord::operator==(const UnitRecord& o) const
{
    return id == o.id && serial == o.serial && station == o.station &&
           operatorName == o.operatorName && started == o.started && ended == o.ended &&
           recipeName == o.recipeName && recipeRevision == o.recipeRevision &&
           recipeChecksum == o.recipeChecksum && approvalId == o.approvalId &&
           approver == o.approver && status == o.status && attempt == o.attempt &&
           failureReason == o.failureReason && drives == o.drives &&
           writtenValues == o.writtenValues && measurements == o.measurements &&
           traffic == o.traffic;
}

} // namespace opentop
