// `drm`: encode, decode, inspect, verify, picture and benchmark .drm files.
//
// Exit codes: 0 success, 1 failure, 2 usage error. A failure prints exactly
// one line on stderr, starting "drm: error: ".
#include "cli.h"
#include "commands.h"
#include "help_text.h"

#include <drmcodec/drmcodec.h>

#include <cstdio>
#include <cstring>
#include <new>
#include <string>
#include <vector>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace {

// The codec builds and drops large tables again and again (each encoder
// trial, each half-edge table rebuild). By default glibc maps blocks over
// 128 KiB (a threshold that rises only as they are freed) from the kernel
// one by one and gives them back when freed, so the next table is faulted
// in page by page all over again, and the kernel's faulting and zeroing of
// fresh pages takes a tenth of an encoding. Blocks up to the largest
// threshold glibc allows come from the heap instead, and the heap keeps
// what is freed for the next table. Peak memory grows a little, as blocks
// freed early stay beside later ones (docs/tuning.md, "The drm tool").
// The heap grows 16 MiB at a time, so that the huge-page
// advice given with its large blocks (huge_pages.cpp) covers what smaller
// blocks take from it next. Process-wide, so the tool's choice, not the
// library's (as are cli.cpp's shareOneMallocArena, for one mesh's threads,
// and mapLargeBlocksApart, which lowers the threshold again for one large
// mesh).
void keepFreedMemoryForReuse() {
#ifdef __GLIBC__
    mallopt(M_MMAP_THRESHOLD, 32 << 20);  // glibc's maximum on 64-bit systems
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    mallopt(M_TOP_PAD, 16 << 20);  // virtual: a page costs memory once touched
#endif
}

using drm::cli::Command;

const Command kCommands[] = {
    {"encode", "compress a mesh (PLY, OBJ, OFF, STL) into a .drm file", drm::cli::kEncodeHelp, drm::cli::runEncode},
    {"decode", "decompress a .drm file into a PLY mesh", drm::cli::kDecodeHelp, drm::cli::runDecode},
    {"info", "show what a .drm file holds (sizes, bits per vertex, ranks)", drm::cli::kInfoHelp, drm::cli::runInfo},
    {"verify", "encode and decode a mesh in memory and check it is lossless", drm::cli::kVerifyHelp, drm::cli::runVerify},
    {"ranks", "write a mesh with faces coloured by their distance rank", drm::cli::kRanksHelp, drm::cli::runRanks},
    {"render", "draw a mesh or .drm file into a PNG picture, optionally coloured by rank", drm::cli::kRenderHelp, drm::cli::runRender},
    {"bench", "compress many meshes and tabulate rates and times", drm::cli::kBenchHelp, drm::cli::runBench},
};

const Command* findCommand(const std::string& name) {
    for (const Command& command : kCommands)
        if (name == command.name) return &command;
    return nullptr;
}

void printOverview() {
    std::printf("drm %s: distance-ranked connectivity compression of triangle meshes\n\n", drm::version());
    std::printf("usage: drm COMMAND [ARGS...]\n\ncommands:\n");
    for (const Command& command : kCommands) std::printf("  %-8s %s\n", command.name, command.summary);
    std::printf("\n'drm help COMMAND' (or 'drm COMMAND --help') describes a command.\n"
                "'drm --version' prints the version.\n");
}

std::string oneLine(std::string message) {
    for (char& c : message)
        if (c == '\n' || c == '\r') c = ' ';
    return message;
}

int fail(int code, const std::string& message) {
    std::fprintf(stderr, "drm: error: %s\n", oneLine(message).c_str());
    return code;
}

int dispatch(const std::vector<std::string>& args) {
    if (args.empty()) throw drm::cli::UsageError("no command given (see 'drm --help')");
    const std::string& first = args[0];
    if (first == "--help" || first == "-h") {
        printOverview();
        return 0;
    }
    if (first == "--version") {
        std::printf("drm %s\n", drm::version());
        return 0;
    }
    if (first == "help") {
        if (args.size() == 1) {
            printOverview();
            return 0;
        }
        const Command* command = findCommand(args[1]);
        if (!command || args.size() > 2)
            throw drm::cli::UsageError("no help for '" + args[1] + "' (commands: encode, decode, info, verify, ranks, render, bench)");
        std::fputs(drm::cli::expandHelp(command->help).c_str(), stdout);
        return 0;
    }
    const Command* command = findCommand(first);
    if (!command) throw drm::cli::UsageError("unknown command '" + first + "' (see 'drm --help')");
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    for (const std::string& arg : rest) {
        if (arg == "--") break;
        if (arg == "--help" || arg == "-h") {
            std::fputs(drm::cli::expandHelp(command->help).c_str(), stdout);
            return 0;
        }
    }
    return command->run(rest);
}

}  // namespace

int main(int argc, char** argv) {
    keepFreedMemoryForReuse();
    try {
        const int code = dispatch(std::vector<std::string>(argv + 1, argv + argc));
        // Output that never reached its destination (a full disk, a closed
        // pipe) is a failure, not a success.
        if (std::fflush(stdout) != 0 || std::ferror(stdout)) return fail(1, "cannot write to standard output");
        return code;
    } catch (const drm::cli::UsageError& e) {
        return fail(2, e.what());
    } catch (const drm::Error& e) {
        return fail(1, e.what());
    } catch (const std::bad_alloc&) {
        return fail(1, "out of memory");
    } catch (const std::exception& e) {
        return fail(1, e.what());
    } catch (...) {
        return fail(1, "internal error: an unknown exception");
    }
}
