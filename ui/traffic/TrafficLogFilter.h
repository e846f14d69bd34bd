#pragma once

#include <QSortFilterProxyModel>

namespace opentop {

// Filters the traffic log model's rows by drive, direction and "errors only".
class TrafficLogFilter : public QSortFilterProxyModel
{
    Q_OBJECT
public:
    enum class DirectionFilter
    {
        All,
        Tx,
        Rx,    // replies
        Events // no reply, port errors
    };

    explicit TrafficLogFilter(QObject* parent = nullptr);

    void setSlave(int slave); // -1: every drive
    void setDirection(DirectionFilter direction);
    void setErrorsOnly(bool errorsOnly);
    int slave() const { return m_slave; }
    DirectionFilter direction() const { return m_direction; }
    bool errorsOnly() const { return m_errorsOnly; }

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex& sourceParent) const override;

private:
    int m_slave = -1;
    DirectionFilter m_direction = DirectionFilter::All;
    bool m_errorsOnly = false;
};

} // namespace opentop
