# Platform pairs: the few classes that talk to the operating system keep what they share in
# Foo.cpp, their POSIX side in Foo_posix.cpp and their Windows side in Foo_win.cpp; a
# Windows-only class is Bar_win.h + Bar_win.cpp. Files with no Windows side at all (the pty
# simulator, the ioctls) are named in POSIX_ONLY. On Linux every *_win.* file is left out, so
# its build is the one it always was.
#   opentop_platform_sources(OPENTOP_SIM_SOURCES POSIX_ONLY PtySimServer.cpp)
function(opentop_platform_sources var)
    cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "POSIX_ONLY")
    set(files ${${var}})
    if(WIN32)
        list(FILTER files EXCLUDE REGEX "_posix\\.(cpp|h)$")
        foreach(file IN LISTS arg_POSIX_ONLY)
            list(REMOVE_ITEM files "${CMAKE_CURRENT_SOURCE_DIR}/${file}")
        endforeach()
    else()
        list(FILTER files EXCLUDE REGEX "_win\\.(cpp|h)$")
    endif()
    set(${var} ${files} PARENT_SCOPE)
endfunction()
