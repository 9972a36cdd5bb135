// `orogen render DIR`: PNG frames and an animation of a run's outputs (src/commands/render_command).
#include <memory>
#include <string>

#include "commands/render_command.hpp"
#include "subcommand.hpp"

namespace orogen::cli {

Subcommand add_render(CLI::App& parent) {
  struct Options {
    RenderCommandOptions render;
    std::string dir;
    bool no_animation = false;  // a plain flag: CLI11 prints "{false}" after a negated one in --help
  };
  auto o = std::make_shared<Options>();
  RenderCommandOptions& render = o->render;
  auto* cmd = parent.add_subcommand("render", "draw the output steps of a run as PNG frames and an animation");
  cmd->add_option("dir", o->dir, "run folder")->required();
  cmd->add_option("--color", render.color,
                  "horizons | cluster | forces | field:NAME (field:max_rel_disp uses the hot colormap; forces "
                  "draws the contact forces of a run with output.contacts = true)")
      ->capture_default_str();
  cmd->add_option("--width", render.width_px, "picture width in pixels")
      ->capture_default_str()
      ->check(not_empty());  // the range is checked by render_command, with the other options
  cmd->add_option("--every", render.every, "draw every n-th output")->capture_default_str()->check(not_empty());
  cmd->add_option("--frames-dir", render.frames_name, "subfolder for the frames (the animation is named after it)")
      ->capture_default_str();
  cmd->add_option("--fps", render.fps, "animation frames per second")->capture_default_str()->check(not_empty());
  cmd->add_flag("--no-animation", o->no_animation, "only the PNG frames");
  cmd->add_flag("--vectors", render.vectors, "draw each disc's displacement over the last three outputs as an arrow");
  cmd->add_option("--vector-scale", render.vector_scale, "arrow length per unit displacement")->capture_default_str();
  cmd->add_option("--vector-stride", render.vector_stride, "draw every n-th disc's arrow")->capture_default_str();
  return {cmd, [o] {
            o->render.dir = o->dir;
            o->render.animation = !o->no_animation;
            return render_command(o->render);
          }};
}

}  // namespace orogen::cli
