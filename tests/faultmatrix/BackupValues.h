#pragma once

#include <QString>
#include <QVector>

namespace opentop::faultmatrix {

// One setting of one drive as a backup file holds it.
struct Setting
{
    int slave = 0;
    QString family;
    QString name;
    quint16 address = 0;
    QVector<quint16> registers;
};

// The settings in a backup file, read straight from its JSON (not through the tool under test).
class BackupValues
{
public:
    static QVector<Setting> load(const QString& path, QString* error);
    static QVector<Setting> ofSlave(const QVector<Setting>& settings, int slave);
    static QVector<int> slaves(const QVector<Setting>& settings);
};

} // namespace opentop::faultmatrix
