#pragma once

// Reads what a writer puts into a FIFO, from a thread: the read end is open before the writer
// comes (so the writer never waits), and the thread ends at the writer's EOF or once
// `writerDone` is set without anything having come (a writer that replaced the FIFO by a
// regular file never opens it). For tests of saving to something that is not a regular file.
#include <QByteArray>
#include <QFile>
#include <QString>
#include <atomic>
#include <chrono>
#include <fcntl.h>
#include <future>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

namespace opentop::test {

inline std::future<QByteArray> readFifo(const QString& path, std::atomic<bool>* writerDone)
{
    const int fd = ::open(QFile::encodeName(path).constData(), O_RDONLY | O_NONBLOCK);
    return std::async(std::launch::async, [fd, writerDone] {
        QByteArray data;
        bool got = false;
        for (int spins = 0; fd >= 0 && spins < 6000; ++spins) {
            char buffer[4096];
            const ssize_t n = ::read(fd, buffer, sizeof buffer);
            if (n > 0) {
                data.append(buffer, int(n));
                got = true;
                continue;
            }
            if (n == 0 && (got || writerDone->load()))
                break;
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        if (fd >= 0)
            ::close(fd);
        return data;
    });
}

inline bool isFifo(const QString& path)
{
    struct stat st = {};
    return ::stat(QFile::encodeName(path).constData(), &st) == 0 && S_ISFIFO(st.st_mode);
}

// Saves through `save` into a new FIFO in `dir`; returns what came out of the FIFO and whether
// it is still a FIFO afterwards.
template <typename Save> QByteArray saveThroughFifo(const QString& dir, Save save, bool* stillFifo)
{
    const QString path = dir + QStringLiteral("/pipe");
    if (::mkfifo(QFile::encodeName(path).constData(), 0600) != 0)
        return {};
    std::atomic<bool> done{false};
    auto data = readFifo(path, &done);
    save(path);
    done = true;
    const QByteArray got = data.get();
    *stillFifo = isFifo(path);
    return got;
}

} // namespace opentop::test
