// LocalTimeZone: TZ is set so that glibc reads the zone once, and the zone stays the system's.
#include "model/monitor/LocalTimeZone.h"

#include <QDateTime>
#include <QTimeZone>
#include <ctime>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

// Restores TZ as it was, whatever a test did to it.
class LocalTimeZoneTest : public ::testing::Test
{
protected:
    void SetUp() override
    {
        m_had = qEnvironmentVariableIsSet("TZ");
        m_old = qgetenv("TZ");
        qunsetenv("TZ");
        tzset();
    }
    void TearDown() override
    {
        if (m_had)
            qputenv("TZ", m_old);
        else
            qunsetenv("TZ");
        tzset();
    }

private:
    bool m_had = false;
    QByteArray m_old;
};

} // namespace

TEST_F(LocalTimeZoneTest, NamesTheSystemsZoneSoThatItIsReadOnce)
{
    const QByteArray before = QTimeZone::systemTimeZoneId();
    const QDateTime instant = QDateTime::fromSecsSinceEpoch(1764000000, QTimeZone::utc());
    const QString localBefore = instant.toLocalTime().toString(Qt::ISODate);
    LocalTimeZone::readOnce();
    EXPECT_EQ(qgetenv("TZ"), QByteArray(":/etc/localtime"));
    // Qt still finds the system's zone (not a zone called ":/etc/localtime"), and local times
    // are what they were.
    EXPECT_EQ(QTimeZone::systemTimeZoneId(), before);
    EXPECT_EQ(instant.toLocalTime().toString(Qt::ISODate), localBefore);
}

TEST_F(LocalTimeZoneTest, AZoneTheUserChoseIsKept)
{
    qputenv("TZ", "XYZ-8"); // a POSIX zone 8 h east of UTC: no tzdata needed
    LocalTimeZone::readOnce();
    EXPECT_EQ(qgetenv("TZ"), QByteArray("XYZ-8"));
    EXPECT_EQ(QDateTime::fromSecsSinceEpoch(0, QTimeZone::utc()).toLocalTime().time().hour(), 8);
}
