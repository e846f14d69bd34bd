#include "ui/help/AboutDialog.h"

#include "transport/LibraryVersions.h"

#include <QApplication>
#include <QDialogButtonBox>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QTextDocument>
#include <QVBoxLayout>

namespace opentop {

AboutDialog::AboutDialog(QWidget* parent)
    : QDialog(parent)
    , m_text(new QLabel(this))
{
    setObjectName(QStringLiteral("aboutDialog"));
    setWindowTitle(tr("About OpenTOP"));
    const QString html =
        tr("<h2>OpenTOP %1</h2>"
           "<p>Commissioning tool for RS-485 Modbus-RTU motor drives: TROY DBU brushless drives "
           "and a DC motor PID controller.</p>"
           "<p>Copyright © the OpenTOP developers.<br>"
           "Licence: GNU General Public License, version 3 or any later version "
           "(GPL-3.0-or-later). This program comes with ABSOLUTELY NO WARRANTY; it is free "
           "software, and you are welcome to redistribute it under the terms of that licence.</p>"
           "<p><b>Built with</b></p>"
           "<ul>"
           "<li>Qt %2 (run time; built with %3): GNU Lesser General Public License, version 3 "
           "(LGPL-3.0-only); Qt Charts: GNU General Public License, version 3 (GPL-3.0-only)</li>"
           "<li>libmodbus %4: GNU Lesser General Public License, version 2.1 or later "
           "(LGPL-2.1-or-later)</li>"
           "<li>GoogleTest (tests only): BSD 3-Clause licence</li>"
           "</ul>")
            .arg(QStringLiteral(OPENTOP_VERSION), QString::fromLatin1(qVersion()),
                 QStringLiteral(QT_VERSION_STR), LibraryVersions::libmodbus());
    m_text->setObjectName(QStringLiteral("aboutText"));
    m_text->setText(html);
    m_text->setWordWrap(true);
    m_text->setTextInteractionFlags(Qt::TextBrowserInteraction);
    m_text->setOpenExternalLinks(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    QPushButton* aboutQt = buttons->addButton(tr("About &Qt"), QDialogButtonBox::HelpRole);
    connect(aboutQt, &QPushButton::clicked, this, [this] { QMessageBox::aboutQt(this); });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_text);
    layout->addWidget(buttons);
    // Wide enough for the licence lines to read as paragraphs, narrow enough for any laptop.
    m_text->setMinimumWidth(420);
    resize(560, sizeHint().height());
}

QString AboutDialog::text() const
{
    QTextDocument document;
    document.setHtml(m_text->text());
    return document.toPlainText();
}

} // namespace opentop
