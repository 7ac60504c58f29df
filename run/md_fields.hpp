#pragma once
// An `md run` folder's measured mean fields as the tracer's host gas (`coldblast tracer
// --background md --md-run DIR`, issue 32): profiles.csv (n, u, T in bins of r/R at every recorded
// time) with the observable R of observables.csv as each time's scale, handed to kinetic/ as numbers
// (kinetic::MeasuredProfiles), and the run's id and scene from its summary.json.
#include <filesystem>
#include <string>

#include "kinetic/md_background.hpp"
#include "md/blast_config.hpp"

namespace coldblast::run {

/// What the tracer takes from an MD run folder.
struct MdRunFields {
  std::string run_id;      ///< empty for a run made before run ids
  std::string scene_toml;  ///< the MD's resolved scene (summary.json's scene_toml)
  md::BlastConfig scene;   ///< that scene, parsed
  kinetic::MeasuredProfiles profiles;
};

/// The scene text of the `md run` folder `directory` (summary.json's scene_toml): the tracer's
/// scene when none is given. std::invalid_argument naming `option` (e.g. "--md-run") when the folder
/// is missing, is not an md run (no summary.json, or a tracer run's), or mixes two runs' files.
std::string md_run_scene_toml(const std::filesystem::path& directory, const std::string& option);

/// Reads an `md run` folder's profiles, R and scene. std::invalid_argument naming `option` as
/// md_run_scene_toml, and when the run recorded no profiles or no R, or its files are malformed
/// (the file and line named).
MdRunFields read_md_run_fields(const std::filesystem::path& directory, const std::string& option);

/// Empty when the tracer's scene has the MD's physics (d, n, a, E, impurities.count, .mass,
/// .radius); otherwise the first difference as "its KEY is MD-VALUE, TRACER-VALUE here".
std::string scene_physics_difference(const md::BlastConfig& md_scene, const md::BlastConfig& tracer_scene);

}  // namespace coldblast::run
