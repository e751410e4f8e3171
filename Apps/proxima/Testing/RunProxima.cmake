# Runs `proxima` once and checks its exit status and output, for the command-line tests:
#   cmake -DPROGRAM=... -DARGS="a|b|c" -DEXPECT_STATUS=2 [-DEXPECT_STDOUT=regex]
#         [-DEXPECT_STDERR=regex] [-DEXPECT_NO_FILE=path] -P RunProxima.cmake
# EXPECT_NO_FILE: removed before the run, and it must not exist after it.
string(REPLACE "|" ";" ARGS "${ARGS}")
if(DEFINED EXPECT_NO_FILE)
  file(REMOVE "${EXPECT_NO_FILE}")
endif()
execute_process(COMMAND "${PROGRAM}" ${ARGS}
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status STREQUAL "${EXPECT_STATUS}")
  message(FATAL_ERROR "exit status ${status}, expected ${EXPECT_STATUS}\nstdout:\n${out}\nstderr:\n${err}")
endif()
if(DEFINED EXPECT_STDOUT AND NOT out MATCHES "${EXPECT_STDOUT}")
  message(FATAL_ERROR "stdout does not match '${EXPECT_STDOUT}':\n${out}")
endif()
include("${CMAKE_CURRENT_LIST_DIR}/CheckStderr.cmake")
proxima_check_stderr("${err}")
if(EXPECT_STATUS STREQUAL "0" AND NOT err STREQUAL "")
  message(FATAL_ERROR "printed on stderr although it succeeded:\n${err}")
endif()
if(DEFINED EXPECT_NO_FILE AND EXISTS "${EXPECT_NO_FILE}")
  message(FATAL_ERROR "left ${EXPECT_NO_FILE} behind")
endif()
message(STATUS "ok: status ${status}")
