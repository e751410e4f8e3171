# Runs `proxima` once against its outputs' failures (DESIGN.md section 6) and checks that it says
# so and leaves nothing behind, for the reliability tests:
#   cmake -DPROGRAM=... -DARGS="a|@F@/x.csv" -DFOLDER=dir -DEXPECT_STATUS=2 -DEXPECT_STDERR=regex
#         [-DFILE_SIZE_BLOCKS=n] [-DSTDOUT_FILE=/dev/full] [-DLAUNCHER="cmd|args"]
#         [-DSETUP="copy:SOURCE:NAME|link:TARGET:NAME"] [-DEXPECT_FILES="a|b"]
#         [-DUNCHANGED="NAME:SOURCE|..."] -P RunProximaOutputs.cmake
# FOLDER is made afresh and is the working directory; @F@ in ARGS stands for it. SETUP copies a
# file in or makes a symbolic link there before the run. Afterwards the folder must hold exactly
# EXPECT_FILES (nothing when not given: no output and no temporary), and each UNCHANGED file
# must still equal its source. FILE_SIZE_BLOCKS runs the program under `ulimit -f` in sh (blocks
# of 512 bytes in dash, 1024 in bash), which is how a full disk is simulated: the program ignores
# SIGXFSZ, so its writes fail with EFBIG.
file(REMOVE_RECURSE "${FOLDER}")
file(MAKE_DIRECTORY "${FOLDER}")
string(REPLACE "|" ";" SETUP "${SETUP}")
foreach(step IN LISTS SETUP)
  string(REPLACE ":" ";" parts "${step}")
  list(GET parts 0 kind)
  list(GET parts 1 source)
  list(GET parts 2 name)
  if(kind STREQUAL "copy")
    configure_file("${source}" "${FOLDER}/${name}" COPYONLY)
  elseif(kind STREQUAL "link")
    file(CREATE_LINK "${source}" "${FOLDER}/${name}" SYMBOLIC)
  else()
    message(FATAL_ERROR "unknown SETUP step '${step}'")
  endif()
endforeach()

string(REPLACE "@F@" "${FOLDER}" ARGS "${ARGS}")
string(REPLACE "|" ";" ARGS "${ARGS}")
string(REPLACE "|" ";" LAUNCHER "${LAUNCHER}")
set(command "${PROGRAM}" ${ARGS})
if(DEFINED FILE_SIZE_BLOCKS)
  set(command sh -c "ulimit -f ${FILE_SIZE_BLOCKS} && exec \"$0\" \"$@\"" ${command})
endif()
set(redirect)
if(DEFINED STDOUT_FILE)
  set(redirect OUTPUT_FILE "${STDOUT_FILE}")
else()
  set(redirect OUTPUT_VARIABLE out)
endif()
execute_process(COMMAND ${LAUNCHER} ${command} WORKING_DIRECTORY "${FOLDER}"
  RESULT_VARIABLE status ${redirect} ERROR_VARIABLE err)
if(NOT status STREQUAL "${EXPECT_STATUS}")
  message(FATAL_ERROR "exit status ${status}, expected ${EXPECT_STATUS}\nstderr:\n${err}")
endif()
include("${CMAKE_CURRENT_LIST_DIR}/CheckStderr.cmake")
proxima_check_stderr("${err}")

# Hidden files too: a temporary left behind is named .<name>.XXXXXX.
file(GLOB left RELATIVE "${FOLDER}" LIST_DIRECTORIES true "${FOLDER}/*" "${FOLDER}/.*")
list(SORT left)
string(REPLACE "|" ";" EXPECT_FILES "${EXPECT_FILES}")
list(SORT EXPECT_FILES)
if(NOT "${left}" STREQUAL "${EXPECT_FILES}")
  message(FATAL_ERROR "the folder holds '${left}', expected '${EXPECT_FILES}'")
endif()
string(REPLACE "|" ";" UNCHANGED "${UNCHANGED}")
foreach(pair IN LISTS UNCHANGED)
  string(REPLACE ":" ";" parts "${pair}")
  list(GET parts 0 name)
  list(GET parts 1 source)
  file(SHA256 "${FOLDER}/${name}" now)
  file(SHA256 "${source}" before)
  if(NOT now STREQUAL before)
    message(FATAL_ERROR "${name} was changed by the run")
  endif()
endforeach()
message(STATUS "ok: status ${status}, folder holds '${left}'")
