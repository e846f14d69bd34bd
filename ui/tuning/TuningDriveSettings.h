#pragma once

#include "model/tuning/TuningSpec.h"

#include <QObject>
#include <QString>

namespace opentop {

class DeviceSession;

// What the tuning page must know of the drive's settings before a test, read each time the
// page is shown: the unit of the closed-loop speed and the speed command's raw scale (those of
// the closed-loop mode, also while the drive is in another), the drive's maximum current, and
// a note when the drive is not in a closed-loop speed mode. Values not read keep the last ones.
class TuningDriveSettings : public QObject
{
    Q_OBJECT
public:
    TuningDriveSettings(DeviceSession* session, const TuningSpec& spec, QObject* parent = nullptr);

    // Reads the speed mode and the maximum current; changed() when they are known.
    void read();
    QString speedUnit() const { return m_unit; }
    // The speed command's scale (engineering per register count).
    double scale() const { return m_scale; }
    double maxCurrent() const { return m_maxCurrent; } // A, 0: unknown
    // Why a step would not run in a closed loop (the mode not read, or another), or empty.
    QString modeNote() const { return m_modeNote; }

signals:
    void changed();

private:
    DeviceSession* m_session;
    TuningSpec m_spec;
    QString m_unit;
    double m_scale = 1;
    double m_maxCurrent = 0;
    QString m_modeNote;
};

} // namespace opentop
