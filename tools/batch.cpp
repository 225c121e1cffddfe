// Many files on every core (see batch.h).
#include "batch.h"

#include <drm_vcg/mesh_io.h>

#include <drmcodec/drmcodec.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <sys/stat.h>
#include <mutex>
#include <new>
#include <numeric>
#include <thread>

namespace drm {
namespace cli {

namespace fs = std::filesystem;

const std::vector<std::string>& batchOptionNames() {
    static const std::vector<std::string> names = {"-o", "--output-dir", "-j", "--jobs"};
    return names;
}

int jobsFrom(const Arguments& args) {
    if (args.has("-j") && args.has("--jobs")) throw UsageError("give -j or --jobs, not both");
    const std::string name = args.has("-j") ? "-j" : "--jobs";
    if (!args.has(name)) return int(std::max(1u, std::thread::hardware_concurrency()));
    const std::string text = args.value(name);
    errno = 0;
    char* end = nullptr;
    const long jobs = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno != 0 || jobs < 1 || jobs > 1024)
        throw UsageError(name + " needs a number of jobs from 1 to 1024, not '" + text + "'");
    return int(jobs);
}

drm::EncodeOptions perFileOptions(const drm::EncodeOptions& options, int jobs, size_t files) {
    drm::EncodeOptions perFile = options;
    if (std::min<size_t>(size_t(std::max(1, jobs)), files) > 1) perFile.threads = 1;
    return perFile;
}

void expectInputAndOutput(const Arguments& args, const std::string& command, const std::string& what) {
    std::error_code error;
    for (const std::string& path : args.positional)
        if (std::filesystem::is_directory(path, error))
            throw UsageError("'" + command + "' reads a folder (" + path + ") only with -o DIR (see 'drm help " +
                             command + "')");
    if (args.positional.size() > 2)
        throw UsageError("'" + command + "' takes " + what + ", or inputs and -o DIR, but got " +
                         std::to_string(args.positional.size()) + " names (see 'drm help " + command + "')");
    args.expectPositional(2, 2, what + " (or inputs and -o DIR)");
}

std::vector<std::string> collectInputs(const std::vector<std::string>& paths,
                                       const std::function<bool(const std::string&)>& wanted, const std::string& kinds) {
    std::vector<std::string> files;
    for (const std::string& path : paths) {
        std::error_code error;
        if (!fs::is_directory(path, error)) {
            files.push_back(path);  // a missing file fails on its own, the others go on
            continue;
        }
        std::vector<std::string> found;
        for (fs::directory_iterator it(path, error), end; !error && it != end; it.increment(error)) {
            std::error_code typeError;
            if (it->is_regular_file(typeError) && wanted(it->path().filename().string()))
                found.push_back(it->path().string());
        }
        if (error) throw drm::Error(drm::ErrorKind::Io, "cannot list " + path + ": " + error.message());
        if (found.empty()) throw drm::Error(drm::ErrorKind::InvalidInput, "no " + kinds + " in " + path);
        std::sort(found.begin(), found.end());
        files.insert(files.end(), found.begin(), found.end());
    }
    if (files.empty()) throw drm::Error(drm::ErrorKind::InvalidInput, "no " + kinds + " given");
    return files;
}

std::vector<std::string> outputPaths(const std::vector<std::string>& inputs, const std::string& dir,
                                     const std::string& extension) {
    std::error_code error;
    if (fs::exists(dir, error) && !fs::is_directory(dir, error))
        throw drm::Error(drm::ErrorKind::Io, "cannot write into " + dir + ": it is not a folder");
    std::vector<std::string> outputs;
    std::map<std::string, std::string> seen;  // output -> input
    for (const std::string& input : inputs) {
        const std::string output = (fs::path(dir) / (fileStem(input) + extension)).string();
        const auto [it, inserted] = seen.emplace(output, input);
        if (!inserted)
            throw drm::Error(drm::ErrorKind::InvalidInput, "two inputs would both be written to " + output + ": " + it->second + " and " + input +
                             " (nothing written)");
        outputs.push_back(output);
    }
    // No output may be any input (a link or hard link to another input
    // counts), nor, for OBJ, its library: writing there would replace it.
    std::set<std::pair<dev_t, ino_t>> inputFiles;
    for (const std::string& input : inputs) {
        struct stat info;
        if (::stat(input.c_str(), &info) == 0) inputFiles.emplace(info.st_dev, info.st_ino);
    }
    for (const std::string& output : outputs) {
        std::vector<std::string> written = {output};
        if (extension == ".obj") written.push_back(drm::vcgio::objLibraryPath(output));
        for (const std::string& path : written) {
            struct stat info;
            if (::stat(path.c_str(), &info) == 0 && inputFiles.count({info.st_dev, info.st_ino}))
                throw drm::Error(drm::ErrorKind::InvalidInput, "cannot write " + path + ": it is one of the inputs, which would be replaced (nothing written)");
        }
    }
    fs::create_directories(dir, error);
    if (error) throw drm::Error(drm::ErrorKind::Io, "cannot create the folder " + dir + ": " + error.message());
    return outputs;
}

uint64_t fileBytes(const std::string& path) {
    std::error_code error;
    const uintmax_t size = fs::file_size(path, error);
    return error ? 0 : uint64_t(size);
}

std::string namingFile(const std::string& input, const std::string& message) {
    return message.find(input) != std::string::npos ? message : input + ": " + message;
}

namespace {

std::string oneLine(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    return text;
}

}  // namespace

void runBatch(const BatchWords& words, const std::vector<BatchFile>& files, int jobs,
              const std::function<FileOutcome(const BatchFile&)>& work) {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();

    // Largest first: the long files start early and the short ones fill in.
    std::vector<size_t> order(files.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return files[a].bytesIn > files[b].bytesIn; });

