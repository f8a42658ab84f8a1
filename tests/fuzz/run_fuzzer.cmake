# Runs one libFuzzer target for SECONDS from a fresh seed corpus, then fails if it found anything.
#   cmake -DFUZZER=... -DFUZZ_TARGET=fuzz_case_loader|fuzz_checkpoint|fuzz_checkpoint_state -DQUICKSAND=... -DSOURCE_DIR=...
#         -DWORK_DIR=... -DSECONDS=60 -P run_fuzzer.cmake
# A crash input is left in WORK_DIR/findings/ with the fuzzer's log; once fixed, copy it into
# tests/fuzz/regressions/FUZZ_TARGET/ so that it is replayed by every later run.
file(REMOVE_RECURSE "${WORK_DIR}")
set(corpus "${WORK_DIR}/corpus")
set(findings "${WORK_DIR}/findings")
file(MAKE_DIRECTORY "${corpus}" "${findings}")
set(regressions "${SOURCE_DIR}/tests/fuzz/regressions/${FUZZ_TARGET}")

if(FUZZ_TARGET STREQUAL "fuzz_case_loader")
  # every case.toml that ships or that the hostile catalogue holds, one file each
  file(GLOB_RECURSE seeds "${SOURCE_DIR}/cases/*/case.toml" "${SOURCE_DIR}/tests/hostile/*/case.toml")
  set(k 0)
  foreach(seed IN LISTS seeds)
    file(COPY_FILE "${seed}" "${corpus}/seed_${k}.toml")
    math(EXPR k "${k} + 1")
  endforeach()
  set(dictionary "-dict=${SOURCE_DIR}/tests/fuzz/case_toml.dict")
  set(max_len 65536)
elseif(FUZZ_TARGET STREQUAL "fuzz_checkpoint_state")
  set(dictionary "")  # its input is a list of edits; it makes the real state itself
  set(max_len 4096)
else()
  # a real checkpoint: the geostatic column run for a few steps
  file(MAKE_DIRECTORY "${WORK_DIR}/case")
  file(READ "${SOURCE_DIR}/cases/verification/geostatic/case.toml" text)
  string(REGEX REPLACE "\nend = [0-9.]+" "\nend = 0.002" text "${text}")
  string(REGEX REPLACE "\noutput_interval = [0-9.]+" "\noutput_interval = 0.001" text "${text}")
  file(WRITE "${WORK_DIR}/case/case.toml" "${text}")
  execute_process(COMMAND "${QUICKSAND}" run "${WORK_DIR}/case" --quiet RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT EXISTS "${WORK_DIR}/case/output/checkpoint.h5")
    message(FATAL_ERROR "could not make the seed checkpoint (${rc}): ${err}")
  endif()
  file(COPY_FILE "${WORK_DIR}/case/output/checkpoint.h5" "${corpus}/geostatic.h5")
  set(dictionary "")
  set(max_len 1048576)
endif()
set(corpora "${corpus}")
if(IS_DIRECTORY "${regressions}")
  list(APPEND corpora "${regressions}")
endif()

# -max_len: for the checkpoint, above the seed's size, so that the seed is never cut. -rss_limit_mb: a case may legitimately ask for a large grid; the loader must refuse it before
# allocating. -timeout: one input that takes longer than 10 s is a hang.
execute_process(
  COMMAND "${FUZZER}" ${corpora} ${dictionary} -max_total_time=${SECONDS} -timeout=10 -rss_limit_mb=2048
          -max_len=${max_len} -artifact_prefix=${findings}/ -print_final_stats=1
  WORKING_DIRECTORY "${WORK_DIR}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(WRITE "${WORK_DIR}/fuzzer.log" "${out}${err}")
string(REGEX MATCH "stat::number_of_executed_units: *[0-9]+" runs "${err}")
string(REGEX MATCH "stat::average_exec_per_sec: *[0-9]+" speed "${err}")
string(REGEX MATCH "DONE +cov: [0-9]+ ft: [0-9]+ corp: [0-9/]+[kKMb]*" coverage "${err}")  # the last line, not INITED
message(STATUS "${FUZZ_TARGET}: ${runs}, ${speed}, ${coverage} (log: ${WORK_DIR}/fuzzer.log)")
file(GLOB found "${findings}/*")
if(NOT rc EQUAL 0 OR found)
  string(REGEX MATCH "==[0-9]+==ERROR[^\n]*" what "${err}")
  message(FATAL_ERROR "${FUZZ_TARGET} found a defect (exit ${rc}): ${what}\ninputs: ${found}\nsee ${WORK_DIR}/fuzzer.log")
endif()
