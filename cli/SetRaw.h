#pragma once

#include <QStringList>

namespace opentop {

class CliContext;

// `set ID --raw ADDR=VALUE...` (service work): registers by address, function 6 or 16
// (`--fc`). What the profile names at an address is still checked (its allowed values, and
// commands need --yes), on the drive and on the children of its communication group, before
// anything is sent; each write is read back, and so are the children.
class SetRaw
{
public:
    static int run(CliContext& context, int slave, const QStringList& assignments);
};

} // namespace opentop
