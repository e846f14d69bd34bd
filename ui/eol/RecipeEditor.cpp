#include "ui/eol/RecipeEditor.h"

#include "model/eol/Recipe.h"
#include "model/eol/RecipeFile.h"
#include "model/profile/ProfileRegistry.h"
#include "ui/eol/GoldenRecipeSource.h"
#include "ui/eol/RecipePositionForm.h"
#include "ui/widgets/ClearOfStopAll.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QJsonArray>
#include <QJsonDocument>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QRegularExpression>
#include <QSplitter>
#include <QTimer>
#include <QVBoxLayout>

namespace opentop {

namespace {

const QString kPositions = QStringLiteral("positions");

} // namespace

RecipeEditor::RecipeEditor(std::function<BusDrives*()> drives, QWidget* parent)
    : QDialog(parent)
    , m_golden(new GoldenRecipeSource(std::move(drives), this))
{
    setWindowTitle(tr("Recipe editor"));
    setObjectName(QStringLiteral("recipeEditor"));
    m_product = new QLineEdit(this);
    m_revision = new QLineEdit(this);
    m_revision->setMaximumWidth(120);
    m_description = new QLineEdit(this);
    m_positions = new QComboBox(this);
    m_form = new RecipePositionForm(this);
    m_problems = new QListWidget(this);
    m_problems->setWordWrap(true);
    m_verdict = new QLabel(this);
    m_message = new QLabel(this);
    m_message->setWordWrap(true);
    m_message->setTextFormat(Qt::PlainText); // paths, errors quoting the recipe
    m_checkTimer = new QTimer(this);
    m_checkTimer->setSingleShot(true);
    m_checkTimer->setInterval(300);

    auto* header = new QFormLayout;
    auto* productRow = new QHBoxLayout;
    productRow->addWidget(m_product, 1);
    productRow->addWidget(new QLabel(tr("Revision:"), this));
    productRow->addWidget(m_revision);
    header->addRow(tr("Product:"), productRow);
    header->addRow(tr("Description:"), m_description);
    header->addRow(tr("Position:"), m_positions);

    auto* problemsBox = new QWidget(this);
    auto* problemsLayout = new QVBoxLayout(problemsBox);
    problemsLayout->setContentsMargins(0, 0, 0, 0);
    problemsLayout->addWidget(m_verdict);
    problemsLayout->addWidget(m_problems, 1);
    auto* split = new QSplitter(Qt::Vertical, this);
    split->addWidget(m_form);
    split->addWidget(problemsBox);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 1);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(makeToolbar());
    layout->addWidget(m_message);
    layout->addLayout(header);
    layout->addWidget(split, 1);
    layout->addWidget(buttons);

    connect(m_positions, &QComboBox::activated, this, &RecipeEditor::showPosition);
    connect(m_form, &RecipePositionForm::changed, this, &RecipeEditor::scheduleCheck);
    for (QLineEdit* e : {m_product, m_revision, m_description})
        connect(e, &QLineEdit::textEdited, this, &RecipeEditor::scheduleCheck);
    connect(m_checkTimer, &QTimer::timeout, this, [this] { check(); });
    connect(m_golden, &GoldenRecipeSource::made, this, [this](const QJsonObject& document) {
        m_path.clear(); // a new recipe: Save asks where
        setDocument(document);
    });
    connect(m_golden, &GoldenRecipeSource::said, this, &RecipeEditor::say);
    connect(m_problems, &QListWidget::itemActivated, this,
            [this](QListWidgetItem* item) { showProblem(item->data(Qt::UserRole).toString()); });
    resize(1000, 720);
    ClearOfStopAll::keep(this);
    setDocument({});
}

QWidget* RecipeEditor::makeToolbar()
{
    auto* bar = new QWidget(this);
    auto* fromDrives = new QPushButton(tr("New from drives on the bus…"), bar);
    auto* fromBackup = new QPushButton(tr("New from backup file…"), bar);
    auto* open = new QPushButton(tr("Open…"), bar);
    m_save = new QPushButton(tr("Save"), bar);
    auto* saveAs = new QPushButton(tr("Save as…"), bar);
    m_bar = new QHBoxLayout(bar);
    m_bar->setContentsMargins(0, 0, 0, 0);
    for (QPushButton* b : {fromDrives, fromBackup, open, m_save, saveAs})
        m_bar->addWidget(b);
    m_bar->addStretch(1);
    connect(fromDrives, &QPushButton::clicked, this,
            [this] { m_golden->chooseDrives(m_product->text()); });
    connect(fromBackup, &QPushButton::clicked, this,
            [this] { m_golden->chooseBackup(m_product->text()); });
    connect(open, &QPushButton::clicked, this, &RecipeEditor::chooseOpen);
    connect(m_save, &QPushButton::clicked, this, [this] { chooseSave(false); });
    connect(saveAs, &QPushButton::clicked, this, [this] { chooseSave(true); });
    return bar;
}

