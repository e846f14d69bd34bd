#pragma once

#include <QJsonArray>
#include <QWidget>

class QTableWidget;

namespace opentop {

class Profile;

// A hold step's limits as a table: the measured value chosen from the family's live values,
// its statistic (min, mean, max), lower and upper limits, and the value's own unit (set with
// the value: the recipe checker refuses any other), with buttons to add and remove a limit.
class RecipeLimitsTable : public QWidget
{
    Q_OBJECT
public:
    enum Column
    {
        Parameter,
        Statistic,
        Lower,
        Upper,
        Unit
    };

    RecipeLimitsTable(const Profile* profile, const QJsonArray& limits, QWidget* parent = nullptr);

    QJsonArray limits() const;
    QTableWidget* table() const { return m_table; }

signals:
    void changed();

private:
    void fillRow(int row, const QJsonObject& limit);
    void addLimit();
    void removeSelected();
    QString unitOf(const QString& parameter) const;

    const Profile* m_profile;
    QTableWidget* m_table;
    bool m_filling = false;
};

} // namespace opentop
