#pragma once

#include <QMessageBox>
#include <QString>

namespace opentop {

// Text OpenTOP did not write (serials, names, recipe texts, drive models, database texts) shown as
// it is written. QLabel, QMessageBox and tool tips guess rich text (Qt::AutoText): a serial
// "<b>SN</b>" or a product "<font size=40>PASS</font>" would otherwise be drawn as HTML (issue 28).
// A label takes setTextFormat(Qt::PlainText); what has no such setting takes asWritten().
class PlainText
{
public:
    // For what guesses rich text and cannot be told "plain" (a tool tip, a message box's
    // informative text, a dialog's label): `text` itself when Qt shows it as written anyway, else
    // rich text that reads exactly as `text`, its spaces and line breaks kept.
    static QString asWritten(const QString& text);

    // QMessageBox's static functions, the text shown as written.
    static QMessageBox::StandardButton
    information(QWidget* parent, const QString& title, const QString& text,
                QMessageBox::StandardButtons buttons = QMessageBox::Ok,
                QMessageBox::StandardButton defaultButton = QMessageBox::NoButton);
    static QMessageBox::StandardButton
    warning(QWidget* parent, const QString& title, const QString& text,
            QMessageBox::StandardButtons buttons = QMessageBox::Ok,
            QMessageBox::StandardButton defaultButton = QMessageBox::NoButton);
    static QMessageBox::StandardButton
    critical(QWidget* parent, const QString& title, const QString& text,
             QMessageBox::StandardButtons buttons = QMessageBox::Ok,
             QMessageBox::StandardButton defaultButton = QMessageBox::NoButton);
    static QMessageBox::StandardButton
    question(QWidget* parent, const QString& title, const QString& text,
             QMessageBox::StandardButtons buttons = QMessageBox::Yes | QMessageBox::No,
             QMessageBox::StandardButton defaultButton = QMessageBox::NoButton);

private:
    static QMessageBox::StandardButton ask(QWidget* parent, QMessageBox::Icon icon,
                                           const QString& title, const QString& text,
                                           QMessageBox::StandardButtons buttons,
                                           QMessageBox::StandardButton defaultButton);
};

} // namespace opentop
