#include "ui/bus/VariantQuestion.h"

#include "model/bus/BusDrives.h"
#include "model/session/DeviceSession.h"

#include <QCoreApplication>
#include <QHash>
#include <QMessageBox>
#include <QPushButton>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::VariantQuestion", text);
}

} // namespace

bool VariantQuestion::ensure(QWidget* parent, BusDrives* drives, int slave,
                             VariantNeed::Purpose purpose, const QStringList& parameters)
{
    if (!drives || !VariantNeed::needed(*drives, slave, purpose, parameters))
        return true;
    const Profile& profile = drives->session(slave)->profile();
    QMessageBox box(
        QMessageBox::Question, tr("Which drive is it?"),
        VariantNeed::question(*drives, slave, purpose, drives->rememberedVariant(slave)),
        QMessageBox::NoButton, parent);
    box.setObjectName(QStringLiteral("variantQuestion"));
    box.setTextFormat(Qt::PlainText); // names the drive
    QHash<QAbstractButton*, QString> variants;
    for (const ProfileVariant& v : profile.variants) {
        QPushButton* b = box.addButton(v.model, QMessageBox::AcceptRole);
        b->setObjectName(QStringLiteral("variant_") + v.id);
        b->setToolTip(v.label);
        variants.insert(b, v.id);
    }
    QPushButton* unknown =
        box.addButton(tr("Not known: check against every variant"), QMessageBox::AcceptRole);
    unknown->setObjectName(QStringLiteral("variantUnknown"));
    QPushButton* cancel = box.addButton(QMessageBox::Cancel);
    // Nothing is assumed on Enter: a wrong variant would allow wrong speeds.
    box.setDefaultButton(cancel);
    box.exec();
    QAbstractButton* clicked = box.clickedButton();
    if (variants.contains(clicked)) {
        drives->setVariant(slave, variants.value(clicked));
        return true;
    }
    if (clicked == unknown) {
        drives->declineVariant(slave);
        return true;
    }
    return false;
}

QString VariantQuestion::ensureEach(QWidget* parent, BusDrives* drives, const QVector<int>& slaves,
                                    VariantNeed::Purpose purpose, const QStringList& parameters)
{
    for (int slave : slaves) {
        if (!ensure(parent, drives, slave, purpose, parameters))
            return tr("the variant of %1 was not given").arg(drives->label(slave));
    }
    return QString();
}

bool VariantQuestion::ensure(QWidget* parent, const DeviceSession* session,
                             VariantNeed::Purpose purpose, const QStringList& parameters)
{
    BusDrives* drives = BusDrives::of(session);
    return !drives || ensure(parent, drives, session->slave(), purpose, parameters);
}

} // namespace opentop
