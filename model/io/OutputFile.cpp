#include "model/io/OutputFile.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::OutputFile", text);
}

} // namespace

QString OutputFile::problem(const QString& path)
{
    const QFileInfo info(path);
    if (info.isDir())
        return tr("cannot write %1: it is a directory; name a file").arg(path);
    if (!info.exists() && !info.absoluteDir().exists())
        return tr("cannot write %1: the folder %2 does not exist")
            .arg(path, info.absoluteDir().path());
    return QString();
}

bool OutputFile::write(const QString& path, const QByteArray& data, QString* error)
{
    auto fail = [&](const QString& reason) {
        if (error)
            *error = tr("cannot write %1: %2").arg(path, reason);
        return false;
    };
    const QFileInfo info(path); // follows a symbolic link to what it names
    if (info.isDir())
        return fail(tr("it is a directory; name a file"));
    if (info.exists() && !info.isFile()) {
        // A device or FIFO: write through it, unbuffered so that every error is seen here.
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly))
            return fail(file.errorString());
        qint64 done = 0;
        while (done < data.size()) {
            const qint64 n = file.write(data.constData() + done, data.size() - done);
            if (n <= 0)
                return fail(file.errorString());
            done += n;
        }
        file.close();
        if (file.error() != QFileDevice::NoError)
            return fail(file.errorString());
        return true;
    }
    // A symbolic link to a regular file: replace the file it names, keep the link. Unbuffered:
    // Qt 6.4's commit() misses the error of flushing a buffered write under 16 KB, so a full
    // disk would leave an empty file renamed over the old one; written straight through, the
    // write itself fails and the old file stays.
    QSaveFile file(info.isSymLink() ? info.canonicalFilePath() : path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Unbuffered))
        return fail(file.errorString());
    if (file.write(data) != data.size()) {
        const QString reason = file.errorString();
        file.cancelWriting();
        return fail(reason);
    }
    if (!file.commit())
        return fail(file.errorString());
    return true;
}

} // namespace opentop
