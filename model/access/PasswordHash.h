#pragma once

#include <QByteArray>
#include <QString>

namespace opentop {

// A password as the results database keeps it: PBKDF2-HMAC-SHA256 (Qt's QPasswordDigestor) with
// a random 16-byte salt per user and the iteration count stored with it, so that a later program
// can raise the count for new passwords and still check old ones. The password itself is never
// kept, logged or compared in clear.
struct PasswordHash
{
    static constexpr int kIterations = 120000; // new passwords
    static constexpr int kMinimumIterations = 100000;
    static constexpr int kMinimumLength = 4;

    QByteArray hash; // base64 of the 32-byte key
    QByteArray salt; // base64
    int iterations = 0;

    // A fresh salt from the system's random source.
    static PasswordHash make(const QString& password, int iterations = kIterations);
    // Constant-time: how much of the key matches never shows in the time taken.
    bool matches(const QString& password) const;
    bool isValid() const { return !hash.isEmpty() && !salt.isEmpty() && iterations > 0; }

    // Why a new password is refused; empty when it is accepted.
    static QString weakness(const QString& password);
};

} // namespace opentop
