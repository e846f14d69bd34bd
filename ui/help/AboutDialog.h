#pragma once

#include <QDialog>

class QLabel;

namespace opentop {

// Help ▸ About: the program's version and licence, and the libraries it is built on with their
// versions and licences.
class AboutDialog : public QDialog
{
    Q_OBJECT
public:
    explicit AboutDialog(QWidget* parent = nullptr);

    // The text shown (plain, for tests).
    QString text() const;

private:
    QLabel* m_text;
};

} // namespace opentop
