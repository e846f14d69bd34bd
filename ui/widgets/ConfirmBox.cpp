#include "ui/widgets/ConfirmBox.h"

#include <QAbstractButton>
#include <QMessageBox>

namespace opentop {

QMessageBox* ConfirmBox::ask(QWidget* parent, const QString& title, const QString& text,
                             const QString& yes, const std::function<void()>& then)
{
    auto* box = new QMessageBox(QMessageBox::Warning, title, text,
                                QMessageBox::Yes | QMessageBox::Cancel, parent);
    box->setTextFormat(Qt::PlainText); // it names drives, as they are named
    box->button(QMessageBox::Yes)->setText(yes);
    box->setDefaultButton(QMessageBox::Cancel);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setWindowModality(Qt::ApplicationModal);
    QObject::connect(box, &QMessageBox::buttonClicked, parent,
                     [box, then](QAbstractButton* button) {
                         if (box->standardButton(button) == QMessageBox::Yes)
                             then();
                     });
    box->show();
    return box;
}

} // namespace opentop
