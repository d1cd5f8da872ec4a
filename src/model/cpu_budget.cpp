#include "model/cpu_budget.hpp"

#include <sched.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <thread>

namespace vi {
namespace {

std::string_view trimmed(std::string_view s) {
    const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
    while (!s.empty() && space(s.front())) s.remove_prefix(1);
    while (!s.empty() && space(s.back())) s.remove_suffix(1);
    return s;
}

// A whole decimal number filling all of s, or nullopt.
std::optional<long long> whole_number(std::string_view s) {
    s = trimmed(s);
    long long v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size() || s.empty()) return std::nullopt;
    return v;
}

std::vector<std::string_view> split(std::string_view s, char sep) {
    std::vector<std::string_view> out;
    for (std::size_t at = 0; at <= s.size();) {
        const std::size_t next = std::min(s.find(sep, at), s.size());
        out.push_back(s.substr(at, next - at));
        at = next + 1;
    }
    return out;
}

std::vector<std::string_view> lines_of(std::string_view text) {
    std::vector<std::string_view> out;
    for (std::string_view line : split(text, '\n')) {
        if (!trimmed(line).empty()) out.push_back(line);
    }
    return out;
}

// mountinfo escapes space, tab, newline and backslash in paths as \ooo (octal).
std::string unescaped(std::string_view s) {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const bool octal = s[i] == '\\' && i + 3 < s.size() &&
                           std::all_of(s.begin() + static_cast<std::ptrdiff_t>(i) + 1,
                                       s.begin() + static_cast<std::ptrdiff_t>(i) + 4,
                                       [](char c) { return c >= '0' && c <= '7'; });
        if (octal) {
            out += static_cast<char>((s[i + 1] - '0') * 64 + (s[i + 2] - '0') * 8 + (s[i + 3] - '0'));
            i += 3;
        } else {
            out += s[i];
        }
    }
    return out;
}

// One line of /proc/self/mountinfo: "<id> <parent> <maj:min> <root> <mount point> <options>
// [optional fields] - <fs type> <source> <super options>".
struct Mount {
    std::string root;
    std::string point;
    std::string type;
    std::vector<std::string_view> super_options;
};

std::optional<Mount> parse_mount(std::string_view line) {
    std::vector<std::string_view> f;
    for (std::string_view w : split(trimmed(line), ' ')) {
        if (!w.empty()) f.push_back(w);
    }
    const auto dash = std::find(f.begin(), f.end(), std::string_view("-"));
    if (f.size() < 6 || dash == f.end() || std::distance(dash, f.end()) < 3) return std::nullopt;
    Mount m;
    m.root = unescaped(f[3]);
    m.point = unescaped(f[4]);
    m.type = std::string(*(dash + 1));
    m.super_options = split(*(dash + 3), ',');
    return m;
}

// The folder of cgroup `path` under a mount of its hierarchy whose root is `root`: the path below
// the mount's root, appended to the mount point. A path outside the mounted part (a container that
// sees only its own subtree without a cgroup namespace) maps to the mount point itself.
std::string folder_of(const Mount& m, const std::string& path) {
    std::string rel;
    if (m.root == "/") {
        rel = path;
    } else if (path.compare(0, m.root.size(), m.root) == 0 &&
               (path.size() == m.root.size() || path[m.root.size()] == '/')) {
        rel = path.substr(m.root.size());
    }
    std::string dir = m.point;
    while (dir.size() > 1 && dir.back() == '/') dir.pop_back();
    if (!rel.empty() && rel != "/") dir += (rel.front() == '/' ? "" : "/") + rel;
    while (dir.size() > 1 && dir.back() == '/') dir.pop_back();
    return dir;
}

// `leaf` and every parent folder up to and including `top` (leaf lies under top).
void add_up_to(std::vector<CgroupCpuDir>& out, std::string leaf, const std::string& top, int version) {
    // One step per path component: at most leaf.size() steps.
    for (std::size_t steps = 0; steps <= leaf.size() + 1; ++steps) {
        out.push_back({leaf, version});
        if (leaf.size() <= top.size()) return;
        const std::size_t slash = leaf.find_last_of('/');
        if (slash == std::string::npos || slash < top.size()) return;
        leaf.erase(slash == 0 ? 1 : slash);
    }
}

std::optional<std::string> read_whole_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream s;
    s << in.rdbuf();
    if (in.bad()) return std::nullopt;
    return s.str();
}

}  // namespace

std::optional<double> cgroup2_cpu_limit(std::string_view cpu_max) {
    const std::string_view line = trimmed(cpu_max.substr(0, cpu_max.find('\n')));
    const std::size_t space = line.find(' ');
    if (space == std::string_view::npos) return std::nullopt;
    if (trimmed(line.substr(0, space)) == "max") return std::nullopt;
    const auto quota = whole_number(line.substr(0, space));
    const auto period = whole_number(line.substr(space + 1));
    if (!quota || !period || *quota <= 0 || *period <= 0) return std::nullopt;
    return static_cast<double>(*quota) / static_cast<double>(*period);
}

