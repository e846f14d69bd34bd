#pragma once

#include <QLabel>

namespace opentop {

class EolStation;

// The operator screen's amber notice of what the station has not finished: results kept on the
// station while the results server does not answer, units a station process that is gone left
// unfinished, and the recipe's drives being made safe (or what that found). Hidden while the
// line is clear; it follows the station's signals by itself.
class StationNotice : public QLabel
{
    Q_OBJECT
public:
    explicit StationNotice(EolStation* station, QWidget* parent = nullptr);
    void refresh();

private:
    EolStation* m_station;
};

} // namespace opentop
