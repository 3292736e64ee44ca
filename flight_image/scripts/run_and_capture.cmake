# Runs COMMAND (arguments separated by '|'), writes its stdout to OUTPUT, prints it, and fails
# unless it exits 0 within TIMEOUT seconds and its output ends the demo with "EXEC END OK".
#   cmake -DCOMMAND=prog|arg|... -DOUTPUT=file -DTIMEOUT=s -P run_and_capture.cmake
string(REPLACE "|" ";" command "${COMMAND}")
execute_process(COMMAND ${command}
  OUTPUT_FILE "${OUTPUT}" ERROR_VARIABLE errors RESULT_VARIABLE result TIMEOUT ${TIMEOUT})
file(READ "${OUTPUT}" output)
message("${output}")
if(errors)
  message("stderr:\n${errors}")
endif()
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the program exited with '${result}' (expected 0)")
endif()
if(NOT output MATCHES "EXEC END OK\n")
  message(FATAL_ERROR "the output does not end the demo with 'EXEC END OK'")
endif()
