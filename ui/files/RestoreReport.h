#pragma once

#include "model/files/RestorePlan.h"

#include <QCoreApplication>
#include <QVector>

namespace opentop {

// The report of a restore (or of its preview) for people to keep: plain text or CSV, one line
// per setting with the file's value, the drive's value before, and what happened.
class RestoreReport
{
    Q_DECLARE_TR_FUNCTIONS(opentop::RestoreReport)
public:
    static QString text(const QString& file, const QVector<RestorePlan>& plans, bool written);
    static QString csv(const QVector<RestorePlan>& plans);
    // CSV when `path` ends in .csv, plain text otherwise.
    static bool save(const QString& path, const QString& file, const QVector<RestorePlan>& plans,
                     bool written, QString* error);
    // "3 written and verified, 40 unchanged, 0 failed, 0 not attempted".
    static QString summary(const RestorePlan& plan);
};

} // namespace opentop
