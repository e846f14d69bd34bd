#pragma once

#include <QString>

namespace opentop {

// The versions of the libraries the transport is built on, as the About box shows them.
struct LibraryVersions
{
    // libmodbus as loaded at run time ("3.1.6").
    static QString libmodbus();
};

} // namespace opentop
