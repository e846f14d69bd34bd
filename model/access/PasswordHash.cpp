#include "model/access/PasswordHash.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QPasswordDigestor>
#include <QRandomGenerator>

namespace opentop {

namespace {

constexpr int kKeyBytes = 32;
constexpr int kSaltBytes = 16;

QByteArray derive(const QString& password, const QByteArray& salt, int iterations)
{
    return QPasswordDigestor::deriveKeyPbkdf2(QCryptographicHash::Sha256, password.toUtf8(), salt,
                                              iterations, kKeyBytes);
}

} // namespace

PasswordHash PasswordHash::make(const QString& password, int iterations)
{
    QByteArray salt(kSaltBytes, Qt::Uninitialized);
    QRandomGenerator::system()->fillRange(reinterpret_cast<quint32*>(salt.data()),
                                          kSaltBytes / int(sizeof(quint32)));
    PasswordHash h;
    h.iterations = std::max(iterations, kMinimumIterations);
    h.salt = salt.toBase64();
    h.hash = derive(password, salt, h.iterations).toBase64();
    return h;
}

bool PasswordHash::matches(const QString& password) const
{
    if (!isValid())
        return false;
    const QByteArray expected = QByteArray::fromBase64(hash);
    const QByteArray got = derive(password, QByteArray::fromBase64(salt), iterations);
    if (expected.size() != got.size())
        return false;
    unsigned char diff = 0;
    for (int i = 0; i < got.size(); ++i)
        diff |= static_cast<unsigned char>(expected[i] ^ got[i]);
    return diff == 0;
}

QString PasswordHash::weakness(const QString& password)
{
    if (password.size() < kMinimumLength)
        return QCoreApplication::translate("opentop::PasswordHash",
                                           "a password needs at least %1 characters")
            .arg(kMinimumLength);
    return QString();
}

} // namespace opentop
