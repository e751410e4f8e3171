# The checks of a run's standard error that both command-line test scripts make (RunProxima.cmake,
# RunProximaOutputs.cmake): it matches EXPECT_STDERR when that is given, and bad input (status 2)
# is reported on exactly one line.
function(proxima_check_stderr err)
  if(DEFINED EXPECT_STDERR AND NOT err MATCHES "${EXPECT_STDERR}")
    message(FATAL_ERROR "stderr does not match '${EXPECT_STDERR}':\n${err}")
  endif()
  string(REGEX MATCHALL "\n" newlines "${err}")
  list(LENGTH newlines numLines)
  if(EXPECT_STATUS STREQUAL "2" AND NOT numLines EQUAL 1)
    message(FATAL_ERROR "expected one line on stderr, got ${numLines}:\n${err}")
  endif()
endfunction()
