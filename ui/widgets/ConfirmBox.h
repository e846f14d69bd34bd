#pragma once

#include <QString>
#include <functional>

class QMessageBox;
class QWidget;

namespace opentop {

// An application-modal warning that asks before something moves a motor or changes how a drive
// is controlled, without blocking: `then` runs only when the user picks `yes`. Cancel is the
// default. Tests answer it through QApplication::activeModalWidget().
class ConfirmBox
{
public:
    static QMessageBox* ask(QWidget* parent, const QString& title, const QString& text,
                            const QString& yes, const std::function<void()>& then);
};

} // namespace opentop
