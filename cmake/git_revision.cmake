# Writes OUTPUT (a header defining FINSEG_GIT_REVISION) from `git rev-parse HEAD` in
# SOURCE_DIR, "unknown" outside a checkout. Run at every build (CMakeLists.txt), it rewrites
# the header only when the revision changed, so that only src/core/version.cpp recompiles then.
execute_process(COMMAND git rev-parse HEAD WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE revision OUTPUT_STRIP_TRAILING_WHITESPACE
                RESULT_VARIABLE result ERROR_QUIET)
if(NOT result EQUAL 0 OR revision STREQUAL "")
  set(revision "unknown")
endif()
file(WRITE ${OUTPUT}.new "#define FINSEG_GIT_REVISION \"${revision}\"\n")
file(COPY_FILE ${OUTPUT}.new ${OUTPUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUTPUT}.new)
