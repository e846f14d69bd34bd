// PortLock on Windows. A COM port opens exclusively (CreateFile without sharing, as libmodbus
// opens it): the system itself keeps a second program off a port in use, for as long as the
// port is open and no longer, and there is no lock-file convention to honour. acquire() finds
// out beforehand whether another program has the port, so that OpenTOP refuses in the same
// words as on Linux before anything touches the line. Some drivers let a port be opened twice
// (Wine's on a pty, virtual port pairs): a named mutex per port, held while the port is ours
// and gone with the process as flock is, keeps a second OpenTOP off it there too.
#include "transport/PortLock.h"

#include "transport/ComPort_win.h"
#include "transport/TransportLog.h"

#include <string>
#include <windows.h>

namespace opentop {

PortLock::PortLock(const QString& port, const QStringList& lockDirectories)
    : m_port(port)
    , m_device(port)
    , m_directories(lockDirectories)
{
}

namespace {

// "Local\opentop-port-COM5" for COM5, com5 and \\.\COM5: one name per port in this session.
std::wstring mutexName(const QString& port)
{
    QString name = port.trimmed().toUpper();
    if (name.startsWith(QLatin1String("\\\\.\\")))
        name = name.mid(4);
    name.replace(QLatin1Char('\\'), QLatin1Char('_'));
    return (QStringLiteral("Local\\opentop-port-") + name).toStdWString();
}

} // namespace

PortLock::Outcome PortLock::acquire(QString* error)
{
    release();
    HANDLE mutex = CreateMutexW(nullptr, FALSE, mutexName(m_port).c_str());
    if (mutex && GetLastError() == ERROR_ALREADY_EXISTS) {
        CloseHandle(mutex);
        if (error)
            *error = inUseText(m_port, findHolder(m_device, m_directories));
        qCWarning(lcTransport).noquote() << m_port << "refused: held by another OpenTOP";
        return Outcome::InUse;
    }
    if (!mutex)
        qCWarning(lcTransport).noquote()
            << QStringLiteral("no port mutex for %1: relying on the exclusive open only")
                   .arg(m_port);
    m_mutex = mutex;
    const std::wstring path = ComPort::devicePath(m_port.trimmed()).toStdWString();
    HANDLE port = CreateFileW(path.c_str(), GENERIC_READ | GENERIC_WRITE, 0, nullptr, OPEN_EXISTING,
                              0, nullptr);
    if (port == INVALID_HANDLE_VALUE) {
        const DWORD err = GetLastError();
        if (err != ERROR_ACCESS_DENIED && err != ERROR_SHARING_VIOLATION) {
            release();
            return Outcome::OpenFailed; // the caller's own open reports it
        }
        release();
        // Windows does not say who has it open.
        if (error)
            *error = inUseText(m_port, findHolder(m_device, m_directories));
        qCWarning(lcTransport).noquote() << m_port << "refused: open in another program";
        return Outcome::InUse;
    }
    CloseHandle(port);
    return Outcome::Acquired;
}

bool PortLock::wantsExclusive(int fd)
{
    Q_UNUSED(fd);
    return false; // exclusive already
}

void PortLock::makeExclusive(int fd)
{
    Q_UNUSED(fd);
}

bool PortLock::isHeld() const
{
    return m_mutex != nullptr;
}

void PortLock::release()
{
    m_file.reset();
    if (m_mutex) {
        CloseHandle(m_mutex);
        m_mutex = nullptr;
    }
}

PortLock::Holder PortLock::findHolder(const QString& device, const QStringList& lockDirectories)
{
    Q_UNUSED(device);
    Q_UNUSED(lockDirectories);
    return {};
}

} // namespace opentop
