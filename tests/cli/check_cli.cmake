# Command-line behaviour of `quicksand` (run by ctest as `cmake -P`):
#  1. `quicksand check` accepts every shipped case;
#  2. a case with bad input exits non-zero with a message naming file, line and key;
#  3. a failed run leaves an earlier output/ untouched;
#  4. `check` sizes a run (cells, points, steps, memory, wall time) and refuses, as `run` does,
#     a case whose memory does not fit the machine;
#  5. a case.toml that is a directory is named as such;
#  and: check refuses what run refuses before its first step (a time step beyond the stable one),
#  gravity = 0 quotes K at standard gravity, Ctrl-C checkpoints and exits with 130, a full disk
#  stops a run cleanly.
file(GLOB_RECURSE cases "${SOURCE_DIR}/cases/*/case.toml")
foreach(c IN LISTS cases)
  get_filename_component(dir "${c}" DIRECTORY)
  execute_process(COMMAND "${QUICKSAND}" check "${dir}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "quicksand check ${dir} failed (${rc}):\n${out}\n${err}")
  endif()
endforeach()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}/bad/output")
file(WRITE "${WORK_DIR}/bad/output/series.csv" "earlier results\n")
file(READ "${SOURCE_DIR}/cases/verification/geostatic/case.toml" good)
string(REPLACE "porosity = 0.38" "porosity = 1.38" bad "${good}")
file(WRITE "${WORK_DIR}/bad/case.toml" "${bad}")
foreach(cmd check run)
  execute_process(COMMAND "${QUICKSAND}" ${cmd} "${WORK_DIR}/bad" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc EQUAL 0)
    message(FATAL_ERROR "quicksand ${cmd} accepted porosity 1.38")
  endif()
  if(NOT err MATCHES "case.toml:[0-9]+: key 'materials\\.[a-z_]+\\.porosity'")
    message(FATAL_ERROR "quicksand ${cmd}: the error does not name file, line and key:\n${err}")
  endif()
endforeach()
file(READ "${WORK_DIR}/bad/output/series.csv" kept)
if(NOT kept STREQUAL "earlier results\n")
  message(FATAL_ERROR "a failed run touched the earlier output/")
endif()

