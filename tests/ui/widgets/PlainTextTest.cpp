// Issue 28 item 5: text OpenTOP did not write reads as it is written where Qt guesses rich text;
// text Qt shows as written anyway is left as it is (tool tips that tests and people read).
#include "ui/widgets/PlainText.h"

#include <QApplication>
#include <QPushButton>
#include <QTextDocument>
#include <QTimer>
#include <gtest/gtest.h>

namespace opentop {

namespace {

// As a tool tip or an informative text draws it, read back as plain text.
QString drawn(const QString& text)
{
    if (!Qt::mightBeRichText(text))
        return text;
    QTextDocument document;
    document.setHtml(text);
    return document.toPlainText();
}

TEST(PlainTextTest, MarkupReadsAsWrittenWithItsSpacesAndLines)
{
    const QString hostile =
        QStringLiteral("<font size=40>PASS</font> & <b>SN-1</b>:  two spaces\n  indented\n\nlast");
    ASSERT_NE(drawn(hostile), hostile) << "Qt would draw it as HTML";
    EXPECT_EQ(drawn(PlainText::asWritten(hostile)), hostile);
    EXPECT_EQ(drawn(PlainText::asWritten(QStringLiteral("Unit <img src=x>"))),
              QStringLiteral("Unit <img src=x>"));
}

TEST(PlainTextTest, TextQtShowsAsWrittenStaysAsItIs)
{
    for (const QString& text : {QStringLiteral("Connection lost: timeout"),
                                QStringLiteral("speed 1500 r/min & load 90 %"), QString(),
                                QStringLiteral("line one\n<b>line two</b>")})
        EXPECT_EQ(PlainText::asWritten(text), text);
}

// Once the next modal message box shows: what it shows, then `button` clicked.
struct Seen
{
    QMessageBox::StandardButtons buttons;
    QMessageBox::StandardButton defaultButton = QMessageBox::NoButton;
    Qt::TextFormat format = Qt::AutoText;
    QString text;
};

void answerNextBox(QMessageBox::StandardButton button, Seen* seen)
{
    auto* timer = new QTimer;
    QObject::connect(timer, &QTimer::timeout, [timer, button, seen] {
        if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
            seen->buttons = box->standardButtons();
            seen->defaultButton = box->standardButton(box->defaultButton());
            seen->format = box->textFormat();
            seen->text = box->text();
            box->button(button)->click();
            timer->deleteLater();
        }
    });
    timer->start(20);
}

} // namespace

TEST(PlainTextTest, AMessageBoxShowsItsTextAsWrittenAndAnswersAsQMessageBoxDoes)
{
    Seen seen;
    const QString question = QStringLiteral("Test unit <b>SN-1</b> again?");
    answerNextBox(QMessageBox::No, &seen);
    EXPECT_EQ(PlainText::question(nullptr, QStringLiteral("Test again"), question),
              QMessageBox::No);
    EXPECT_EQ(seen.buttons, QMessageBox::Yes | QMessageBox::No);
    EXPECT_EQ(seen.format, Qt::PlainText);
    EXPECT_EQ(seen.text, question);

    answerNextBox(QMessageBox::Ok, &seen);
    EXPECT_EQ(PlainText::warning(nullptr, QStringLiteral("Recipe"), QStringLiteral("<i>x</i>"),
                                 QMessageBox::Ok | QMessageBox::Cancel, QMessageBox::Cancel),
              QMessageBox::Ok);
    EXPECT_EQ(seen.buttons, QMessageBox::Ok | QMessageBox::Cancel);
    EXPECT_EQ(seen.defaultButton, QMessageBox::Cancel);
    EXPECT_EQ(seen.format, Qt::PlainText);

    // No default given: the first button that accepts, as QMessageBox::information() has it.
    answerNextBox(QMessageBox::Ok, &seen);
    EXPECT_EQ(PlainText::information(nullptr, QStringLiteral("Recipe"), QStringLiteral("done")),
              QMessageBox::Ok);
    EXPECT_EQ(seen.buttons, QMessageBox::Ok);
    EXPECT_EQ(seen.defaultButton, QMessageBox::Ok);
}

} // namespace opentop
