#include "CodeTable.h"

namespace opentop {

const CodeEntry* CodeTable::find(qint64 code) const
{
    for (const CodeEntry& e : entries) {
        if (e.code == code)
            return &e;
    }
    return nullptr;
}

} // namespace opentop
