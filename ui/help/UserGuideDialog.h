#pragma once

#include <QDialog>

class QTextBrowser;

namespace opentop {

// Help ▸ User guide: a short guide to commissioning a drive with the program, and where the
// longer documentation is (the manual pages, the installed documentation).
class UserGuideDialog : public QDialog
{
    Q_OBJECT
public:
    explicit UserGuideDialog(QWidget* parent = nullptr);

    QTextBrowser* browser() const { return m_browser; }
    // Where the package installs its documentation (empty when it is not installed).
    static QString installedDocumentation();

private:
    QTextBrowser* m_browser;
};

} // namespace opentop
