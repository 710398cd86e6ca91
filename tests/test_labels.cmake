# ctest labels, so that a part of the suite can be run alone: `ctest -L unit`, `-L statistical`,
# `-L render`, `-L slow`, `-L cluster` (or `-LE slow` to leave the slow ones out). Run by ctest
# after the test lists that gtest_discover_tests wrote (TEST_INCLUDE_FILES, tests/CMakeLists.txt),
# so it sees every discovered test by name:
#   cluster      needs the Slurm cluster (root, slurm-wlm, munge)
#   slow         took over 8 s in the last clean-clone CI run (2 cores)
#   statistical  checks Monte Carlo estimates against a pdf or an exact answer, with a tolerance of
#                standard errors (chi-square of sampled BSDFs, furnaces, analytic scenes, convergence)
#   render       renders images: the renderer's tests and the image regressions
#   unit         all the others: deterministic checks of one part
set(_cluster "^FarmCluster\\.")
set(_slow "^(DefaultShotStory|CryingRivuletStory|FarmCluster|RenderMemory)\\.|^LiquidTearCourse\\.OnTheDefaultShot|^SequenceInterrupt\\.Killed")
set(_statistical
    "^(AllBsdfs/BsdfChi2|BsdfEnergy|VndfChi2|Chi2SelfTest|Chi2Family|SubsurfaceAlbedo|DiffusionProfile|SubsurfaceDiffusion|AnalyticScenes|BounceLimits|Caustics|SamplerConvergence|WaterAnalytic)\\.")
# The sampler's own tests live beside the renderer (it is the renderer's type) but render nothing.
set(_unit_in_renderer "^(PixelSampler|PixelSamplerSobol|Sobol)\\.")
set(_render_in_tools "^(Shots/ImageRegression|Shots/LayerRecombination|TestSuiteCli|CliRender|BenchQuality)\\.")

foreach(_executable geometry flesh sph crowd tracking materials renderer scenes tools fuzz)
  foreach(_test IN LISTS lacrima_${_executable}_tests_TESTS)
    set(_labels "")
    if(_test MATCHES "${_cluster}")
      list(APPEND _labels cluster)
    endif()
    if(_test MATCHES "${_slow}")
      list(APPEND _labels slow)
    endif()
    if(_test MATCHES "${_statistical}")
      list(APPEND _labels statistical)
    endif()
    if((_executable STREQUAL "renderer" AND NOT _test MATCHES "${_unit_in_renderer}") OR _test MATCHES "${_render_in_tools}")
      list(APPEND _labels render)
    endif()
    if(NOT _labels)
      set(_labels unit)
    endif()
    set_tests_properties("${_test}" PROPERTIES LABELS "${_labels}")
  endforeach()
endforeach()
