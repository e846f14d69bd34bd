#pragma once

#include "model/bus/VariantNeed.h"

#include <QStringList>
#include <QVector>

class QWidget;

namespace opentop {

class BusDrives;
class DeviceSession;

// The window's side of VariantNeed: when the model says a drive's variant is needed, asks it
// (modal) with what it changes, one button per variant, "Not known" and Cancel (the default).
// A chosen variant goes to BusDrives (kept for the bus); "Not known" is not asked again.
class VariantQuestion
{
public:
    // True when the action may go on (nothing to ask, a variant chosen, or "not known"); false
    // when the user cancelled: then nothing is done.
    static bool ensure(QWidget* parent, BusDrives* drives, int slave, VariantNeed::Purpose purpose,
                       const QStringList& parameters = {});
    // The same for each of `slaves`, in turn: empty when the action may go on, otherwise what
    // stopped it ("the variant of machine number 150 was not given").
    static QString ensureEach(QWidget* parent, BusDrives* drives, const QVector<int>& slaves,
                              VariantNeed::Purpose purpose, const QStringList& parameters = {});
    // The same for the drive of `session` (a session of BusDrives; others are never asked).
    static bool ensure(QWidget* parent, const DeviceSession* session, VariantNeed::Purpose purpose,
                       const QStringList& parameters = {});
};

} // namespace opentop
