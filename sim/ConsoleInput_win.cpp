#include "sim/ConsoleInput.h"

#include <cstdio>
#include <mutex>
#include <thread>

namespace opentop {

// What the reading thread and the object share: the thread posts only while the object lives.
struct ConsoleInput::Reader
{
    std::mutex mutex;
    ConsoleInput* target = nullptr; // read and cleared under the mutex only

    void post(const QByteArray& bytes, bool atEnd)
    {
        std::lock_guard<std::mutex> lock(mutex);
        if (ConsoleInput* input = target)
            QMetaObject::invokeMethod(
                input, [input, bytes, atEnd] { emit input->received(bytes, atEnd); },
                Qt::QueuedConnection);
    }
};

ConsoleInput::ConsoleInput(QObject* parent)
    : QObject(parent)
    , m_reader(std::make_shared<Reader>())
{
    m_reader->target = this;
    // Blocked in a read until a line comes, also when the program ends: Windows ends the thread
    // with the process. It holds its own reference to what it shares.
    std::thread([reader = m_reader] {
        char line[1024];
        while (std::fgets(line, sizeof line, stdin))
            reader->post(QByteArray(line), false);
        reader->post(QByteArray(), true);
    }).detach();
}

ConsoleInput::~ConsoleInput()
{
    stop();
}

void ConsoleInput::stop()
{
    std::lock_guard<std::mutex> lock(m_reader->mutex);
    m_reader->target = nullptr;
}

} // namespace opentop
