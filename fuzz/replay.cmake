# The replay program (replay.cpp) and the ctest entry fuzz_corpus_replay: every stored corpus and regression input
# of the fuzz targets, run by the normal compiler, so that CI needs no clang.
set(BEZOUTIAN_FUZZ_DIR ${PROJECT_SOURCE_DIR}/fuzz)
add_executable(bezoutian_fuzz_replay ${BEZOUTIAN_FUZZ_DIR}/replay.cpp ${BEZOUTIAN_FUZZ_DIR}/fuzz_failure.cpp
               ${BEZOUTIAN_FUZZ_DIR}/target_json.cpp ${BEZOUTIAN_FUZZ_DIR}/target_expression.cpp
               ${BEZOUTIAN_FUZZ_DIR}/target_dat.cpp ${BEZOUTIAN_FUZZ_DIR}/target_bpt.cpp
               ${BEZOUTIAN_FUZZ_DIR}/target_curves.cpp ${BEZOUTIAN_FUZZ_DIR}/target_patches.cpp)
target_link_libraries(bezoutian_fuzz_replay PRIVATE Bezoutian::Bezoutian)
add_test(NAME fuzz_corpus_replay COMMAND bezoutian_fuzz_replay ${BEZOUTIAN_FUZZ_DIR})
set_tests_properties(fuzz_corpus_replay PROPERTIES TIMEOUT 120)
