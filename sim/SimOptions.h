#pragma once

#include "sim/DcMotor.h"
#include "sim/FaultInjector.h"
#include "sim/SimDefectSpec.h"

#include <QCoreApplication>
#include <QPair>
#include <QString>
#include <QStringList>
#include <QVector>
#include <optional>

namespace opentop {

// The command line of opentop-sim.
struct SimOptions
{
    Q_DECLARE_TR_FUNCTIONS(opentop::SimOptions)
public:
    QString devices;
    bool pty = false;
    QString ptyLink; // symlink to create, empty for none
    bool tcp = false;
    QString tcpHost = QStringLiteral("127.0.0.1");
    quint16 tcpPort = 502;
    int baud = 19200;
    char parity = 'N';
    bool wireTiming = false;
    bool halfDuplex = false; // with wireTiming: PtySimServer::setHalfDuplex
    double turnaroundMs = 2.0;
    FaultInjector::Rates faults;
    quint32 seed = 1;
    QVector<QPair<int, SimDefectSpec>> defects; // --defect ID:DEFECT[,...], in order
    DcMotor::Model motor;                       // --motor, every DC controller
    bool quiet = false;
    bool help = false;
    bool version = false;

    // `arguments` without the program name. On error returns nothing and sets *error to a
    // message that names the allowed values.
    static std::optional<SimOptions> parse(const QStringList& arguments, QString* error);
    static QString usage();
    static const QList<int>& bauds();
};

} // namespace opentop
