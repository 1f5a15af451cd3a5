#pragma once
// The tool subcommands `mpdem generate`, `mpdem agglomerate`, `mpdem mesh`, `mpdem clump` and `mpdem validate`. Each
// registers itself on the app; when the command line selects it, its callback stores the work in `action`, which main()
// runs inside its error handling (so an InputError becomes exit status 2 like everywhere else).
#include <functional>

#include <CLI/CLI.hpp>

namespace mpdem::cli {

using ToolAction = std::function<int()>;

void add_generate_command(CLI::App& app, ToolAction& action);
void add_mesh_command(CLI::App& app, ToolAction& action);
void add_clump_command(CLI::App& app, ToolAction& action);  // docs/tools.md "mpdem clump"
// docs/tools.md "mpdem agglomerate"; under `app` (the command line, or `generate`); returns it.
CLI::App* add_agglomerate_command(CLI::App& app, ToolAction& action);
void add_validate_command(CLI::App& app, ToolAction& action);  // `mpdem validate` (docs/validation.md)

}  // namespace mpdem::cli