    std::mutex printing;
    std::atomic<size_t> next{0};
    size_t finished = 0;
    uint64_t bytesIn = 0, bytesOut = 0;
    std::vector<std::string> failed;  // inputs, in the order they failed

    auto worker = [&]() {
        for (size_t taken = next++; taken < order.size(); taken = next++) {
            const BatchFile& file = files[order[taken]];
            FileOutcome outcome;
            try {
                outcome = work(file);
            } catch (const std::bad_alloc&) {
                outcome.ok = false;
                outcome.error = namingFile(file.input, "out of memory");
            } catch (const std::exception& e) {
                outcome.ok = false;
                outcome.error = namingFile(file.input, e.what());
            }
            std::lock_guard<std::mutex> lock(printing);
            ++finished;
            for (const std::string& note : outcome.notes)
                std::fprintf(stderr, "drm: note: %s: %s\n", file.input.c_str(), oneLine(note).c_str());
            if (outcome.ok) {
                bytesIn += file.bytesIn;
                bytesOut += outcome.bytesOut;
                std::printf("[%zu/%zu] %s\n", finished, files.size(), oneLine(outcome.line).c_str());
                std::fflush(stdout);
            } else {
                failed.push_back(file.input);
                std::fflush(stdout);
                std::fprintf(stderr, "drm: error: %s\n", oneLine(namingFile(file.input, outcome.error)).c_str());
            }
        }
    };
    const size_t threads = std::min(size_t(std::max(1, jobs)), files.size());
    std::vector<std::thread> pool;
    for (size_t t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();  // this thread is a worker too
    for (std::thread& thread : pool) thread.join();

    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    const size_t succeeded = files.size() - failed.size();
    std::string ratio = "-";
    if (bytesIn > 0 && bytesOut > 0) {
        ratio = words.expands ? "expansion 1:" + fixed(double(bytesOut) / double(bytesIn), 2)
                              : "compression " + fixed(double(bytesIn) / double(bytesOut), 2) + ":1";
    }
    std::printf("%s %zu of %zu files%s: %llu bytes in -> %llu %s, %s, %s s wall, %zu job%s\n", words.done, succeeded,
                files.size(), failed.empty() ? "" : (" (" + std::to_string(failed.size()) + " failed)").c_str(),
                (unsigned long long)bytesIn, (unsigned long long)bytesOut, words.outBytes, ratio.c_str(),
                fixed(seconds, 3).c_str(), threads, threads == 1 ? "" : "s");
    std::fflush(stdout);
    if (!failed.empty()) {
        std::string list;
        for (size_t i = 0; i < failed.size() && i < 10; ++i) list += (i ? ", " : "") + failed[i];
        if (failed.size() > 10) list += ", ...";
        throw drm::Error(drm::ErrorKind::InvalidInput, std::to_string(failed.size()) + " of " + std::to_string(files.size()) +
                         " files failed: " + list);
    }
}

}  // namespace cli
}  // namespace drm
