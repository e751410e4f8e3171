# Runs `proxima` once and checks its exit status and output, for the command-line tests:
#   cmake -DPROGRAM=... -DARGS="a|b|c" -DEXPECT_STATUS=2 [-DEXPECT_STDOUT=regex]
#         [-DEXPECT_STDERR=regex] -P RunProxima.cmake
string(REPLACE "|" ";" ARGS "${ARGS}")
execute_process(COMMAND "${PROGRAM}" ${ARGS}
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status STREQUAL "${EXPECT_STATUS}")
  message(FATAL_ERROR "exit status ${status}, expected ${EXPECT_STATUS}\nstdout:\n${out}\nstderr:\n${err}")
endif()
if(DEFINED EXPECT_STDOUT AND NOT out MATCHES "${EXPECT_STDOUT}")
  message(FATAL_ERROR "stdout does not match '${EXPECT_STDOUT}':\n${out}")
endif()
if(DEFINED EXPECT_STDERR AND NOT err MATCHES "${EXPECT_STDERR}")
  message(FATAL_ERROR "stderr does not match '${EXPECT_STDERR}':\n${err}")
endif()
if(EXPECT_STATUS STREQUAL "0" AND NOT err STREQUAL "")
  message(FATAL_ERROR "printed on stderr although it succeeded:\n${err}")
endif()
# Bad input is reported on exactly one line.
string(REGEX MATCHALL "\n" newlines "${err}")
list(LENGTH newlines numLines)
if(EXPECT_STATUS STREQUAL "2" AND NOT numLines EQUAL 1)
  message(FATAL_ERROR "expected one line on stderr, got ${numLines}:\n${err}")
endif()
message(STATUS "ok: status ${status}")
