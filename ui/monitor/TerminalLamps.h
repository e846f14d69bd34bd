#pragma once

#include <QWidget>
#include <optional>

class QGridLayout;
class QLabel;

namespace opentop {

struct ParameterMeta;

// The ON/OFF fields of a bits parameter as lamps, e.g. the input terminals X0–X3 or outputs
// Y0–Y1: a filled green lamp with "ON" or a hollow grey one with "OFF" under its name, so that
// the state is never told by colour alone. The terminals wrap onto more rows on a narrow window.
class TerminalLamps : public QWidget
{
    Q_OBJECT
public:
    TerminalLamps(const ParameterMeta& meta, QWidget* parent = nullptr);

    // Fields of `meta` shown as lamps: single bits whose values are OFF/ON (or unnamed).
    static bool isLampField(const QStringList& values);
    void setRaw(std::optional<double> raw); // nothing: not read (all lamps unknown)
    // Stale (monitor/Freshness): the last state read, greyed; no lamp is lit green.
    void setStale(bool stale);
    bool isStale() const { return m_stale; }
    // Settings a lamp's meaning depends on (a field's "appliesWhen"), and their values as the
    // drive holds them: a lamp whose condition does not hold shows "n/a" (e.g. Hold while "No
    // holding force" is set).
    QStringList conditionParameters() const;
    void setCondition(const QString& parameter, std::optional<double> raw, const QString& text);
    // "X0 ON, X1 OFF, ..." as shown.
    QString stateText() const;
    // Settings that assign the terminals' functions (a field's "function"), in lamp order.
    QStringList functionParameters() const;
    // Shows under the terminal what `parameter` assigns to it ("Warning-Out"), so that a lit
    // output says what it means.
    void setFunctionText(const QString& parameter, const QString& text);
    QString functionText(const QString& parameter) const;

    QSize minimumSizeHint() const override;
    QSize sizeHint() const override;
    // Terminals side by side before they wrap onto another row.
    int columns() const { return m_columns; }

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    static constexpr int kSpacing = 14;
    int cellWidth() const;
    void arrange(int columns);

    struct Lamp
    {
        int bit = 0;
        QString name;
        QLabel* lamp = nullptr;
        QLabel* state = nullptr;
        QString function;
        QLabel* functionLabel = nullptr;
        QString appliesParam;
        double appliesRaw = 0;
        bool applies = true;
        QString conditionText; // the setting as the drive holds it, when it does not apply
    };
    void paint();
    QVector<Lamp> m_lamps;
    bool m_stale = false;
    QVector<QWidget*> m_cells;
    QGridLayout* m_grid;
    int m_columns = 0;
    std::optional<std::optional<double>> m_shown; // what the lamps show (nothing: not set yet)
};

} // namespace opentop
