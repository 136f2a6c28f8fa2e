// `circles oracle [SCENE]`: the exact oracle run in both profiles on a scene, and what it did (the main job's
// first part, cli/main_job.hpp; printed by cli/oracle_report.hpp).
#pragma once

#include "cli/options.hpp"

#include <CLI/CLI.hpp>

#include <cstddef>
#include <ostream>

namespace circles::cli {

// The most steps `circles oracle` takes: its exact rationals grow with every step.
inline constexpr std::size_t kMaxOracleSteps = 1000000;

struct OracleCommandOptions {
  std::size_t steps = 100;               // --steps, else the scene's "steps", else 100
  CLI::Option* steps_option = nullptr;   // whether --steps was given, and its default for --help
};

// Declares the command and its options on `app`; the scene's options go to `scene`.
CLI::App* add_oracle_command(CLI::App& app, SceneOptions& scene, OracleCommandOptions& options);

// The command: the oracle's report on `out`, 0; or 2 with the reason on `err` for a scene's "steps" beyond
// kMaxOracleSteps. Throws SceneError for a scene that cannot be read (formats/scene.hpp).
int oracle_command(const SceneOptions& scene, const OracleCommandOptions& options, std::ostream& out,
                   std::ostream& err);

}  // namespace circles::cli
