// The `drm` subcommands: one source file each (cmd_*.cpp), one entry each in
// the table main.cpp dispatches on.
#ifndef DRM_TOOLS_COMMANDS_H
#define DRM_TOOLS_COMMANDS_H

#include <string>
#include <vector>

namespace drm {
namespace cli {

struct Command {
    const char* name;
    const char* summary;  // one line for `drm --help`
    const char* help;     // the full text of `drm help NAME`, with help_text.h's {names}
    // Returns the exit code; throws drm::Error, UsageError or std::exception.
    int (*run)(const std::vector<std::string>& args);
};

int runEncode(const std::vector<std::string>& args);
int runDecode(const std::vector<std::string>& args);
int runInfo(const std::vector<std::string>& args);
int runVerify(const std::vector<std::string>& args);
int runRanks(const std::vector<std::string>& args);
int runRender(const std::vector<std::string>& args);
int runBench(const std::vector<std::string>& args);

extern const char* const kEncodeHelp;
extern const char* const kDecodeHelp;
extern const char* const kInfoHelp;
extern const char* const kVerifyHelp;
extern const char* const kRanksHelp;
extern const char* const kRenderHelp;
extern const char* const kBenchHelp;

}  // namespace cli
}  // namespace drm

#endif  // DRM_TOOLS_COMMANDS_H
