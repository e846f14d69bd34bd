#pragma once

#include <QJsonObject>
#include <QPointer>
#include <QProgressDialog>
#include <QPushButton>
#include <functional>

namespace opentop {

class BusDrives;
class Recipe;
class GoldenMeasure;

// The recipe editor's "Measure limits…": the golden unit on the bus runs the edited recipe's
// steps once and its hold limits are tightened around what it measured (GoldenMeasure, the
// same as `eol recipe create --measure`). Every drive and what it will do is named first and
// the question defaults to No; Cancel, Esc and a lost link stop every motor.
class GoldenMeasureButton : public QPushButton
{
    Q_OBJECT
public:
    GoldenMeasureButton(std::function<BusDrives*()> drives, std::function<QJsonObject()> document,
                        std::function<void(const QJsonObject&)> apply, QWidget* parent);
    bool isRunning() const { return !m_run.isNull(); }

signals:
    // The run is over: `changes` lines when the limits were applied, else `error`.
    void finished(const QStringList& changes, const QString& error);

private:
    void measure(); // checks and asks
    void run(const Recipe& recipe);

    std::function<BusDrives*()> m_drives;
    std::function<QJsonObject()> m_document;
    std::function<void(const QJsonObject&)> m_apply;
    QPointer<GoldenMeasure> m_run;
    QPointer<QProgressDialog> m_progress;
};

} // namespace opentop
