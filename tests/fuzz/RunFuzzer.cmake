# cmake -DFUZZER=exe -DSEEDS=dir -DWORK=dir -DSECONDS=n -P RunFuzzer.cmake
# Copies the seed corpus to WORK/corpus, fuzzes it for SECONDS with bounded memory; crash,
# leak, timeout and OOM reproducers are written to WORK/artifacts/ and fail the test.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/corpus ${WORK}/artifacts)
file(GLOB seeds ${SEEDS}/*)
file(COPY ${seeds} DESTINATION ${WORK}/corpus)
execute_process(
  COMMAND ${FUZZER} -max_total_time=${SECONDS} -rss_limit_mb=2048 -malloc_limit_mb=2048 -timeout=25
          -max_len=65536 -print_final_stats=1 -artifact_prefix=${WORK}/artifacts/ ${WORK}/corpus
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${FUZZER} found a problem (exit ${rc}); reproducer in ${WORK}/artifacts/")
endif()
