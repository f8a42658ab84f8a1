# `quicksand` under mpirun (run by ctest as `cmake -P`, label mpi):
#  1. `check` on 2 ranks prints the report and the decomposition once, not once per rank;
#  2. a bad case on 2 ranks is refused once, naming file and key, with exit code 1;
#  3. `run` of a 1D column on 2 ranks, which cannot be cut, is refused once, within the timeout
#     (no rank waits for another), and leaves an earlier output/ untouched;
#  4. `check --ranks N` plans a decomposition without mpirun, and refuses more ranks than cells;
#  5. `--version` names the MPI library;
#  6. more ranks than the grid has columns for, under mpirun: refused once, naming the file;
#  7. `run` of the random bed on 2 ranks writes one series.csv (one header, a row per output),
#     fields.h5 and a checkpoint, and resumes on 3 ranks and on 1 (without mpirun) to the next
#     outputs, its series within 1e-8 of a straight run's on one rank;
#  8. the semi-implicit scheme on 2 ranks, resumed on 3, within 1e-8 of a straight run on one.
# MPIEXEC: mpirun with its flags (--oversubscribe: more ranks than the 2 cores).
separate_arguments(mpiexec UNIX_COMMAND "${MPIEXEC}")
set(piping "${SOURCE_DIR}/cases/piping2D")

# Each quantity of CHAIN's series.csv within 1e-8 of its scale in STRAIGHT's (the ledger's residual,
# a difference of the stored water's volume, within 1e-8 of that volume); ROWS: how many rows
# both must have (0: as many as each other).
function(compare_series straight chain rows what)
  execute_process(COMMAND python3 -c "
import csv, sys
a = list(csv.DictReader(open(sys.argv[1]))); b = list(csv.DictReader(open(sys.argv[2])))
rows = int(sys.argv[3])
assert len(a) == len(b) and (rows == 0 or len(a) == rows), (len(a), len(b), rows)
bad = []
for k in a[0]:
    scale = max(abs(float(r[k])) for r in a) or 1.0
    if k == 'ledger_residual':
        scale = max(abs(float(r['liquid_mass'])) for r in a) / 998.2
    worst = max(abs(float(x[k]) - float(y[k])) for x, y in zip(a, b))
    if worst > 1e-8 * scale: bad.append('%s: %g of %g' % (k, worst, scale))
sys.exit('differ: ' + '; '.join(bad) if bad else 0)
" "${straight}/output/series.csv" "${chain}/output/series.csv" "${rows}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what}: ${out}${err}")
  endif()
endfunction()

function(count_matches text pattern out)
  string(REGEX MATCHALL "${pattern}" found "${text}")
  list(LENGTH found n)
  set(${out} ${n} PARENT_SCOPE)
endfunction()

