// `orogen config [--markdown]`: the default configuration, every key documented (src/config/schema).
#include <iostream>
#include <memory>
#include <optional>

#include "config/config.hpp"
#include "config/schema.hpp"
#include "subcommand.hpp"

namespace orogen::cli {

Subcommand add_config(CLI::App& parent) {
  auto markdown = std::make_shared<bool>(false);
  auto* cmd = parent.add_subcommand("config", "print the default configuration (every key, documented)");
  cmd->add_flag("--markdown", *markdown, "print the key reference as Markdown tables instead");
  return {cmd, [markdown] {
            std::cout << (*markdown ? reference_markdown() : Config::load(std::nullopt, {}).to_toml());
            return 0;
          }};
}

}  // namespace orogen::cli
