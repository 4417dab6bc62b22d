#pragma once
// `washout study SCENE.lua --vary NAME=V1,V2,... [--vary ...] [--repeat N] [--out DIR]`:
// error against run time over a set of runs (docs/validation.md). argv[0] is "study".
// Returns 0 when the study ran (whatever each run's status), 1 on a wrong scene or option,
// 3 when study.csv cannot be written, 4 when a run was interrupted.
namespace washout::cli {

int run_study_command(int argc, char** argv);

}  // namespace washout::cli
