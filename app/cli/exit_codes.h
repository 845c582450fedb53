#pragma once
// docs/CLI.md, "Exit codes": 0 success, 1 the input or the render failed, 2 usage error.
namespace glint::cli {
enum ExitCode : int { kSuccess = 0, kFailure = 1, kUsage = 2 };
}
