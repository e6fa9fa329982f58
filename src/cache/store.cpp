#include "cache/store.h"

#include "cache/sha256.h"
#include "spec/error.h"

#include <fmt/format.h>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#if __has_include(<link.h>)
#include <elf.h>
#include <link.h>
#define IMPACT_HAS_DL_ITERATE_PHDR 1
#endif

#include <algorithm>
#include <atomic>
#include <cctype>
#include <limits>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <string_view>
#include <vector>

namespace impact::cache {
namespace fs = std::filesystem;

std::string packed(const std::map<std::string, std::string>& files)
{
    std::string out;
    for (const auto& [path, contents] : files)
        out += fmt::format("{} {}\n{}{}", path.size(), contents.size(), path, contents);
    return out;
}

std::optional<std::map<std::string, std::string>> unpacked(const std::string& text)
{
    std::map<std::string, std::string> files;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t line = text.find('\n', at);
        if (line == std::string::npos)
            return std::nullopt;
        std::istringstream header(text.substr(at, line - at));
        std::size_t path_size = 0, contents_size = 0;
        if (!(header >> path_size >> contents_size) || line + 1 + path_size + contents_size > text.size())
            return std::nullopt;
        files[text.substr(line + 1, path_size)] = text.substr(line + 1 + path_size, contents_size);
        at = line + 1 + path_size + contents_size;
    }
    return files;
}


namespace {

constexpr const char* tag_name = "CACHEDIR.TAG";
// The standard's signature line, then who made the folder.
constexpr const char* tag_text =
    "Signature: 8a477f597d28d172789f06886806bc55\n"
    "# This file is a cache directory tag created by Impact (impact regenerate).\n"
    "# For information about cache directory tags, see https://bford.info/cachedir/\n"
    "# Everything here can be removed: Impact computes it again when needed.\n";
constexpr const char* entry_header = "impact cache entry 1\n";

const std::regex& entry_name()
{
    static const std::regex r("[0-9a-f]{64}\\.entry");
    return r;
}

const std::regex& temporary_name()
{
    static const std::regex r("([0-9a-f]{64}\\.entry|CACHEDIR\\.TAG)\\.tmp-[0-9]+-[0-9]+");
    return r;
}

std::optional<std::string> read_whole(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return std::nullopt;
    std::ostringstream bytes;
    bytes << in.rdbuf();
    if (in.bad())
        return std::nullopt;
    return bytes.str();
}

// A file mapped read-only: an entry holds the whole output (tens of megabytes), read on
// every warm regeneration, and is hashed where the page cache holds it, then copied once.
// Impact never changes an entry in place (it writes a new one and renames it over), so a
// mapping stays whole while another run replaces or trims the entry.
class mapped_file {
public:
    explicit mapped_file(const fs::path& path)
    {
        const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
        if (fd < 0)
            return;
        struct stat st {};
        const bool regular = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
        if (regular) {
            size_ = static_cast<std::size_t>(st.st_size);
            if (size_ == 0)
                ok_ = true;
            else if (void* at = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd, 0); at != MAP_FAILED) {
                data_ = static_cast<const char*>(at);
                ok_ = true;
            }
        }
        ::close(fd);
        // A file system that cannot map files (some FUSE ones): read it instead.
        if (regular && !ok_)
            if (std::optional<std::string> read = read_whole(path)) {
                copy_ = std::move(*read);
                ok_ = true;
            }
    }
    ~mapped_file()
    {
        if (data_)
            ::munmap(const_cast<char*>(data_), size_);
    }
    mapped_file(const mapped_file&) = delete;
    mapped_file& operator=(const mapped_file&) = delete;

    explicit operator bool() const { return ok_; }
    std::string_view bytes() const { return data_ ? std::string_view(data_, size_) : std::string_view(copy_); }

private:
    std::string copy_;
    const char* data_ = nullptr;
    std::size_t size_ = 0;
    bool ok_ = false;
};

// Writes `contents` to a temporary file beside `path` and renames it into place, so
// that a reader sees the previous file or the whole new one. False when it could not.
bool write_atomically(const fs::path& path, const std::string& contents)
{
    static std::atomic<unsigned> counter{0};
    const fs::path temporary =
        path.string() + fmt::format(".tmp-{}-{}", static_cast<long>(::getpid()), counter++);
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out << contents;
        out.close();
        if (!out) {
            std::error_code ignored;
            fs::remove(temporary, ignored);
            return false;
        }
    }
    std::error_code failed;
    fs::rename(temporary, path, failed);
    if (failed) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        return false;
    }
    return true;
}

