#include "ui/pages/SpeedUnitsPage.h"
#include "model/session/DeviceParameters.h"
#include "tests/ui/UiSimFixture.h"
#include "ui/workspace/ParameterField.h"

#include <QLineEdit>

using namespace opentop;

namespace {

class SpeedUnitsPageTest : public test::UiSimFixture
{
protected:
    void SetUp() override
    {
        startBus(QStringLiteral("dbu200@1"));
        params = std::make_unique<DeviceParameters>(session(1));
        page = std::make_unique<SpeedUnitsPage>(params.get());
        ASSERT_TRUE(
            runUntil(page.get(), &ParameterPage::operationFinished, [this] { page->refresh(); }));
    }
    void TearDown() override
    {
        page.reset();
        params.reset();
        DriveSimFixture::TearDown();
    }

    bool enabled(const QString& name) const { return page->field(name)->isEnabled(); }
    void enter(const QString& name, const QString& text)
    {
        page->field(name)->enter(text);
        ASSERT_TRUE(page->field(name)->problem().isEmpty())
            << qPrintable(page->field(name)->problem());
    }
    // What SpeedDisplay makes of the drive's values with `overrides` in place.
    SpeedDisplay::Shown expected(const QHash<QString, double>& overrides, double rpm) const
    {
        QString error;
        const auto display = SpeedDisplay::fromValues(
            SpeedDisplay::Names::withPrefix(),
            [&](const QString& n) -> std::optional<double> {
                if (overrides.contains(n))
                    return overrides.value(n);
                const auto* e = params->entry(n);
                return e && e->device.valid ? std::optional<double>(e->device.number)
                                            : std::nullopt;
            },
            &error);
        EXPECT_TRUE(display) << qPrintable(error);
        return display ? display->show(rpm) : SpeedDisplay::Shown{};
    }

    std::unique_ptr<DeviceParameters> params;
    std::unique_ptr<SpeedUnitsPage> page;
};

} // namespace

TEST_F(SpeedUnitsPageTest, EnablesOnlyTheFieldsOfTheChosenUnit)
{
    const QStringList time = {QStringLiteral("unit.time_diameter"), QStringLiteral("unit.distance"),
                              QStringLiteral("unit.distance_unit"),
                              QStringLiteral("unit.time_unit")};
    const QString yd = QStringLiteral("unit.diameter_yard");
    const QString m = QStringLiteral("unit.diameter_meter");
    enter(QStringLiteral("unit.mode"), QStringLiteral("0"));
    for (const QString& n : {QStringLiteral("unit.reduction"), QStringLiteral("unit.increase"),
                             QStringLiteral("unit.decimals"), QStringLiteral("unit.update_time"),
                             QStringLiteral("unit.ro0"), QStringLiteral("unit.ro3")})
        EXPECT_TRUE(enabled(n)) << qPrintable(n);
    EXPECT_FALSE(enabled(yd));
    EXPECT_FALSE(enabled(m));
    for (const QString& n : time)
        EXPECT_FALSE(enabled(n)) << qPrintable(n);

    enter(QStringLiteral("unit.mode"), QStringLiteral("1"));
    EXPECT_TRUE(enabled(yd));
    EXPECT_FALSE(enabled(m));
    EXPECT_FALSE(enabled(time.first()));

    enter(QStringLiteral("unit.mode"), QStringLiteral("2"));
    EXPECT_FALSE(enabled(yd));
    EXPECT_TRUE(enabled(m));

    enter(QStringLiteral("unit.mode"), QStringLiteral("3"));
    EXPECT_FALSE(enabled(yd));
    EXPECT_FALSE(enabled(m));
    for (const QString& n : time)
        EXPECT_TRUE(enabled(n)) << qPrintable(n);
    EXPECT_TRUE(enabled(QStringLiteral("unit.reduction")));
}

TEST_F(SpeedUnitsPageTest, PreviewFollowsPendingEditsBeforeTheyAreWritten)
{
    const int writesBefore = writesSent();
    enter(QStringLiteral("unit.mode"), QStringLiteral("0"));
    enter(QStringLiteral("unit.decimals"), QStringLiteral("3"));
    enter(QStringLiteral("unit.reduction"), QStringLiteral("10.00"));
    const QHash<QString, double> edits = {{QStringLiteral("unit.mode"), 0},
                                          {QStringLiteral("unit.decimals"), 3},
                                          {QStringLiteral("unit.reduction"), 10}};
    EXPECT_EQ(page->previewText(), expected(edits, 1500).panel);
    // 150.000 computed; the 5-digit panel shows 150.00.
    EXPECT_EQ(page->previewText(), QStringLiteral("150.00"));
    EXPECT_EQ(page->previewUnit(), QStringLiteral("r/min"));
    page->setPreviewSpeed(1500, true);
    EXPECT_EQ(page->previewText(), expected(edits, -1500).panel);
    EXPECT_TRUE(page->previewText().startsWith(QLatin1Char('-')));
    EXPECT_EQ(writesSent(), writesBefore); // a preview never writes

    // Linear speed in m/min with a diameter: the page and SpeedDisplay agree.
    enter(QStringLiteral("unit.mode"), QStringLiteral("2"));
    enter(QStringLiteral("unit.diameter_meter"), QStringLiteral("500")); // mm
    enter(QStringLiteral("unit.decimals"), QStringLiteral("2"));
    page->setPreviewSpeed(1200);
    const QHash<QString, double> linear = {{QStringLiteral("unit.mode"), 2},
                                           {QStringLiteral("unit.decimals"), 2},
                                           {QStringLiteral("unit.reduction"), 10},
                                           {QStringLiteral("unit.diameter_meter"), 500}};
    EXPECT_EQ(page->previewText(), expected(linear, 1200).panel);
    EXPECT_EQ(page->previewUnit(), QStringLiteral("m/min"));

    // Typing, before Enter or Tab confirms the value, already moves the preview.
    auto* edit = qobject_cast<QLineEdit*>(page->field(QStringLiteral("unit.reduction"))->editor());
    ASSERT_TRUE(edit);
    edit->setText(QStringLiteral("20"));
    emit edit->textEdited(edit->text());
    QHash<QString, double> typed = linear;
    typed.insert(QStringLiteral("unit.reduction"), 20);
    EXPECT_EQ(page->previewText(), expected(typed, 1200).panel);
}

TEST_F(SpeedUnitsPageTest, WrittenSettingsReachTheDriveAndThePreviewStays)
{
    enter(QStringLiteral("unit.mode"), QStringLiteral("0"));
    enter(QStringLiteral("unit.decimals"), QStringLiteral("3"));
    enter(QStringLiteral("unit.reduction"), QStringLiteral("10.00"));
    const QString before = page->previewText();
    ASSERT_TRUE(
        runUntil(page.get(), &ParameterPage::operationFinished, [this] { page->writePage(); }));
    EXPECT_TRUE(params->pendingNames().isEmpty());
    EXPECT_EQ(page->previewText(), before);
    // 10.00 at 0.01 per step = 1000 in the low word of the 32-bit value at 0x0403.
    EXPECT_EQ(simRegister(1, 0x0404), 1000);
}
