#pragma once

#include <QByteArray>
#include <QString>

namespace opentop {

// Writes a whole file the safe way for what the path names. A regular file (or a new one) is
// replaced atomically: a temporary file beside it, renamed over it only when all was written.
// Anything else that exists (a device such as /dev/stdout, a FIFO) is written through, never
// replaced by a regular file, and every write error is reported (a full device says so).
// A directory is refused. A write that fails (a full disk, a file size limit) leaves the old
// file as it was and says why; the data is written straight through, never left in a buffer
// whose error a commit could miss.
class OutputFile
{
public:
    // Why `path` cannot be written, before any work is done for it (a directory, a folder that
    // does not exist); empty when it looks writable.
    static QString problem(const QString& path);
    static bool write(const QString& path, const QByteArray& data, QString* error);
};

} // namespace opentop
