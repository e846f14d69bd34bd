#pragma once

#include <QObject>
#include <QProcess>
#include <QString>

namespace opentop::soak {

// One opentop-sim process serving the simulated bus on a pty with wire timing: what a USB
// adapter on a real RS-485 line looks like to the program measured.
class SoakSim : public QObject
{
    Q_OBJECT
public:
    explicit SoakSim(QObject* parent = nullptr);
    ~SoakSim() override;

    // Starts `program` and waits for its "ready"; false with *error when it does not come.
    bool start(const QString& program, const QString& devices, int baud, QString* error);
    void stop();
    QString pty() const { return m_pty; }
    qint64 pid() const { return m_process.processId(); }
    bool isRunning() const { return m_process.state() == QProcess::Running; }

signals:
    // The simulator ended before stop().
    void died(const QString& why);

private:
    QProcess m_process;
    QString m_pty;
    bool m_stopping = false;
};

} // namespace opentop::soak