// What in `folder` is not the store's, or nothing when all of it is.
std::optional<std::string> foreign_file(const fs::path& folder)
{
    bool has_tag = false, has_other = false;
    for (const auto& entry : fs::directory_iterator(folder)) {
        const std::string name = entry.path().filename().string();
        const fs::file_status status = entry.symlink_status();
        if (!fs::is_regular_file(status))
            return name;
        if (name == tag_name) {
            const auto text = read_whole(entry.path());
            if (!text || text->find("created by Impact") == std::string::npos)
                return name;
            has_tag = true;
        } else if (name.rfind(std::string(tag_name) + ".tmp-", 0) == 0 && std::regex_match(name, temporary_name())) {
            // Another regeneration tagging the same new folder at this moment: its tag is
            // written before any entry, so this is not yet a reason to refuse the folder.
        } else if (std::regex_match(name, entry_name()) || std::regex_match(name, temporary_name())) {
            has_other = true;
        } else {
            return name;
        }
    }
    // Files named like entries in a folder Impact did not tag are not known to be Impact's.
    if (has_other && !has_tag)
        return std::string("files without Impact's CACHEDIR.TAG");
    return std::nullopt;
}

} // namespace

fs::path default_folder()
{
    const char* xdg = std::getenv("XDG_CACHE_HOME");
    if (xdg && *xdg && fs::path(xdg).is_absolute())
        return fs::path(xdg) / "impact";
    const char* home = std::getenv("HOME");
    if (!home || !*home)
        throw error({"impact", 0, 0}, "neither XDG_CACHE_HOME nor HOME is set: give --cache DIR or --no-cache");
    return fs::path(home) / ".cache" / "impact";
}

namespace {

#ifdef IMPACT_HAS_DL_ITERATE_PHDR
// The main program's NT_GNU_BUILD_ID note, read from its loaded PT_NOTE segments: the
// linker's hash of the whole executable, so another build has another one. Empty when
// the program was linked without one (--build-id=none).
int find_build_id(dl_phdr_info* info, std::size_t, void* out)
{
    auto& id = *static_cast<std::string*>(out);
    // The first object is the main program; its notes are all that are wanted.
    for (ElfW(Half) i = 0; i < info->dlpi_phnum; ++i) {
        const ElfW(Phdr)& segment = info->dlpi_phdr[i];
        if (segment.p_type != PT_NOTE)
            continue;
        const char* at = reinterpret_cast<const char*>(info->dlpi_addr + segment.p_vaddr);
        const char* const end = at + segment.p_memsz;
        const auto aligned = [](std::size_t n) { return (n + 3) & ~std::size_t{3}; };
        while (at + sizeof(ElfW(Nhdr)) <= end) {
            const auto* note = reinterpret_cast<const ElfW(Nhdr)*>(at);
            const char* name = at + sizeof(ElfW(Nhdr));
            const char* desc = name + aligned(note->n_namesz);
            const char* next = desc + aligned(note->n_descsz);
            if (next > end)
                break;
            if (note->n_type == NT_GNU_BUILD_ID && std::string_view(name, note->n_namesz) == std::string_view("GNU", 4)) {
                id.assign(desc, note->n_descsz);
                return 1;
            }
            at = next;
        }
    }
    return 1;
}
#endif

std::string build_id()
{
    std::string id;
#ifdef IMPACT_HAS_DL_ITERATE_PHDR
    dl_iterate_phdr(find_build_id, &id);
#endif
    std::string hex;
    for (unsigned char c : id)
        hex += fmt::format("{:02x}", c);
    return hex;
}

} // namespace

const std::string& program_fingerprint()
{
    static const std::string fingerprint = [] {
        // The linker's build ID when there is one: reading it costs nothing, where hashing
        // the executable reads all of it (tens of megabytes with debugging information).
        if (const std::string id = build_id(); !id.empty())
            return "build " + id;
        const auto bytes = read_whole("/proc/self/exe");
        // Unreadable: a fingerprint of this process alone, so that nothing is reused.
        if (!bytes || bytes->empty())
            return fmt::format("unknown program, process {}", static_cast<long>(::getpid()));
        return sha256_hex(*bytes);
    }();
    return fingerprint;
}

std::optional<std::uintmax_t> parse_size(const std::string& text)
{
    std::size_t digits = 0;
    while (digits < text.size() && text[digits] >= '0' && text[digits] <= '9')
        ++digits;
    if (digits == 0 || digits > 19)
        return std::nullopt;
    std::string unit = text.substr(digits);
    for (char& c : unit)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    int shift = 0;
    if (!unit.empty() && std::string("KMGT").find(unit[0]) != std::string::npos) {
        shift = 10 * (1 + static_cast<int>(std::string("KMGT").find(unit[0])));
        unit.erase(0, 1);
        if (unit == "IB")
            unit.clear();
    }
    if (!unit.empty() && unit != "B")
        return std::nullopt;
    const std::uintmax_t n = std::stoull(text.substr(0, digits));
    if (shift > 0 && n > (std::numeric_limits<std::uintmax_t>::max() >> shift))
        return std::nullopt;
    return n << shift;
}

bool is_store_file_name(const std::string& name)
{
    return std::regex_match(name, entry_name()) || std::regex_match(name, temporary_name());
}

