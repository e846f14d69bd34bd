#pragma once

#include <QHash>
#include <QProcess>
#include <QString>
#include <QVector>

namespace opentop::faultmatrix {

struct Setting;

// The opentop-sim process under the matrix: started on a pty symlink with wire timing and
// faults, driven through its console. The truth about the drives comes from here (the console
// reads the simulator's registers, never the wire).
class MatrixSim
{
public:
    explicit MatrixSim(const QString& binDir);
    ~MatrixSim();

    bool start(const QString& devices, const QString& faults, int seed, const QString& link,
               int baud, QString* error);
    void stop();

    // One console command and its one-line answer ("" when the simulator did not answer).
    QString command(const QString& line);
    // Many commands at once, their answers in order.
    QStringList commands(const QStringList& lines);
    bool set(int slave, quint16 address, quint16 value);
    // The registers each setting occupies, as the simulated drive holds them.
    QHash<QString, QVector<quint16>> truth(const QVector<Setting>& settings, QString* error);

    static QString key(int slave, const QString& name);

private:
    QString readLine(int timeoutMs);

    QString m_binDir;
    QProcess m_process;
};

} // namespace opentop::faultmatrix
