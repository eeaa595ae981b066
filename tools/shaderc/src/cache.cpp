// The permutation cache (--cache-dir): see PermutationCache in shaderc.h and docs/permutations.md.
#include "shaderc.h"

#include <xxhash.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <thread>

namespace ffxdof::shaderc {
namespace {

constexpr uint32_t kSpirvMagic = 0x07230203;
constexpr size_t kSpirvHeaderWords = 5;

std::string hex(const XXH128_hash_t& hash) {
    char text[33];
    std::snprintf(text, sizeof(text), "%016llx%016llx", static_cast<unsigned long long>(hash.high64),
                  static_cast<unsigned long long>(hash.low64));
    return text;
}

// This executable's bytes: glslang and SPIRV-Tools are linked into it, so a new build of either (or of the
// tool) files its permutations apart from the old one's.
std::string executableDigest() {
#if defined(__linux__)
    const fs::path self = "/proc/self/exe";
    std::ifstream file(self, std::ios::binary);
    if (!file) throw Error("--cache-dir: cannot read this executable (" + self.string() + ") to key the cache");
    XXH3_state_t* state = XXH3_createState();
    if (!state) throw Error("--cache-dir: out of memory");
    XXH3_128bits_reset(state);
    std::vector<char> buffer(size_t(1) << 16);
    while (file) {
        file.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
        XXH3_128bits_update(state, buffer.data(), static_cast<size_t>(file.gcount()));
    }
    const std::string digest = hex(XXH3_128bits_digest(state));
    XXH3_freeState(state);
    return digest;
#else
    throw Error(
        "--cache-dir is supported on Linux only: the cache is keyed by this executable's bytes, read from "
        "/proc/self/exe");
#endif
}

}  // namespace

PermutationCache::PermutationCache(const fs::path& folder) : folder_(folder), toolDigest_(executableDigest()) {
    std::error_code ec;
    fs::create_directories(folder_, ec);
    if (!fs::is_directory(folder_, ec)) throw Error("--cache-dir: cannot create the folder " + folder_.string());
}

std::string PermutationCache::key(const std::string& identity, const std::string& preprocessed) const {
    XXH3_state_t* state = XXH3_createState();
    if (!state) throw Error("--cache-dir: out of memory");
    XXH3_128bits_reset(state);
    // Lengths first, so that no two different (identity, source) pairs hash the same bytes.
    const uint64_t lengths[3] = {toolDigest_.size(), identity.size(), preprocessed.size()};
    XXH3_128bits_update(state, lengths, sizeof(lengths));
    XXH3_128bits_update(state, toolDigest_.data(), toolDigest_.size());
    XXH3_128bits_update(state, identity.data(), identity.size());
    XXH3_128bits_update(state, preprocessed.data(), preprocessed.size());
    const std::string result = hex(XXH3_128bits_digest(state));
    XXH3_freeState(state);
    return result;
}

std::vector<uint32_t> PermutationCache::find(const std::string& key) {
    std::ifstream file(folder_ / (key + ".spv"), std::ios::binary);
    std::vector<uint32_t> words;
    if (file) {
        const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
        if (file.good() || file.eof()) {
            if (bytes.size() % 4 == 0 && bytes.size() / 4 > kSpirvHeaderWords) {
                words.resize(bytes.size() / 4);
                std::memcpy(words.data(), bytes.data(), bytes.size());
                if (words[0] != kSpirvMagic) words.clear();
            }
        }
    }
    ++(words.empty() ? misses_ : hits_);
    return words;
}

void PermutationCache::store(const std::string& key, const std::vector<uint32_t>& spirv) {
    // Written under a name no other writer uses, then renamed: a reader sees a whole file or none.
    std::ostringstream temporaryName;
    temporaryName << key << ".tmp." << std::random_device{}() << "." << std::this_thread::get_id();
    const fs::path temporary = folder_ / temporaryName.str();
    const fs::path final = folder_ / (key + ".spv");
    bool written = false;
    {
        std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
        file.write(reinterpret_cast<const char*>(spirv.data()), static_cast<std::streamsize>(spirv.size() * 4));
        written = static_cast<bool>(file.flush());
    }
    std::error_code ec;
    if (written) fs::rename(temporary, final, ec);
    if (!written || ec) {
        fs::remove(temporary, ec);
        if (!warned_.exchange(true)) {
            std::fprintf(stderr,
                         "ffx-dof-shaderc: warning: cannot write to the cache folder %s; compiling without it\n",
                         folder_.string().c_str());
        }
    }
}

}  // namespace ffxdof::shaderc