store::store(fs::path folder, std::uintmax_t limit) : folder_(std::move(folder)), limit_(limit)
{
    const std::string given = folder_.string();
    std::error_code failed;
    const fs::file_status status = fs::status(folder_, failed);
    if (fs::exists(status) && !fs::is_directory(status))
        throw error({given, 0, 0}, "the cache folder is a file, not a folder (give another --cache DIR)");
    if (!fs::exists(status)) {
        fs::create_directories(folder_, failed);
        if (failed)
            throw error({given, 0, 0}, fmt::format("cannot create the cache folder: {}", failed.message()));
    }
    if (const auto foreign = foreign_file(folder_))
        throw error({given, 0, 0},
                    fmt::format("the cache folder holds what is not Impact's cache ({}); Impact keeps its cache "
                                "only in an empty folder or its own (give another --cache DIR)",
                                *foreign));
    if (!fs::exists(folder_ / tag_name) && !write_atomically(folder_ / tag_name, tag_text))
        throw error({given, 0, 0}, "cannot write into the cache folder");
}

fs::path store::entry_path(const std::string& kind, const std::string& key) const
{
    return folder_ / (sha256().add(kind).add(std::string_view("\n", 1)).add(key).hex() + ".entry");
}

std::optional<std::string> store::get(const std::string& kind, const std::string& key)
{
    const fs::path path = entry_path(kind, key);
    const mapped_file file(path);
    auto count = [&](bool hit, bool rejected) {
        const std::lock_guard<std::mutex> lock(mutex_);
        counts& c = counts_[kind];
        (hit ? c.hits : c.misses)++;
        c.rejected += rejected ? 1 : 0;
    };
    if (!file) {
        count(false, false);
        return std::nullopt;
    }
    // The header: what it is, which entry, the payload's length and SHA-256.
    const std::string_view bytes = file.bytes();
    std::size_t at = 0;
    auto line = [&]() -> std::string_view {
        const std::size_t end = bytes.find('\n', at);
        if (end == std::string_view::npos) {
            at = bytes.size() + 1;
            return {};
        }
        const std::string_view text = bytes.substr(at, end - at);
        at = end + 1;
        return text;
    };
    const std::string_view header = line(), name_line = line(), length_line = line(), hash_line = line(),
                           blank = line();
    bool whole = at <= bytes.size() && std::string(header) + "\n" == entry_header &&
                 name_line == "entry " + path.filename().string() && blank.empty();
    std::string payload;
    if (whole) {
        const std::string_view stored = bytes.substr(at);
        whole = length_line == "length " + std::to_string(stored.size()) &&
                hash_line == "sha256 " + sha256_hex(stored);
        if (whole)
            payload.assign(stored);
    }
    if (!whole) {
        count(false, true);
        return std::nullopt;
    }
    // Used now: the last to be evicted.
    std::error_code ignored;
    fs::last_write_time(path, fs::file_time_type::clock::now(), ignored);
    count(true, false);
    return payload;
}

void store::put(const std::string& kind, const std::string& key, const std::string& value)
{
    const fs::path path = entry_path(kind, key);
    const std::string contents = fmt::format("{}entry {}\nlength {}\nsha256 {}\n\n", entry_header,
                                             path.filename().string(), value.size(), sha256_hex(value)) +
                                 value;
    write_atomically(path, contents);
}

void store::trim()
{
    struct found {
        fs::path path;
        fs::file_time_type when;
        std::uintmax_t size;
    };
    std::vector<found> entries;
    std::uintmax_t total = 0;
    const auto hour_ago = fs::file_time_type::clock::now() - std::chrono::hours(1);
    std::error_code failed;
    for (const auto& entry : fs::directory_iterator(folder_, failed)) {
        std::error_code ignored;
        const std::string name = entry.path().filename().string();
        if (!entry.is_regular_file(ignored) || entry.is_symlink(ignored))
            continue;
        const auto when = entry.last_write_time(ignored);
        if (ignored)
            continue;
        if (std::regex_match(name, temporary_name())) {
            if (when < hour_ago)
                fs::remove(entry.path(), ignored);
        } else if (std::regex_match(name, entry_name())) {
            const std::uintmax_t size = entry.file_size(ignored);
            if (ignored)
                continue;
            entries.push_back({entry.path(), when, size});
            total += size;
        }
    }
    std::sort(entries.begin(), entries.end(), [](const found& a, const found& b) {
        return a.when != b.when ? a.when < b.when : a.path < b.path;
    });
    for (const found& e : entries) {
        if (total <= limit_)
            break;
        std::error_code ignored;
        if (fs::remove(e.path, ignored))
            total -= e.size;
    }
}

std::map<std::string, counts> store::statistics() const
{
    const std::lock_guard<std::mutex> lock(mutex_);
    return counts_;
}

void store::add_counts(const std::string& kind, const counts& more)
{
    const std::lock_guard<std::mutex> lock(mutex_);
    counts& c = counts_[kind];
    c.hits += more.hits;
    c.misses += more.misses;
    c.rejected += more.rejected;
    c.unusable += more.unusable;
}

void store::unusable(const std::string& kind)
{
    const std::lock_guard<std::mutex> lock(mutex_);
    counts& c = counts_[kind];
    if (c.hits > 0) {
        --c.hits;
        ++c.misses;
        ++c.unusable;
    }
}

} // namespace impact::cache
