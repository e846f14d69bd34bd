# Run by cpack on the staged files before it makes the package (CPACK_PRE_BUILD_SCRIPTS).
# CPACK_STRIP_FILES strips symbols like `install -s`, which keeps the .comment and .note
# sections; dh_strip removes them too, and lintian notes them otherwise.
find_program(OPENTOP_STRIP strip REQUIRED)
file(GLOB_RECURSE staged_programs "${CPACK_TEMPORARY_INSTALL_DIRECTORY}/*/usr/bin/*")
foreach(program IN LISTS staged_programs)
    execute_process(COMMAND ${OPENTOP_STRIP} --remove-section=.comment --remove-section=.note
                            "${program}" RESULT_VARIABLE failed)
    if(failed)
        message(FATAL_ERROR "strip failed on ${program}")
    endif()
endforeach()
