// clrt-mpi: one image rendered across the ranks of an MPI job.
//   mpirun -np N clrt-mpi [clrt's options] [--tile WxH] SCENE -o OUT
// Rank 0 reads the scene and its meshes and sends their bytes to every rank (no shared file
// system needed); every rank builds the same BVH and renders the tiles it is dealt; rank 0
// gathers them and writes the image, the same bytes clrt writes. Exit status as clrt's; a
// failure on any rank ends every rank, printed once by rank 0, with no output file.
#include <chrono>
#include <iostream>
#include <optional>

#include "cli/heap_policy.hpp"
#include "cli/dark_scene_note.hpp"
#include "cli/image_write_options.hpp"
#include "cli/options.hpp"
#include "cli/picture_options.hpp"
#include "cli/run_clrt.hpp"
#include "image/interrupt_cleanup.hpp"
#include "cli/docs/cli_docs_option.hpp"
#include "mpi/mpi_options.hpp"
#include "mpi/mpi_report.hpp"
#include "mpi/mpi_session.hpp"
#include "mpi/rank_devices.hpp"
#include "mpi/scene_files.hpp"
#include "mpi/tile_farm.hpp"
#include "render/render_limits.hpp"
#include "render/usage_error.hpp"
#include "scene/file_source.hpp"

namespace {

using namespace clrt;
using Clock = std::chrono::steady_clock;

// Runs `step` and turns what it throws into the rank's outcome.
template <class Step>
mpi::Session::Outcome attempt(Step&& step) {
  try {
    step();
  } catch (const SceneError& e) {
    return {2, e.what()};
  } catch (const UsageError& e) {
    return {2, std::string("clrt-mpi: error: ") + e.what()};
  } catch (const RenderLimitError& e) {
    return {e.exit_code(), std::string("clrt-mpi: error: ") + e.what()};
  } catch (const std::exception& e) {
    end_by_pending_signal();
    return {1, std::string("clrt-mpi: error: ") + e.what()};
  }
  return {};
}

// Every rank learns whether any failed; rank 0 prints the failure once.
bool all_went_well(const mpi::Session& session, const mpi::Session::Outcome& mine, int& status,
                   Progress& progress) {
  const mpi::Session::Outcome job = session.agree(mine);
  status = job.status;
  if (job.status != 0 && session.first()) {
    progress.finish();
    std::cerr << job.message << "\n";
  }
  return job.status == 0;
}

int run(const mpi::Session& session, const CliOptions& cli, const mpi::TileSize& tile) {
  const auto start = Clock::now();
  Progress progress(!cli.quiet && session.first());
  int status = 0;
  ImageOutput output;
  Scene scene;
  std::map<std::string, std::string> files;
  // Rank 0 checks the request and reads the scene from its disk, keeping the bytes.
  mpi::Session::Outcome mine = attempt([&] {
    if (!session.first()) return;
    if (cli.list_devices) throw UsageError("--list-devices: run clrt --list-devices on a node");
    const FramePlan frames = resolve_frames(cli.animation);
    output = resolve_image_output(cli, frames);
    progress.phase("loading " + cli.scene);
    RecordingFiles recording;
    scene = load_scene(cli.scene, recording);
    check_outputs_are_not_inputs(output, frames, scene);
    if (!cli.quiet)
      for (const std::string& warning : scene.warnings) progress.message(warning);
    files = recording.files();
  });
  if (!all_went_well(session, mine, status, progress)) return status;

  mpi::RunReport report(session.size());
  files = mpi::share_files(session, files, report.scene_bytes_sent);
  std::optional<Renderer> renderer;
  RenderSetup setup;
  std::optional<std::string> dark_note;
  mine = attempt([&] {
    if (!session.first()) scene = load_scene(cli.scene, MemoryFiles(files));
    files.clear();
    setup = checked_render_setup(cli, scene, mpi::rank_devices(cli.device, session.local_rank()));
    if (session.first()) check_output_space(output, FramePlan{}, render_region(setup.options));
    // Before the build, which frees the scene's instances.
    dark_note = dark_scene_note(scene, setup.options.mode);
    renderer.emplace(scene, built_geometry(scene, progress), setup, &progress);
  });
  if (!all_went_well(session, mine, status, progress)) return status;

  const PixelRect region = render_region(setup.options);
  const DisplayTransform display = display_transform(cli, setup.options.mode);
  if (session.first() && !cli.quiet && dark_note)
    progress.message("clrt-mpi: note: " + cli.scene + ": " + *dark_note);
  // Only rank 0 knows the output: the tiles travel in the pixels it needs.
  std::string eight_bit_flag = renders_bytes(output, display) ? "1" : "0";
  session.broadcast(eight_bit_flag);
  const bool eight_bit = eight_bit_flag == "1";
  progress.start("rendering", region.pixel_count());
  const auto render_start = Clock::now();
  AnyImage image = mpi::farm_tiles(session, *renderer, region,
                                   mpi::cut_into_tiles(region, tile.width, tile.height),
                                   eight_bit, report.farm, progress);
  report.render_seconds = std::chrono::duration<double>(Clock::now() - render_start).count();
  RenderStats stats;
  renderer->report(stats);
  const std::vector<std::string> rank_stats = session.gather(stats.to_json().dump());
  if (!session.first()) return 0;

  mine = attempt([&] {
    progress.phase("writing");
    std::visit(
        [&](auto& pixels) {
          if (region.pixel_count() != std::uint64_t(setup.options.width) * setup.options.height)
            pixels.placement = Placement{static_cast<int>(region.x), static_cast<int>(region.y),
                                         setup.options.width, setup.options.height};
          if (!writes_nothing(output))
            write_image(output, pixels, image_write_options(cli.exr_pixel, display, "clrt-mpi"));
        },
        image);
  });
  if (mine.status != 0) {
    progress.finish();
    std::cerr << mine.message << "\n";
    return mine.status;
  }
  report.total_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  const std::string ranks =
      " from " + std::to_string(session.size()) + (session.size() == 1 ? " rank" : " ranks");
  const std::string where = output.is_stdout() ? "standard output" : output.path;
  progress.finish(writes_nothing(output) ? "rendered" + ranks + ", wrote nothing (--no-write)"
                                         : "wrote " + where + ranks);
  std::ostream& out = output.is_stdout() ? std::cerr : std::cout;
  if (cli.stats == StatsFormat::Json) out << report.to_json(rank_stats).dump(2) << "\n";
  if (cli.stats == StatsFormat::Text) out << report.to_text(rank_stats);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  clrt::remove_temporaries_on_signal();
  clrt::return_large_blocks_when_freed();
  clrt::mpi::TileSize tile;
  // The build writes the man page without an MPI job to start.
  if (clrt::asks_for_cli_docs({argv + 1, argv + argc}))
    return clrt::parse_arguments({argv + 1, argv + argc}, true, clrt::mpi::mpi_program_options(tile))
        .exit_code.value_or(2);
  clrt::mpi::Session session(argc, argv);
  const clrt::ParseResult parsed = clrt::parse_arguments(
      {argv + 1, argv + argc}, session.first(), clrt::mpi::mpi_program_options(tile));
  if (parsed.exit_code) return *parsed.exit_code;
  return run(session, parsed.options, tile);
}
