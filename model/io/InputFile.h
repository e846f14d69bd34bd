#pragma once

#include <QByteArray>
#include <QCoreApplication>
#include <QString>

namespace opentop {

// Reads a whole file that a person chose, never more than a cap: what the file claims to hold
// is not trusted (a device such as /dev/zero has no size). The counterpart of OutputFile.
class InputFile
{
    Q_DECLARE_TR_FUNCTIONS(opentop::InputFile)
public:
    enum class Status
    {
        Ok,
        CannotOpen, // *error says why
        TooLarge    // more than maxBytes: the caller names what the file should have been
    };
    // Reads at most maxBytes + 1 bytes of `path` into *data.
    static Status read(const QString& path, qint64 maxBytes, QByteArray* data, QString* error);
};

} // namespace opentop