# 1.
execute_process(COMMAND ${mpiexec} -np 2 "${QUICKSAND}" check "${piping}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "mpirun -np 2 quicksand check failed (${rc}):\n${out}\n${err}")
endif()
count_matches("${out}" "case OK" ok)
count_matches("${out}" "decomposition: 2 ranks, 2 x 1 blocks \\(columns whole\\)" plans)
if(NOT ok EQUAL 1 OR NOT plans EQUAL 1)
  message(FATAL_ERROR "check on 2 ranks printed 'case OK' ${ok} times and the decomposition ${plans} times, "
                      "expected once each:\n${out}")
endif()

# 2.
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}/bad/output")
file(WRITE "${WORK_DIR}/bad/output/series.csv" "earlier results\n")
file(READ "${SOURCE_DIR}/cases/verification/geostatic/case.toml" good)
string(REPLACE "porosity = 0.38" "porosity = 1.38" bad "${good}")
file(WRITE "${WORK_DIR}/bad/case.toml" "${bad}")
foreach(cmd check run)
  execute_process(COMMAND ${mpiexec} -np 2 "${QUICKSAND}" ${cmd} "${WORK_DIR}/bad"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
  if(rc EQUAL 0 OR NOT rc MATCHES "^[0-9]+$")
    message(FATAL_ERROR "mpirun -np 2 quicksand ${cmd} of porosity 1.38: exit ${rc}, expected 1:\n${err}")
  endif()
  count_matches("${err}" "case.toml:[0-9]+: key 'materials\\.[a-z_]+\\.porosity'" said)
  if(NOT said EQUAL 1)
    message(FATAL_ERROR "quicksand ${cmd} on 2 ranks said the error ${said} times, expected once:\n${err}")
  endif()
endforeach()

# 3.
file(MAKE_DIRECTORY "${WORK_DIR}/good/output")
file(WRITE "${WORK_DIR}/good/output/series.csv" "earlier results\n")
file(WRITE "${WORK_DIR}/good/case.toml" "${good}")
execute_process(COMMAND ${mpiexec} -np 2 "${QUICKSAND}" run "${WORK_DIR}/good"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
if(NOT rc EQUAL 1)
  message(FATAL_ERROR "mpirun -np 2 quicksand run: exit ${rc}, expected 1 (refused):\n${out}\n${err}")
endif()
count_matches("${err}" "a 1D column \\(grid.dimension = 1\\) cannot be cut over 2" said)
if(NOT said EQUAL 1)
  message(FATAL_ERROR "run on 2 ranks said its refusal ${said} times, expected once:\n${err}")
endif()
file(READ "${WORK_DIR}/good/output/series.csv" kept)
if(NOT kept STREQUAL "earlier results\n")
  message(FATAL_ERROR "a refused run on 2 ranks touched the earlier output/")
endif()

# 4.
execute_process(COMMAND "${QUICKSAND}" check "${piping}" --ranks 3
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
if(NOT rc EQUAL 0 OR NOT out MATCHES "decomposition: 3 ranks, 3 x 1 blocks \\(columns whole\\)")
  message(FATAL_ERROR "quicksand check --ranks 3 (${rc}):\n${out}\n${err}")
endif()
execute_process(COMMAND "${QUICKSAND}" check "${piping}" --ranks 1000
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
if(NOT rc EQUAL 1 OR NOT err MATCHES "piping2D/case.toml: the grid of 13 x 49 cells .* cannot be cut into 1000 blocks")
  message(FATAL_ERROR "quicksand check --ranks 1000 of 13 x 49 cells (${rc}):\n${out}\n${err}")
endif()

# 5.
execute_process(COMMAND "${QUICKSAND}" --version RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
if(NOT rc EQUAL 0 OR NOT out MATCHES "MPI: +Open MPI")
  message(FATAL_ERROR "quicksand --version does not name the MPI library (${rc}):\n${out}\n${err}")
endif()

# 6.
execute_process(COMMAND ${mpiexec} -np 3 "${QUICKSAND}" check "${piping}" --set grid.width=0.0248
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
count_matches("${err}" "piping2D/case.toml: the grid of 4 x 49 cells .* cannot be cut into 3 blocks" said)
if(NOT rc EQUAL 1 OR NOT said EQUAL 1)
  message(FATAL_ERROR "mpirun -np 3 quicksand check of 4 columns: exit ${rc}, said ${said} times, expected 1 and once:\n${out}\n${err}")
endif()

# 7.
file(MAKE_DIRECTORY "${WORK_DIR}/bed")
file(COPY "${SOURCE_DIR}/cases/verification/random_bed/case.toml" DESTINATION "${WORK_DIR}/bed")
set(short --set time.end=0.02 --set time.output_interval=0.01 --set grid.width=0.1488 --quiet)
execute_process(COMMAND ${mpiexec} -np 2 "${QUICKSAND}" run "${WORK_DIR}/bed" ${short}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "mpirun -np 2 quicksand run of the random bed: exit ${rc}:\n${out}\n${err}")
endif()
foreach(f series.csv pipes.csv fields.h5 fields.xdmf checkpoint.h5 case.effective.toml)
  if(NOT EXISTS "${WORK_DIR}/bed/output/${f}")
    message(FATAL_ERROR "a run on 2 ranks did not write output/${f}")
  endif()
endforeach()
file(STRINGS "${WORK_DIR}/bed/output/series.csv" lines)
list(LENGTH lines n)
count_matches("${lines}" "time" headers)
if(NOT n EQUAL 4 OR NOT headers EQUAL 1)  # the header, t = 0, 0.01, 0.02
  message(FATAL_ERROR "series.csv of a run on 2 ranks has ${n} lines and ${headers} headers, expected 4 and 1:\n${lines}")
endif()
execute_process(COMMAND ${mpiexec} -np 3 "${QUICKSAND}" run "${WORK_DIR}/bed" ${short} --set time.end=0.03 --resume
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
execute_process(COMMAND "${QUICKSAND}" run "${WORK_DIR}/bed" ${short} --set time.end=0.04 --resume
                RESULT_VARIABLE rc1 OUTPUT_VARIABLE out1 ERROR_VARIABLE err1 TIMEOUT 300)
file(STRINGS "${WORK_DIR}/bed/output/series.csv" lines)
list(LENGTH lines n)
if(NOT rc EQUAL 0 OR NOT rc1 EQUAL 0 OR NOT n EQUAL 6)
  message(FATAL_ERROR "the 2 ranks' checkpoint resumed on 3 (exit ${rc}) and then on 1 (exit ${rc1}): series.csv has "
                      "${n} lines, expected 6:\n${err}\n${err1}\n${lines}")
endif()
# the chain's series against a straight run on one rank: each quantity within 1e-8 of its scale
file(MAKE_DIRECTORY "${WORK_DIR}/straight")
file(COPY "${SOURCE_DIR}/cases/verification/random_bed/case.toml" DESTINATION "${WORK_DIR}/straight")
execute_process(COMMAND "${QUICKSAND}" run "${WORK_DIR}/straight" ${short} --set time.end=0.04
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
compare_series("${WORK_DIR}/straight" "${WORK_DIR}/bed" 0
               "the run on 2, then 3, then 1 rank against a straight run on one")

# 8. the semi-implicit scheme: 2 ranks (hypre's CG over the ranks), resumed on 3, against a
# straight run on one rank (the sparse Cholesky factorisation), at the same 1e-8
set(semi --set time.scheme=\"semi_implicit\" --set liquid.bulk_modulus=2.2e9)
file(MAKE_DIRECTORY "${WORK_DIR}/semi" "${WORK_DIR}/semi_straight")
foreach(d semi semi_straight)
  file(COPY "${SOURCE_DIR}/cases/verification/random_bed/case.toml" DESTINATION "${WORK_DIR}/${d}")
endforeach()
execute_process(COMMAND ${mpiexec} -np 2 "${QUICKSAND}" run "${WORK_DIR}/semi" ${short} ${semi}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
execute_process(COMMAND ${mpiexec} -np 3 "${QUICKSAND}" run "${WORK_DIR}/semi" ${short} ${semi} --set time.end=0.04 --resume
                RESULT_VARIABLE rc3 OUTPUT_VARIABLE out3 ERROR_VARIABLE err3 TIMEOUT 300)
execute_process(COMMAND "${QUICKSAND}" run "${WORK_DIR}/semi_straight" ${short} ${semi} --set time.end=0.04
                RESULT_VARIABLE rc1 OUTPUT_VARIABLE out1 ERROR_VARIABLE err1 TIMEOUT 300)
if(NOT rc EQUAL 0 OR NOT rc3 EQUAL 0 OR NOT rc1 EQUAL 0)
  message(FATAL_ERROR "the semi-implicit scheme on 2 ranks (exit ${rc}), resumed on 3 (exit ${rc3}), and on one "
                      "(exit ${rc1}):\n${err}\n${err3}\n${err1}")
endif()
compare_series("${WORK_DIR}/semi_straight" "${WORK_DIR}/semi" 5
               "the semi-implicit run on 2, then 3 ranks against a straight run on one")
