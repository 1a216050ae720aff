# Runs COMMAND (arguments separated by '|') and checks its exit code CODE,
# that its standard error matches STDERR, its standard output STDOUT (when
# given), and the file FILE the regular expression FILE_REGEX (when given).
string(REPLACE "|" ";" command "${COMMAND}")
execute_process(COMMAND ${command} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code STREQUAL CODE)
  message(FATAL_ERROR "exit code ${code}, expected ${CODE}\nstdout: ${out}\nstderr: ${err}")
endif()
if(NOT err MATCHES "${STDERR}")
  message(FATAL_ERROR "stderr does not match '${STDERR}':\n${err}")
endif()
if(DEFINED STDOUT AND NOT out MATCHES "${STDOUT}")
  message(FATAL_ERROR "stdout does not match '${STDOUT}':\n${out}")
endif()
if(DEFINED FILE)
  # the header of a binary PLY is text; 2000 bytes hold it
  file(READ "${FILE}" content LIMIT 2000)
  string(REGEX REPLACE "[^\n -~]" "?" content "${content}")
  if(NOT content MATCHES "${FILE_REGEX}")
    message(FATAL_ERROR "${FILE} does not match '${FILE_REGEX}':\n${content}")
  endif()
endif()
