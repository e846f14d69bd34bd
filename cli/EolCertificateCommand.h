#pragma once

#include "cli/EolSubcommand.h"

namespace opentop {

// `eol certificate SERIAL | --id ID [-o FILE] [--json]`: the newest record of a serial number
// (or the record ID) as a printable PDF (report/CertificatePdf) or as JSON (UnitRecordJson).
class EolCertificateCommand : public EolSubcommand
{
public:
    QString name() const override { return QStringLiteral("certificate"); }
    QString synopsis() const override
    {
        return QStringLiteral("certificate SERIAL | --id ID [--db URL] [-o FILE.pdf] [--json]");
    }
    QString summary() const override;
    QList<QCommandLineOption> options() const override;
    int run(CliContext& context, const QStringList& args) override;

    // "C200-0001.pdf": the default file, the serial with what a file name cannot hold replaced.
    static QString defaultFile(const QString& serial);
};

} // namespace opentop
