#pragma once

#include <QVector>

class QMenu;

namespace opentop {

class BusDrives;

// The bus list's Variant submenu: the variants of the first selected drive's family, for every
// selected drive of that family that answered. Nothing is added for a family with one variant.
class VariantMenu
{
public:
    static void add(QMenu* menu, BusDrives* drives, const QVector<int>& slaves);
};

} // namespace opentop
