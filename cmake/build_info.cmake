# The one home of the version and the commit: VERSION is the top CMakeLists.txt's project(VERSION),
# the commit is read from git here (at build time, marked "-dirty" when the work tree differs from
# it; "unknown" outside git). Writes build_info.hpp (OUTPUT, for the C++ library and the CLI's
# --version) and/or the Python package's _version.py (PYTHON_OUTPUT, whose __version__ is the
# PEP 440 form 0.1.0+<commit>); rewrites a file only when its content changes, so an unchanged
# commit triggers no rebuild. setup.py runs this script too, for the wheel's version.
execute_process(COMMAND git rev-parse --short=12 HEAD WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE result)
if(NOT result EQUAL 0 OR commit STREQUAL "")
  set(commit "unknown")
else()
  execute_process(COMMAND git diff --quiet HEAD -- WORKING_DIRECTORY ${SOURCE_DIR} RESULT_VARIABLE dirty ERROR_QUIET)
  if(NOT dirty EQUAL 0)
    set(commit "${commit}-dirty")
  endif()
endif()

function(write_if_changed file content)
  if(EXISTS ${file})
    file(READ ${file} old)
  endif()
  if(NOT "${old}" STREQUAL "${content}")
    file(WRITE ${file} "${content}")
  endif()
endfunction()

if(OUTPUT)
  write_if_changed(${OUTPUT} "#pragma once
// Generated at build time by cmake/build_info.cmake: version and commit written into every output header.
namespace coldblast::common {
inline constexpr const char* version = \"${VERSION}\";
inline constexpr const char* git_commit = \"${commit}\";
}  // namespace coldblast::common
")
endif()
if(PYTHON_OUTPUT)
  # A PEP 440 local version label holds letters, digits and dots: a21aaf8c1234-dirty -> a21aaf8c1234.dirty.
  string(REPLACE "-" "." local_label "${commit}")
  write_if_changed(${PYTHON_OUTPUT} "# Generated at build time by cmake/build_info.cmake from project(VERSION) and git.
__commit__ = \"${commit}\"
__version__ = \"${VERSION}+${local_label}\"
")
endif()
