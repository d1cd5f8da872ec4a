#pragma once
// The CPUs this process may use: its affinity set (taskset, a batch system's binding), lowered to a
// cgroup CPU quota (a container's or a job's --cpus). What `--threads 0` means.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vi {

// CPUs that a cgroup v2 `cpu.max` file allows: "<quota> <period>" (microseconds) gives
// quota / period; "max ..." (no limit) or text that is not such a line gives nullopt.
std::optional<double> cgroup2_cpu_limit(std::string_view cpu_max);

// The same for cgroup v1: the contents of cpu.cfs_quota_us (-1: no limit) and cpu.cfs_period_us.
std::optional<double> cgroup1_cpu_limit(std::string_view quota_us, std::string_view period_us);

// Whole CPUs for a fractional limit: rounded up (a quota of 1.5 CPUs keeps 2 threads 75 % busy),
// at least 1.
int cpus_for_limit(double cpus);

// A folder of a cgroup file system whose CPU quota applies to this process, and its version (1, 2).
struct CgroupCpuDir {
    std::string path;
    int version = 2;
};

// The cgroup folders, leaf first, up to the mount point, whose quota bounds this process, from the
// text of /proc/self/cgroup and /proc/self/mountinfo: the cgroup v2 hierarchy and the v1 hierarchy
// that holds the `cpu` controller (a machine may have both: the "hybrid" layout).
std::vector<CgroupCpuDir> cgroup_cpu_dirs(std::string_view proc_cgroup, std::string_view mountinfo);

// Reads a whole file, or nullopt when it does not exist or cannot be read.
using FileReader = std::function<std::optional<std::string>(const std::string& path)>;

// The smallest CPU quota [CPUs] over the folders of cgroup_cpu_dirs (a parent's quota bounds its
// children), reading cpu.max (v2) or cpu.cfs_quota_us and cpu.cfs_period_us (v1) with `read`;
// nullopt when no folder sets one.
std::optional<double> cgroup_cpu_limit(std::string_view proc_cgroup, std::string_view mountinfo,
                                       const FileReader& read);

// This process's CPU affinity as a bit set (bit i of word i / 64: CPU i may run it); empty when
// the system does not tell.
std::vector<std::uint64_t> affinity_mask();

// True when the two bit sets have a CPU in common.
bool masks_overlap(const std::vector<std::uint64_t>& a, const std::vector<std::uint64_t>& b);

// CPUs this process may run on: the count of its affinity set, lowered to
// cpus_for_limit(cgroup quota) when one applies; the machine's hardware concurrency when the
// affinity is unknown; at least 1.
int usable_cpu_count();

}  // namespace vi
