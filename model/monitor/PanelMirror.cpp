#include "model/monitor/PanelMirror.h"

#include "model/monitor/DeviceMonitor.h"
#include "model/profile/Profile.h"
#include "model/profile/RoleEvaluator.h"
#include "model/profile/RunningData.h"
#include "model/profile/SpeedDisplay.h"

namespace opentop {

bool PanelMirror::supported(const Profile& profile)
{
    return RoleEvaluator::parameter(profile, QStringLiteral("panelDisplay")) != nullptr;
}

QString PanelMirror::contentName(Content content)
{
    switch (content) {
    case Content::Speed:
        return tr("speed");
    case Content::MachineNumber:
        return tr("machine number");
    case Content::RunningData:
        return tr("running data No.");
    case Content::Countdown:
        return tr("countdown");
    case Content::Load:
        return tr("load rate");
    }
    return QString();
}

QString PanelMirror::fit(const QString& text, bool* overflow)
{
    return SpeedDisplay::panelText(text, overflow);
}

PanelMirror::Shown PanelMirror::show(const Profile& profile, const MonitorSample& sample,
                                     std::optional<Content> content, const Countdown& countdown)
{
    Shown shown;
    if (sample.alarmActive.value_or(false)) {
        shown.alarm = true;
        shown.text = sample.activeAlarm ? sample.activeAlarm->panel : QStringLiteral("AL---");
        shown.meaning =
            sample.activeAlarm
                ? tr("Alarm %1 %2").arg(sample.activeAlarm->panel, sample.activeAlarm->name)
                : tr("Alarm (code not read yet)");
        return shown;
    }
    // At standby the panel shows the speed; the setting chooses what it shows while running.
    const Content c =
        sample.running.value_or(false) ? content.value_or(Content::Speed) : Content::Speed;
    switch (c) {
    case Content::Speed: {
        if (sample.currentShown && sample.currentShown->valid) {
            shown.text = fit(sample.currentShown->text, &shown.overflow);
            shown.meaning =
                tr("Current speed %1 %2").arg(sample.currentShown->text, sample.currentShown->unit);
        } else if (sample.currentShown) {
            shown.text = sample.currentShown->text; // "--:--": no finite time at standstill
            shown.meaning =
                tr("Current speed: no finite value in %1").arg(sample.currentShown->unit);
        } else {
            const ParameterMeta* speed =
                RoleEvaluator::parameter(profile, QStringLiteral("currentSpeed"));
            const std::optional<double> v = speed ? sample.signedSpeed(speed->name) : std::nullopt;
            shown.text =
                v ? fit(QString::number(*v, 'f', 0), &shown.overflow) : QStringLiteral("-----");
            shown.meaning = v ? tr("Current speed %1 r/min").arg(*v) : tr("Speed not read");
        }
        break;
    }
    case Content::MachineNumber:
        shown.text = QStringLiteral("ID%1").arg(sample.slave, 3, 10, QLatin1Char('0'));
        shown.meaning = tr("Machine number %1").arg(sample.slave);
        break;
    case Content::RunningData: {
        const std::optional<int> spno = RunningData::selected(
            profile, [&sample](const QString& name) { return sample.rawOf(name); });
        if (spno) {
            shown.text = QStringLiteral("SPno%1").arg(*spno);
            shown.meaning = tr("Running data SPno%1").arg(*spno);
        } else {
            shown.text = QStringLiteral("SPno-");
            shown.meaning = tr("Running data not read");
        }
        break;
    }
    case Content::Countdown: {
        // Total hours and minutes of the configured running time.
        const int hours = countdown.days * 24 + countdown.hours;
        shown.text = QStringLiteral("%1-%2")
                         .arg(hours, 2, 10, QLatin1Char('0'))
                         .arg(countdown.minutes, 2, 10, QLatin1Char('0'));
        shown.meaning = tr("Countdown set to %1 d %2 h %3 min %4 s (the drive does not report "
                           "the time left)")
                            .arg(countdown.days)
                            .arg(countdown.hours)
                            .arg(countdown.minutes)
                            .arg(countdown.seconds);
        break;
    }
    case Content::Load: {
        const ParameterMeta* load = RoleEvaluator::parameter(profile, QStringLiteral("load"));
        const MonitorValue* v = load ? sample.find(load->name) : nullptr;
        if (v && v->value.valid) {
            shown.text =
                QStringLiteral("LD%1").arg(qRound(v->value.number), 3, 10, QLatin1Char('0'));
            shown.meaning = tr("Load rate %1 %").arg(qRound(v->value.number));
        } else {
            shown.text = QStringLiteral("LD---");
            shown.meaning = tr("Load rate not read");
        }
        break;
    }
    }
    return shown;
}

} // namespace opentop
