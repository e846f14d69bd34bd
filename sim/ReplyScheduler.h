#pragma once

#include <QByteArray>
#include <QObject>
#include <QVector>
#include <functional>

class QSocketNotifier;

namespace opentop {

// Sends replies at their moment on the wire to within a few microseconds: a timerfd on the
// event loop, where a QTimer rounds to whole milliseconds (a tenth of a fast transaction).
// Times are CLOCK_MONOTONIC nanoseconds (nowNs()).
class ReplyScheduler : public QObject
{
    Q_OBJECT
public:
    struct Reply
    {
        QByteArray bytes;
        qint64 startNs = 0; // when its first byte goes on the wire
        qint64 dueNs = 0;   // when its last byte has left: sent to the client then
    };
    using Send = std::function<void(const QByteArray&)>;

    explicit ReplyScheduler(Send send, QObject* parent = nullptr);
    ~ReplyScheduler() override;

    static qint64 nowNs();
    void schedule(const Reply& reply);
    // Replies not yet sent, earliest first; a half-duplex line garbles them in place.
    QVector<Reply>& pending() { return m_pending; }
    void clear();

private:
    void arm();
    void onTimer();

    Send m_send;
    int m_fd = -1;
    QSocketNotifier* m_notifier = nullptr;
    QVector<Reply> m_pending;
};

} // namespace opentop
