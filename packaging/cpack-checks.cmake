# Read by cpack before it makes the package (CPACK_PROJECT_CONFIG_FILE). CPack's DEB generator
# needs "file" to find the executables and dpkg-shlibdeps for their library dependencies;
# without dpkg-shlibdeps it would silently make a package without them.
foreach(tool file dpkg-shlibdeps)
    find_program(OPENTOP_CPACK_TOOL_${tool} ${tool})
    if(NOT OPENTOP_CPACK_TOOL_${tool})
        message(FATAL_ERROR "The Debian package needs the program '${tool}': "
                            "apt-get install file dpkg-dev")
    endif()
endforeach()
