#pragma once

#include <QLabel>

namespace opentop {

class EolStation;

// This shift's figures on the operator screen, as the results database holds them
// (StationYield): tested, passed, failed, station errors and the yields, with the command that
// prints the same figures in its tooltip.
class StationFigures : public QLabel
{
    Q_OBJECT
public:
    explicit StationFigures(EolStation* station, QWidget* parent = nullptr);
    void refresh();

private:
    EolStation* m_station;
};

} // namespace opentop