# --version: the version and commit, then each build option; a run's first line names the build
execute_process(COMMAND "${QUICKSAND}" --version RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
foreach(expected "^quicksand [0-9]+\\.[0-9]+\\.[0-9]+ \\(commit " "\n  OpenFOAM: " "\n  MPI: +(Open MPI|none)"
                 "\n  OpenMP: " "\n  HDF5: +1\\.")
  if(NOT rc EQUAL 0 OR NOT out MATCHES "${expected}")
    message(FATAL_ERROR "quicksand --version (${rc}) does not say '${expected}':\n${out}\n${err}")
  endif()
endforeach()
file(MAKE_DIRECTORY "${WORK_DIR}/version")
file(WRITE "${WORK_DIR}/version/case.toml" "${good}")
execute_process(COMMAND "${QUICKSAND}" run "${WORK_DIR}/version" --set time.end=0.001 --set output.fields=false
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "^quicksand [0-9]+\\.[0-9]+\\.[0-9]+ \\(commit [^;]+; [^)]*HDF5 1\\.[0-9.]+\\)\n")
  message(FATAL_ERROR "a run's first line does not name the build (${rc}):\n${out}\n${err}")
endif()

# 4. sizing
execute_process(COMMAND "${QUICKSAND}" check "${SOURCE_DIR}/cases/deltaresColumnLumped" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
foreach(expected "size: [0-9]+ cells, [0-9]+ nodes, [0-9]+ solid \\+ [0-9]+ liquid points" "[0-9]+ steps"
                 "estimated peak memory [0-9.]+ [KMG]iB of the machine's" "estimated wall time [0-9.]+ (s|min|h)")
  if(NOT out MATCHES "${expected}")
    message(FATAL_ERROR "quicksand check does not size the run ('${expected}'):\n${out}")
  endif()
endforeach()
file(MAKE_DIRECTORY "${WORK_DIR}/huge/output")
file(WRITE "${WORK_DIR}/huge/output/series.csv" "earlier results\n")
string(REPLACE "cell_size = 0.0093" "cell_size = 1e-8" huge "${good}")
file(WRITE "${WORK_DIR}/huge/case.toml" "${huge}")
foreach(cmd check run)
  execute_process(COMMAND "${QUICKSAND}" ${cmd} "${WORK_DIR}/huge" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc EQUAL 0 OR NOT err MATCHES "does not fit this machine's memory: it needs about [0-9.]+ [GT]iB \\([0-9]+ cells"
     OR NOT err MATCHES "grid.cell_size")
    message(FATAL_ERROR "quicksand ${cmd} did not refuse a case too big for the machine (${rc}):\n${out}\n${err}")
  endif()
endforeach()
file(READ "${WORK_DIR}/huge/output/series.csv" kept)
if(NOT kept STREQUAL "earlier results\n")
  message(FATAL_ERROR "a refused run touched the earlier output/")
endif()

# 4b. a time step beyond the stable one: check refuses it as run does
file(MAKE_DIRECTORY "${WORK_DIR}/fastdt")
string(REPLACE "[time]" "[time]\ndt = 1.0e-3" fastdt "${good}")
file(WRITE "${WORK_DIR}/fastdt/case.toml" "${fastdt}")
foreach(cmd check run)
  execute_process(COMMAND "${QUICKSAND}" ${cmd} "${WORK_DIR}/fastdt" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc EQUAL 0 OR NOT err MATCHES "case.toml: key 'time.dt': 0.001 s exceeds the stable step")
    message(FATAL_ERROR "quicksand ${cmd} did not refuse a time step beyond the stable one (${rc}):\n${out}\n${err}")
  endif()
endforeach()

# 4c. without gravity the conductivity is quoted at standard gravity, saying so
file(MAKE_DIRECTORY "${WORK_DIR}/weightless")
string(REGEX REPLACE "gravity = [0-9.]+" "gravity = 0" weightless "${good}")
file(WRITE "${WORK_DIR}/weightless/case.toml" "${weightless}")
execute_process(COMMAND "${QUICKSAND}" check "${WORK_DIR}/weightless" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT out MATCHES "hydraulic conductivity K +[0-9.]*[1-9][0-9.e-]* m/s \\(at g = 9.81 m/s2")
  message(FATAL_ERROR "check with gravity = 0 does not quote K at standard gravity (${rc}):\n${out}\n${err}")
endif()

# 4d. Ctrl-C: the run checkpoints, says how to resume, exits with 130, and resumes to the end
file(MAKE_DIRECTORY "${WORK_DIR}/interrupted")
file(READ "${SOURCE_DIR}/cases/verification/falling_head/case.toml" longer)
file(WRITE "${WORK_DIR}/interrupted/case.toml" "${longer}")
execute_process(COMMAND timeout --preserve-status -s INT 1.5 "${QUICKSAND}" run "${WORK_DIR}/interrupted"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 130 OR NOT err MATCHES "interrupted by SIGINT at t = [0-9.]+ s .*checkpoint written to .*--resume"
   OR NOT EXISTS "${WORK_DIR}/interrupted/output/checkpoint.h5")
  message(FATAL_ERROR "Ctrl-C did not end the run with a checkpoint and exit code 130 (${rc}):\n${out}\n${err}")
endif()
execute_process(COMMAND "${QUICKSAND}" run "${WORK_DIR}/interrupted" --resume --quiet
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the interrupted run did not resume (${rc}):\n${out}\n${err}")
endif()
# the resumed run keeps the field steps from before the interruption: one per series line
file(STRINGS "${WORK_DIR}/interrupted/output/series.csv" rows)
list(LENGTH rows row_count)
file(READ "${WORK_DIR}/interrupted/output/fields.xdmf" xdmf)
string(REGEX MATCHALL "<Time Value=\"[^\"]*\"" times "${xdmf}")
list(LENGTH times time_count)
set(first_time "none")
if(time_count GREATER 0)
  list(GET times 0 first_time)
endif()
math(EXPR output_count "${row_count} - 1")
if(NOT time_count EQUAL output_count OR NOT first_time STREQUAL "<Time Value=\"0\"")
  message(FATAL_ERROR "the resumed run's fields.xdmf has ${time_count} steps from ${first_time}, "
                      "series.csv ${output_count} outputs")
endif()

# 4e. a disk that fills up: the run stops with the system's reason, series.csv keeps only
# complete lines, no temporary file is left behind. Needs a small tmpfs (root); skipped,
# saying why, where mounting is not allowed.
set(full "${WORK_DIR}/diskfull")
file(MAKE_DIRECTORY "${full}/case" "${full}/mount")
execute_process(COMMAND mount -t tmpfs -o size=200k tmpfs "${full}/mount" RESULT_VARIABLE mounted ERROR_VARIABLE why)
if(mounted EQUAL 0)
  string(REPLACE "end = 0.5" "end = 2.0" filling "${good}")
  file(WRITE "${full}/case/case.toml" "${filling}\n[output]\ndirectory = \"${full}/mount/out\"\n")
  execute_process(COMMAND "${QUICKSAND}" run "${full}/case" --quiet RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  file(GLOB leftovers "${full}/mount/out/*.tmp")
  file(STRINGS "${full}/mount/out/series.csv" rows)
  execute_process(COMMAND umount "${full}/mount")
  if(rc EQUAL 0 OR NOT err MATCHES "No space left on device" OR leftovers)
    message(FATAL_ERROR "a full disk did not stop the run cleanly (${rc}, leftovers: ${leftovers}):\n${err}")
  endif()
  list(GET rows 0 header)
  string(REGEX MATCHALL "," commas "${header}")
  list(LENGTH commas ncols)
  foreach(row IN LISTS rows)
    string(REGEX MATCHALL "," c "${row}")
    list(LENGTH c n)
    if(NOT n EQUAL ncols)
      message(FATAL_ERROR "series.csv on a full disk holds a half-written line: ${row}")
    endif()
  endforeach()
else()
  message(STATUS "SKIPPED the disk-full check: cannot mount a tmpfs here (${why})")
endif()

# 5. case.toml that is a directory
file(MAKE_DIRECTORY "${WORK_DIR}/dircase/case.toml")
execute_process(COMMAND "${QUICKSAND}" check "${WORK_DIR}/dircase" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0 OR NOT err MATCHES "case.toml: is a directory, not a file")
  message(FATAL_ERROR "a case.toml directory is not named as such (${rc}):\n${err}")
endif()
message(STATUS "cli checks passed (${cases})")