void RecipeEditor::addToolbarButton(QPushButton* button)
{
    m_bar->insertWidget(m_bar->count() - 1, button); // before the stretch
}

void RecipeEditor::setDocument(const QJsonObject& document)
{
    m_loading = true;
    m_document = document;
    m_document.remove(QStringLiteral("checksum"));
    if (!m_document.contains(QStringLiteral("format"))) {
        m_document.insert(QStringLiteral("format"), RecipeFile::formatName());
        m_document.insert(QStringLiteral("formatVersion"), RecipeFile::kFormatVersion);
    }
    m_product->setText(m_document.value(QStringLiteral("product")).toString());
    m_revision->setText(m_document.value(QStringLiteral("revision")).toString());
    m_description->setText(m_document.value(QStringLiteral("description")).toString());
    m_current = -1;
    fillPositionChooser();
    showPosition(0);
    m_loading = false;
    check();
}

void RecipeEditor::fillPositionChooser()
{
    m_positions->clear();
    const QJsonArray positions = m_document.value(kPositions).toArray();
    for (int i = 0; i < positions.size(); ++i) {
        const QJsonObject p = positions.at(i).toObject();
        const QString name = p.value(QStringLiteral("name")).toString();
        m_positions->addItem(
            tr("%1: %2%3")
                .arg(Recipe::positionText(i, p.value(QStringLiteral("machineNumber")).toInt()),
                     p.value(QStringLiteral("family")).toString(),
                     name.isEmpty() ? QString() : tr(" — %1").arg(name)));
    }
    m_positions->setEnabled(!positions.isEmpty());
    m_form->setEnabled(!positions.isEmpty());
}

void RecipeEditor::commitPosition()
{
    QJsonArray positions = m_document.value(kPositions).toArray();
    if (m_current >= 0 && m_current < positions.size()) {
        positions.replace(m_current, m_form->position());
        m_document.insert(kPositions, positions);
    }
}

void RecipeEditor::showPosition(int index)
{
    commitPosition();
    const QJsonArray positions = m_document.value(kPositions).toArray();
    if (index < 0 || index >= positions.size()) {
        m_current = -1;
        m_form->setPosition({});
        return;
    }
    m_current = index;
    m_form->setPosition(positions.at(index).toObject());
    m_positions->setCurrentIndex(index);
}

QJsonObject RecipeEditor::document()
{
    commitPosition();
    m_document.insert(QStringLiteral("product"), m_product->text().trimmed());
    m_document.insert(QStringLiteral("revision"), m_revision->text().trimmed());
    if (m_description->text().trimmed().isEmpty())
        m_document.remove(QStringLiteral("description"));
    else
        m_document.insert(QStringLiteral("description"), m_description->text().trimmed());
    return m_document;
}

void RecipeEditor::showProblem(const QString& path)
{
    // "positions[1].settings[3].value": the position, then the row of its table.
    static const QRegularExpression at(
        QStringLiteral(R"(^positions\[(\d+)\](?:\.(settings|unitValues|steps)\[(\d+)\])?)"));
    const QRegularExpressionMatch m = at.match(path);
    if (!m.hasMatch())
        return;
    showPosition(m.captured(1).toInt());
    if (m.captured(2) == QLatin1String("settings"))
        m_form->showRow(m_form->settingsTable(), m.captured(3).toInt());
    else if (m.captured(2) == QLatin1String("unitValues"))
        m_form->showRow(m_form->unitValuesTable(), m.captured(3).toInt());
    else if (m.captured(2) == QLatin1String("steps"))
        m_form->showStep(m.captured(3).toInt());
}

void RecipeEditor::scheduleCheck()
{
    if (!m_loading)
        m_checkTimer->start();
}

