#include "model/io/InputFile.h"

#include <QFile>

namespace opentop {

InputFile::Status InputFile::read(const QString& path, qint64 maxBytes, QByteArray* data,
                                  QString* error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        if (error)
            *error = tr("cannot read %1: %2").arg(path, file.errorString());
        return Status::CannotOpen;
    }
    *data = file.read(maxBytes + 1);
    return data->size() > maxBytes ? Status::TooLarge : Status::Ok;
}

} // namespace opentop
