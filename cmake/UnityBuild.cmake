# Unity builds (-DCMAKE_UNITY_BUILD=ON, CMake's default batches of 8 files per target) parse the
# headers that every file includes (Eigen, SUNDIALS, nlohmann/json, Boost.Test, the project's own)
# once per batch instead of once per file: CI's cold builds are unity builds (.ci/run configures
# both trees so; docs/quality-checks.md, Time, has the measured gain). Developers' trees are not
# unity builds unless configured so: an edit there recompiles one file, not its batch.
#
# A file that cannot share a unity source with the other files of its target (a name in an
# anonymous namespace that another file of the target also defines, or a class member whose type
# lives in an anonymous namespace: GCC's -Wsubobject-linkage once the file is #included) is
# compiled alone: one "target file" pair a line, with the reason. A new collision shows as a
# redefinition error in a unity build only; add the file here.
set(ROTBEAM_UNITY_ALONE
  rotbeam_core core/static_driver.cpp            # NewtonWorkspace::Impl holds an anonymous-namespace type
  rotbeam_core core/dae_ida.cpp                  # check() and Resources, as in kinsol_driver.cpp
  rotbeam_reference core/oracles/manufactured_motion.cpp  # kE1, kE3, as in manufactured.cpp
  rotbeam_estimates estimates/estimate.cpp      # vec3, mat3, Tally, length_scale, PointDifference, as in point_difference.cpp and history_estimate.cpp
  rotbeam_runs runs/accuracy_run.cpp             # mode_stations, as in run_case.cpp
  rotbeam_runs runs/run_mixed_dynamics.cpp       # has_static_load, modal, dynamic, as in run_displacement_dynamics.cpp
  rotbeam_cases cases/loader/beamdyn_lines.cpp   # its quoted() meets std::quoted (ADL) once a batch has <iomanip>
)
function(rotbeam_apply_unity_exclusions)
  set(pairs ${ROTBEAM_UNITY_ALONE})
  while(pairs)
    list(POP_FRONT pairs target file)
    if(TARGET ${target})
      set_source_files_properties(${PROJECT_SOURCE_DIR}/${file} TARGET_DIRECTORY ${target}
        PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
    endif()
  endwhile()
endfunction()