QVector<RecipeProblem> RecipeEditor::check()
{
    m_checkTimer->stop();
    const QJsonObject edited = document();
    m_problems->clear();
    if (edited.value(kPositions).toArray().isEmpty() &&
        edited.value(QStringLiteral("product")).toString().isEmpty()) {
        m_verdict->setText(tr("Make a recipe from a golden unit's drives on the bus or its backup "
                              "file, or open one."));
        m_verdict->setStyleSheet(QString());
        m_save->setEnabled(false);
        return {RecipeProblem{QString(), tr("the recipe is empty")}};
    }
    QVector<RecipeProblem> problems;
    QString error;
    const std::optional<Recipe> recipe = RecipeFile::fromEdited(edited, &error);
    if (!recipe)
        problems << RecipeProblem{QString(), error};
    else
        problems << RecipeChecker(ProfileRegistry::builtIn()).check(*recipe);
    for (const RecipeProblem& p : problems) {
        auto* item = new QListWidgetItem(
            p.path.isEmpty() ? p.message : tr("%1 — %2").arg(p.message, p.path), m_problems);
        item->setData(Qt::UserRole, p.path);
    }
    if (problems.isEmpty()) {
        m_verdict->setText(tr("The recipe passes check: it can be saved and run."));
        m_verdict->setStyleSheet(QStringLiteral("color: #1b5e20; font-weight: bold"));
    } else {
        m_verdict->setText(tr("%n problem(s): the recipe cannot be saved until they are fixed.",
                              nullptr, int(problems.size())));
        m_verdict->setStyleSheet(QStringLiteral("color: #b71c1c; font-weight: bold"));
    }
    m_save->setEnabled(problems.isEmpty());
    return problems;
}

bool RecipeEditor::saveTo(const QString& path, QString* error)
{
    const QVector<RecipeProblem> problems = check();
    if (!problems.isEmpty()) {
        *error = tr("the recipe does not pass check (%n problem(s)); nothing was saved", nullptr,
                    int(problems.size()));
        return false;
    }
    const std::optional<Recipe> recipe = RecipeFile::fromEdited(document(), error);
    if (!recipe || !RecipeFile::save(*recipe, path, error))
        return false;
    m_path = path;
    m_save->setEnabled(true);
    return true;
}

bool RecipeEditor::openFile(const QString& path, QString* error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = tr("cannot read %1: %2").arg(path, file.errorString());
        return false;
    }
    const QByteArray bytes = file.read(RecipeFile::kMaxFileBytes + 1);
    QJsonParseError parse;
    const QJsonDocument json = QJsonDocument::fromJson(bytes, &parse);
    if (bytes.size() > RecipeFile::kMaxFileBytes || parse.error != QJsonParseError::NoError ||
        !json.isObject() ||
        json.object().value(QStringLiteral("format")).toString() != RecipeFile::formatName()) {
        // The file reader's own words say what is wrong with it.
        RecipeFile::load(path, error);
        if (error->isEmpty())
            *error = tr("%1 is not an OpenTOP recipe file").arg(path);
        return false;
    }
    QString loadError;
    const bool signedFile = bool(RecipeFile::load(path, &loadError));
    m_path = path;
    setDocument(json.object());
    say(signedFile ? tr("Opened %1").arg(path)
                   : tr("Opened %1, which does not load as it is (%2). Saving checks it and signs "
                        "it again.")
                         .arg(path, loadError),
        !signedFile);
    return true;
}

bool RecipeEditor::newFromBackup(const QString& backupPath, const QString& product,
                                 const QString& revision, QString* error)
{
    return m_golden->fromBackup(backupPath, product, revision, error);
}

void RecipeEditor::newFromDrives(const QVector<int>& ids, const QString& product,
                                 const QString& revision, std::function<void(bool, QString)> done)
{
    m_golden->fromDrives(ids, product, revision, std::move(done));
}

void RecipeEditor::chooseOpen()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Open recipe"), QString(),
                                                      tr("Recipes (*.json);;All files (*)"));
    QString error;
    if (!path.isEmpty() && !openFile(path, &error))
        say(error, true);
}

void RecipeEditor::chooseSave(bool askPath)
{
    QString path = m_path;
    if (askPath || path.isEmpty())
        path = QFileDialog::getSaveFileName(this, tr("Save recipe"),
                                            path.isEmpty() ? QStringLiteral("recipe.json") : path,
                                            tr("Recipes (*.json)"));
    if (path.isEmpty())
        return;
    QString error;
    if (saveTo(path, &error))
        say(tr("Saved and signed: %1").arg(path), false);
    else
        say(error, true);
}

void RecipeEditor::say(const QString& text, bool error)
{
    m_message->setText(text);
    m_message->setStyleSheet(error ? QStringLiteral("color: #b71c1c; font-weight: bold")
                                   : QString());
}

} // namespace opentop
