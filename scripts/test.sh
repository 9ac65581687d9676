#!/usr/bin/env bash
# Sets everything up and runs the whole test suite: format check, release build and tests,
# then the same tests under AddressSanitizer + UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
jobs=$(nproc)

echo "== clang-format check"
git ls-files '*.cpp' '*.hpp' | xargs clang-format --dry-run --Werror

# Both builds are unity builds (the library excepted, CMakeLists.txt): a dozen test files to a
# translation unit parse the shared headers (Eigen, gtest, the library's) and instantiate their
# templates once, which takes most of a test file's compile time: the tests build in about a
# quarter of the CPU time. So file-local names must differ between the files of a folder (each
# test file's helpers live in a namespace named after it; CMake leaves out files with their
# own definitions).
unity="-DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=12"

echo "== release build and tests"
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release $unity >/dev/null
cmake --build build/release -j"$jobs"
ctest --test-dir build/release --output-on-failure -j"$jobs"

echo "== ASan/UBSan build and tests"
# -g1 (line tables, no variable info) is enough for the sanitizers' stack traces and compiles in
# about 60 % of the time of -g; the Python module is not built here (its tests cannot run
# sanitized, see below).
cmake -S . -B build/asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFINSEG_SANITIZE=ON $unity \
  -DFINSEG_BENCH=OFF -DFINSEG_PYTHON=OFF -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" >/dev/null
cmake --build build/asan -j"$jobs"
# The 32-segment mesh convergence pull (6 s in Release) is skipped here: under the
# sanitizers it would take a large part of the CI budget; every other test runs.
# Likewise the refinement studies of the strip through the FOLD path (69 s and 29 s sanitized)
# and the Miura and degree-4 vertex kinematics over the whole fold range (40 s and 23 s):
# ZigzagFoldPath.DeploysWithContact and CliGenPatterns.MiuraFoldedFromFlat... run the same code
# sanitized on smaller models.
# python_pytest is not built here: Debian's python3 is not built with ASan, so the sanitized module only
# loads with libasan in LD_PRELOAD, and the leak checker then reports the interpreter's own
# allocations; the module's C++ is the library's, which the tests above run sanitized.
# The clamped plate's refinement to 63 x 63 segments (20 s in Release) likewise; the simply
# supported plate runs the same code on the same cells, sanitized. The pressurised tube up to
# 64 facets likewise, with nu = 0 and nu = 0.3: GasTube.PressurisedTubeSmall and
# GasTube.CappedTubeCarriesItsEndLoadAxially run 8 and 16 facets sanitized. The 20
# layers of 3 x 3 cells pressed together (15 s in Release) likewise: the 20 x (2 x 2) and
# 5 x (3 x 3) stacks run sanitized. The lay-flat tube's 0.3 ms of inflation (3.5 s in Release)
# likewise: its pattern, chamber and scene (the example's first 0.2 ms) run sanitized. The Miura
# tube pulled open over its fold range (4-6 s in Release) likewise: its pattern and the
# example's first 0.2 ms run sanitized. The reflected cone inflated with friction to 0.66 s,
# twice with the continuous law (55 s in Release) and three times with the anchor law (36 s)
# likewise: friction's secant runs sanitized in
# ContactDynamics.PlateDroppedBelowTheSlidingAngleComesToRestAndStays (its solves take it) and
# tests/test_friction_secant.cpp, the anchor law in tests/test_contact_dynamics.cpp, the
# example's scene in CliGenPatterns' first 20 ms.
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build/asan --output-on-failure -j"$jobs" \
  -E "ZigzagConditions.PeakForceConvergesUnderRefinementWithContact|python_pytest|PlateValidation.ClampedSquarePlateUnderUniformPressure|GasTube.PressurisedTubeGrowsAsMembraneTheorySays|GasTube.WithPoissonsRatioTheWallStrainsAsHookesLawConvergingAtSecondOrder|ContactStack.TwentyFinerFoldedLayersPressedTogetherStayApart|ZigzagFoldPath.BendingConvergesAtSecondOrderToTheGeneratorsLimit|ZigzagFoldPath.TheCreaseLawAloneIsFirstOrder|MiuraValidation.OuterDimensionsFollowTheClosedFormOverTheFoldRange|MiuraValidation.SingleDegreeFourVertexFollowsHuffmansRelation|FlatTube.PressurisedFlatTubeRoundsOutConservingEnergy|MiuraTubeKinematics.PulledOpenTubeFollowsTheClosedFormOverTheFoldRange|ConeStowed.ExamplePullStartsWithContactOnAndNoForceFromTheStacksOverlap|ConeFriction.InflationWithLayersSlidingMatchesTheWiderLawToItsCreep|ConeFriction.AnchorInflationMatchesASofterSpringToItsStickLength"
