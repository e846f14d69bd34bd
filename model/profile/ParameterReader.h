#pragma once

#include "model/profile/JsonReader.h"
#include "model/profile/ParameterMeta.h"
#include "model/profile/Profile.h"

#include <QJsonObject>

namespace opentop {

// Reads and checks one parameter entry of a profile. Checks that need the whole parameter list
// (references, overlapping addresses) are the loader's.
class ParameterReader
{
public:
    ParameterReader(const Profile& profile, JsonReader& json)
        : m_profile(profile)
        , m_json(json)
    {
    }

    bool read(const QJsonObject& o, ParameterMeta* meta);

private:
    bool readSpec(const QJsonObject& o, const ParameterMeta& meta, ValueSpec* spec);
    // `key` ("allowed", "recommended") names the list in messages.
    bool readRanges(const QJsonArray& a, const QString& key, const ParameterMeta& meta,
                    double scale, QVector<ValueRange>* ranges);
    bool readOptions(const QJsonArray& a, const ParameterMeta& meta, ValueSpec* spec);
    bool readWriteBlock(const QJsonObject& o, ParameterMeta* meta);
    bool readBits(const QJsonArray& a, ParameterMeta* meta);
    bool readConditions(const QJsonArray& a, ParameterMeta* meta);

    const Profile& m_profile;
    JsonReader& m_json;
};

} // namespace opentop