std::optional<double> cgroup1_cpu_limit(std::string_view quota_us, std::string_view period_us) {
    const auto quota = whole_number(quota_us);
    const auto period = whole_number(period_us);
    if (!quota || !period || *quota <= 0 || *period <= 0) return std::nullopt;
    return static_cast<double>(*quota) / static_cast<double>(*period);
}

int cpus_for_limit(double cpus) {
    if (!(cpus > 1.0)) return 1;
    // A 1e-9 slack: 200000/100000 is exactly 2, but a quota computed from a float could be 2.0000000001.
    return static_cast<int>(std::min(std::ceil(cpus - 1e-9), 1e6));
}

std::vector<CgroupCpuDir> cgroup_cpu_dirs(std::string_view proc_cgroup, std::string_view mountinfo) {
    std::optional<std::string> v2_path;
    std::optional<std::string> v1_path;
    for (std::string_view line : lines_of(proc_cgroup)) {
        // "<hierarchy id>:<controllers>:<path>"; the path may itself hold ':'.
        const std::size_t a = line.find(':');
        const std::size_t b = a == std::string_view::npos ? a : line.find(':', a + 1);
        if (b == std::string_view::npos) continue;
        const std::string_view id = line.substr(0, a);
        const std::string_view controllers = line.substr(a + 1, b - a - 1);
        const std::string path(trimmed(line.substr(b + 1)));
        if (id == "0" && controllers.empty()) {
            v2_path = path;
        } else {
            const auto list = split(controllers, ',');
            if (std::find(list.begin(), list.end(), std::string_view("cpu")) != list.end()) v1_path = path;
        }
    }
    std::vector<CgroupCpuDir> out;
    bool v2_done = false;
    bool v1_done = false;
    for (std::string_view line : lines_of(mountinfo)) {
        const auto m = parse_mount(line);
        if (!m) continue;
        if (m->type == "cgroup2" && v2_path && !v2_done) {
            add_up_to(out, folder_of(*m, *v2_path), folder_of(*m, m->root), 2);
            v2_done = true;
        } else if (m->type == "cgroup" && v1_path && !v1_done &&
                   std::find(m->super_options.begin(), m->super_options.end(), std::string_view("cpu")) !=
                       m->super_options.end()) {
            add_up_to(out, folder_of(*m, *v1_path), folder_of(*m, m->root), 1);
            v1_done = true;
        }
    }
    return out;
}

std::optional<double> cgroup_cpu_limit(std::string_view proc_cgroup, std::string_view mountinfo,
                                       const FileReader& read) {
    std::optional<double> limit;
    for (const CgroupCpuDir& d : cgroup_cpu_dirs(proc_cgroup, mountinfo)) {
        std::optional<double> here;
        if (d.version == 2) {
            if (const auto text = read(d.path + "/cpu.max")) here = cgroup2_cpu_limit(*text);
        } else {
            const auto quota = read(d.path + "/cpu.cfs_quota_us");
            const auto period = read(d.path + "/cpu.cfs_period_us");
            if (quota && period) here = cgroup1_cpu_limit(*quota, *period);
        }
        if (here && (!limit || *here < *limit)) limit = here;
    }
    return limit;
}

std::vector<std::uint64_t> affinity_mask() {
    // The set must be at least as large as the kernel's: grow it until sched_getaffinity accepts it
    // (1024 CPUs first, at most 2^20).
    for (int cpus = 1024; cpus <= (1 << 20); cpus *= 2) {
        cpu_set_t* set = CPU_ALLOC(cpus);
        if (set == nullptr) return {};
        const std::size_t bytes = CPU_ALLOC_SIZE(cpus);
        CPU_ZERO_S(bytes, set);
        if (sched_getaffinity(0, bytes, set) == 0) {
            std::vector<std::uint64_t> mask((static_cast<std::size_t>(cpus) + 63) / 64, 0);
            for (int c = 0; c < cpus; ++c) {
                if (CPU_ISSET_S(c, bytes, set)) mask[static_cast<std::size_t>(c) / 64] |= std::uint64_t{1} << (c % 64);
            }
            CPU_FREE(set);
            while (!mask.empty() && mask.back() == 0) mask.pop_back();
            return mask;
        }
        CPU_FREE(set);
        if (errno != EINVAL) return {};
    }
    return {};
}

bool masks_overlap(const std::vector<std::uint64_t>& a, const std::vector<std::uint64_t>& b) {
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
        if ((a[i] & b[i]) != 0) return true;
    }
    return false;
}

int usable_cpu_count() {
    int count = 0;
    for (const std::uint64_t w : affinity_mask()) count += std::popcount(w);
    if (count <= 0) count = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    const auto cgroup = read_whole_file("/proc/self/cgroup");
    const auto mounts = read_whole_file("/proc/self/mountinfo");
    if (cgroup && mounts) {
        if (const auto limit = cgroup_cpu_limit(*cgroup, *mounts, read_whole_file)) {
            count = std::min(count, cpus_for_limit(*limit));
        }
    }
    return std::max(1, count);
}

}  // namespace vi
