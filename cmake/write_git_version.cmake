# Writes OUTPUT, a header defining RECOIL_GIT as `git describe` of SOURCE_DIR,
# at every build, but touches it only when the text changes, so that a build
# of an unchanged commit recompiles nothing.
execute_process(COMMAND git describe --always --dirty
                WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE git OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT git)
  set(git "unknown")
endif()
set(text "#pragma once\n// Written by cmake/write_git_version.cmake at build time.\n#define RECOIL_GIT \"${git}\"\n")
set(old "")
if(EXISTS ${OUTPUT})
  file(READ ${OUTPUT} old)
endif()
if(NOT old STREQUAL text)
  file(WRITE ${OUTPUT} "${text}")
endif()
