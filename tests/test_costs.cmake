# Included by CTest after the discovered tests (tests/CMakeLists.txt says why): each of the
# longest discovered tests' seconds in a Release `ctest -j2` on the 2-core VM, under load
# (2026-11-27). Only their order matters: CTest starts the costliest first, and replaces these
# by the times of the previous run once a build directory has one. The same names under the
# sanitizer pass's "no-device: " prefix get the same costs. A renamed or new test simply gets
# the default cost 0 (started last) until it is listed here.
set(mb_test_costs
  [==[report writes index.html and every image it references, from this run's measurements]==] 385
  [==[every command that takes materials or scenes runs cleanly on every description form (report on one)]==] 120
  [==[three shards merged equal the single-process package, byte for byte]==] 109
  [==[pruned permutations of the shipped example scenes equal their feature-complete forms]==] 99
  [==[the allowance where needed, on four threads, judges as the full allowance on one]==] 81
  [==[every example permutation validates]==] 77
  [==[eval works for every brick that bricks --json lists]==] 68
  [==[Every shipped permutation's fragment shader compiles, validates and reflects the documented interface]==] 61
  [==[HLSL and MSL includes of every shipped material compile in their wrappers]==] 59
  [==[a fixed-point sampler's image lies within the derived sampling bound]==] 56
  [==[merge refuses an incomplete, mixed, stale or damaged set of shards and writes nothing]==] 45
  [==[preview writes decodable PNGs of the right size]==] 45
  [==[every shipped material under both environments matches the reference at every pixel]==] 43
  [==[a remote cache slower than compiling locally is noticed and dropped]==] 41
  [==[the quadrature DFG LUT is within 1e-4 (channels 0, 1) and 1e-3 relative (cloth) of the exact integrals at every texel]==] 37
  [==[compile writes each permutation's fragment shader in every target, with manifest entry and header]==] 37
  [==[a compile killed at any moment leaves the old package or the new one, complete]==] 36
  [==[quiet long commands (-q) print nothing on success]==] 28
  [==[every bad input gets its expected diagnostics, in text and json, leaves nothing behind, and is shown as docs/bad-inputs.md has it]==] 44
  [==[JSON and macro forms of each shipped material give byte-identical SPIR-V]==] 24
  [==[concurrent matbricks processes writing one remote cache leave only whole blobs]==] 22
  [==[every file of the glTF conformance corpus compiles and scene-compiles]==] 21
  [==[shards of a build farm share one remote cache: a fresh machine then compiles nothing]==] 20
  [==[output is bit-identical at -j1 and -j4, every target]==] 19
  [==[fp32 permutations cross-compile to every target and pass its check]==] 19
  [==[SPIR-V of every permutation and brick probe passes spirv-val]==] 13
  [==[a scene package records the scene's counts and every target's files]==] 13
  [==[pruned permutations of a constructed scene equal their feature-complete forms]==] 13
  [==[dfgIntegrals and clothDfgIntegral converge to 1e-7 at every extreme of the LUT]==] 12
  [==[stress on the shipped glTF files exits 0 and reports every material]==] 12
  [==[a sweep renders one distinct sphere per step]==] 11
  [==[matbricks energy --grid coarse --json reports every lobe]==] 11
  [==[every brick of the manifest validates against its reference on lavapipe]==] 11
  [==[prefiltered levels: the GPU kernel computes its estimator, whose noise is bounded]==] 10
  [==[the lean and legacy pipelines give the same SPIR-V and reject a module with the same message]==] 10
  [==[the reference does not depend on the number of threads]==] 10
  [==[each include is self-contained: hooks + include + calls compile]==] 10
  [==[the mediump (ESSL) form of fp16 permutations computes the fp32 function on lavapipe, but for its caps]==] 10
  [==[cache verification: a valid-looking wrong entry under the right key is caught and evicted]==] 9
  [==[without its sampling share the fixed-point sampler's image fails]==] 9
  [==[a package directory is created, filled when empty, and replaced atomically when it is ours]==] 9
  [==[a wrong reference (perturbed roughness) is caught]==] 9
  [==[fp16: GLSL 450, HLSL (min16float) and MSL from the half module, ESSL 3.10 from the mediump form]==] 9
  [==[a streamed build in small windows writes the same package as one window, and compiles a unit once]==] 9
  [==[a remote cache that is down or silent costs one request and one warning]==] 8
  [==[another unit's blob with its key field rewritten is a miss: rebuilt, never stored locally, one warning]==] 8
  [==[stress of a material passes at fp32 and at fp16 (emulated)]==] 8
  [==[two compiles of the same permutation are byte-identical]==] 8
  [==[all three features together validate on lavapipe in every environment mode]==] 8
  [==[cloth's indirect sheen is sheenColor * Int D_Charlie V_Ashikhmin (n.l) in a constant environment]==] 7
  [==[package manifest: keys, hashes, deduplicated files per target, deterministic]==] 7
  [==[matbricks lut writes the file its extension names and reports in JSON]==] 7
  [==[a remote cache that refuses uploads is still read]==] 7
  [==[a corrupt, truncated or misplaced remote blob is detected, ignored and replaced]==] 6
  [==[the cloth model validates on lavapipe: all lights, every environment mode]==] 6
  [==[a package is replaced only while it holds exactly what its marker lists]==] 6
  [==[a low-quality and a folded scene permutation validate on lavapipe]==] 6
  [==[the DFG LUT path equals the brute-force integral of the direct BRDF in a constant environment]==] 6
  [==[an fp16 package's fragment shaders: half SPIR-V, ESSL from the mediump form]==] 6
  [==[a remote cache fills on a miss, serves a fresh machine, and the local cache stays in front]==] 5
  [==[a clear coat with its own normal validates on lavapipe under every light and environment]==] 5
  [==[preview rejects bad input with one line and writes nothing]==] 5
  [==[the fragment shader is cached with its kernel: a warm build compiles nothing and gives the same bytes]==] 5
  [==[each stability fix is shown: the naive form fails where the shipped brick passes]==] 5
  [==[a fold that is not neutral in the full form is caught]==] 5
  [==[glTF scenes plan the environment a viewer shows]==] 5
  [==[each target's check rejects a broken output]==] 5
  [==[stress finds a planted NaN, exits 1, and its worst input replays with eval]==] 5
  [==[seeded mutations of every shipped material load or give coded diagnostics, never crash or hang]==] 4
  [==[builds through the cache: a warm build hits, a corrupt entry is rebuilt to identical output]==] 4
  [==[two swapped entries of a one-shard split are refused, not merged into a wrong package]==] 4
  [==[a mount point inside a package is never removed across: refused, the mounted files kept]==] 4
  [==[the C++ header compiles, finds every key, and its std140 asserts can fail]==] 4
  [==[scene JSON naming a glTF without lights: the same default, overridable]==] 4
  [==[a parameter block the optimizer removed is no internal error]==] 4
  [==[two concurrent builds on one cache directory give identical output and whole entries]==] 4
  [==[norm_tube_karis saturates the line angle, as UE4]==] 4
  [==[diffuse_fabric_lambert takes alpha, as seed 000 and Unity]==] 4
  [==[a single-file write killed before its rename leaves a marked temporary, which the next write removes]==] 4
  [==[validate --json gives one complete record per permutation]==] 4
  [==[the standard model's SH and IBL environments validate on lavapipe]==] 3
  [==[max_noh_decima_newton holds its derived tolerance down to n.v = 1e-3]==] 3
  [==[example scenes: required counts, far below possible, sorted keys, deterministic]==] 3
  [==[the manifest keeps what the engine needs of a glTF material]==] 3
  [==[static cost: every shipped brick costs more than nothing]==] 3)

list(LENGTH mb_test_costs mb_count)
math(EXPR mb_last "${mb_count} - 1")
foreach(mb_at RANGE 0 ${mb_last} 2)
  math(EXPR mb_next "${mb_at} + 1")
  list(GET mb_test_costs ${mb_at} mb_name)
  list(GET mb_test_costs ${mb_next} mb_cost)
  list(FIND mb_tests_device_TESTS "${mb_name}" mb_found_device)
  list(FIND mb_tests_host_TESTS "${mb_name}" mb_found)
  if(NOT mb_found EQUAL -1 OR NOT mb_found_device EQUAL -1)
    set_tests_properties("${mb_name}" PROPERTIES COST ${mb_cost})
  endif()
  list(FIND mb_tests_no_device_TESTS "no-device: ${mb_name}" mb_found)
  if(NOT mb_found EQUAL -1)
    set_tests_properties("no-device: ${mb_name}" PROPERTIES COST ${mb_cost})
  endif()
endforeach()
