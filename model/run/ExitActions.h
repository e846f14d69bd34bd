#pragma once

#include <QObject>
#include <QStringList>
#include <QVector>
#include <functional>

namespace opentop {

class BusDrives;

// Carries out what the user chose for those drives: stop them (each family's stop broadcast,
// then every listed drive confirmed stopped), or give control back to their inputs (the
// "ioPriority" role written and read back). Asynchronous; `done` gets one line per failure.
class ExitActions : public QObject
{
    Q_OBJECT
public:
    using Done = std::function<void(const QStringList& failures)>;
    explicit ExitActions(BusDrives* drives, QObject* parent = nullptr);

    void stop(const QVector<int>& slaves, Done done);
    void returnToIoPriority(const QVector<int>& slaves, Done done);

private:
    void returnNext(QVector<int> slaves, QStringList failures, Done done);

    BusDrives* m_drives;
};

} // namespace opentop
