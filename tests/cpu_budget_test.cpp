// The CPUs a process may use (model/cpu_budget.hpp): cgroup quota files as the kernel writes them,
// the cgroup folders found from /proc/self/cgroup and /proc/self/mountinfo (cgroup v1, v2, hybrid,
// containers), and the count this process gets against its own affinity.

#include <gtest/gtest.h>
#include <sched.h>

#include <bit>
#include <map>
#include <optional>
#include <sstream>
#include <string>

#include "model/cpu_budget.hpp"
#include "model/parallel_for.hpp"

namespace vi {
namespace {

TEST(CpuBudget, Cgroup2CpuMaxGivesQuotaOverPeriod) {
    EXPECT_EQ(cgroup2_cpu_limit("200000 100000\n"), 2.0);
    EXPECT_EQ(cgroup2_cpu_limit("150000 100000"), 1.5);
    EXPECT_EQ(cgroup2_cpu_limit("50000 100000\n"), 0.5);
    EXPECT_EQ(cgroup2_cpu_limit("max 100000\n"), std::nullopt);
    EXPECT_EQ(cgroup2_cpu_limit("max\n"), std::nullopt);
    EXPECT_EQ(cgroup2_cpu_limit(""), std::nullopt);
    EXPECT_EQ(cgroup2_cpu_limit("garbage here\n"), std::nullopt);
    EXPECT_EQ(cgroup2_cpu_limit("0 100000\n"), std::nullopt);
    EXPECT_EQ(cgroup2_cpu_limit("100000 0\n"), std::nullopt);
}

TEST(CpuBudget, Cgroup1QuotaAndPeriod) {
    EXPECT_EQ(cgroup1_cpu_limit("300000\n", "100000\n"), 3.0);
    EXPECT_EQ(cgroup1_cpu_limit("25000\n", "100000\n"), 0.25);
    EXPECT_EQ(cgroup1_cpu_limit("-1\n", "100000\n"), std::nullopt);  // the kernel's "no limit"
    EXPECT_EQ(cgroup1_cpu_limit("100000\n", ""), std::nullopt);
    EXPECT_EQ(cgroup1_cpu_limit("x\n", "100000\n"), std::nullopt);
}

TEST(CpuBudget, FractionalQuotaRoundsUp) {
    EXPECT_EQ(cpus_for_limit(0.25), 1);
    EXPECT_EQ(cpus_for_limit(1.0), 1);
    EXPECT_EQ(cpus_for_limit(1.5), 2);
    EXPECT_EQ(cpus_for_limit(2.0), 2);
    EXPECT_EQ(cpus_for_limit(2.0000001), 3);
    EXPECT_EQ(cpus_for_limit(16.0), 16);
}

// A container with a cgroup namespace (cgroup v2 only): the process is at the root of what it sees.
const char* kV2Cgroup = "0::/\n";
const char* kV2Mounts =
    "1021 1000 0:22 / / rw,relatime - overlay overlay rw,lowerdir=/a,upperdir=/b\n"
    "1030 1021 0:26 / /sys/fs/cgroup ro,nosuid,nodev,noexec,relatime - cgroup2 cgroup rw,nsdelegate\n";

// A host with systemd and cgroup v2: the process sits deep in the tree.
const char* kHostCgroup = "0::/user.slice/user-1000.slice/session-3.scope\n";
const char* kHostMounts =
    "22 1 259:2 / / rw,relatime shared:1 - ext4 /dev/nvme0n1p2 rw\n"
    "30 22 0:26 / /sys/fs/cgroup rw,nosuid,nodev,noexec,relatime shared:9 - cgroup2 cgroup2 rw,nsdelegate\n";

// The hybrid layout (cgroup v1 controllers, v2 mounted at unified/), as on this project's CI machine.
const char* kHybridCgroup =
    "9:name=systemd:/\n8:pids:/\n3:cpuset:/\n2:cpuacct:/\n1:cpu:/job42\n0::/\n";
const char* kHybridMounts =
    "40 30 0:30 / /sys/fs/cgroup/unified rw,nosuid - cgroup2 cgroup2 rw\n"
    "41 30 0:31 / /sys/fs/cgroup/cpuset rw,nosuid - cgroup cgroup rw,cpuset\n"
    "42 30 0:32 / /sys/fs/cgroup/cpu rw,nosuid - cgroup cgroup rw,cpu\n"
    "43 30 0:33 / /sys/fs/cgroup/cpuacct rw,nosuid - cgroup cgroup rw,cpuacct\n";

// A docker container without a cgroup namespace (v1, cpu and cpuacct together): the mount's root is
// the container's own cgroup.
const char* kDockerCgroup = "4:cpu,cpuacct:/docker/abc123\n3:memory:/docker/abc123\n";
const char* kDockerMounts =
    "600 500 0:50 /docker/abc123 /sys/fs/cgroup/cpu,cpuacct ro,nosuid - cgroup cgroup rw,cpu,cpuacct\n";

std::string dirs_text(const std::vector<CgroupCpuDir>& dirs) {
    std::ostringstream s;
    for (const auto& d : dirs) s << 'v' << d.version << ':' << d.path << ' ';
    return s.str();
}

TEST(CpuBudget, CgroupFoldersFromProcFiles) {
    EXPECT_EQ(dirs_text(cgroup_cpu_dirs(kV2Cgroup, kV2Mounts)), "v2:/sys/fs/cgroup ");
    EXPECT_EQ(dirs_text(cgroup_cpu_dirs(kHostCgroup, kHostMounts)),
              "v2:/sys/fs/cgroup/user.slice/user-1000.slice/session-3.scope "
              "v2:/sys/fs/cgroup/user.slice/user-1000.slice v2:/sys/fs/cgroup/user.slice v2:/sys/fs/cgroup ");
    EXPECT_EQ(dirs_text(cgroup_cpu_dirs(kHybridCgroup, kHybridMounts)),
              "v2:/sys/fs/cgroup/unified v1:/sys/fs/cgroup/cpu/job42 v1:/sys/fs/cgroup/cpu ");
    EXPECT_EQ(dirs_text(cgroup_cpu_dirs(kDockerCgroup, kDockerMounts)), "v1:/sys/fs/cgroup/cpu,cpuacct ");
    // A mount point with a space, escaped by the kernel as \040.
    EXPECT_EQ(dirs_text(cgroup_cpu_dirs("0::/a\n", "1 0 0:1 / /my\\040cg rw - cgroup2 none rw\n")),
              "v2:/my cg/a v2:/my cg ");
    EXPECT_TRUE(cgroup_cpu_dirs("", kV2Mounts).empty());
    EXPECT_TRUE(cgroup_cpu_dirs(kV2Cgroup, "").empty());
}

FileReader fake_files(std::map<std::string, std::string> files) {
    return [files = std::move(files)](const std::string& path) -> std::optional<std::string> {
        const auto it = files.find(path);
        if (it == files.end()) return std::nullopt;
        return it->second;
    };
}

TEST(CpuBudget, TheSmallestQuotaOnThePathApplies) {
    // docker run --cpus=1.5 (v2, namespaced).
    EXPECT_EQ(cgroup_cpu_limit(kV2Cgroup, kV2Mounts, fake_files({{"/sys/fs/cgroup/cpu.max", "150000 100000\n"}})),
              1.5);
    // No quota anywhere (the root cgroup has no cpu.max at all).
    EXPECT_EQ(cgroup_cpu_limit(kHostCgroup, kHostMounts,
                               fake_files({{"/sys/fs/cgroup/user.slice/cpu.max", "max 100000\n"}})),
              std::nullopt);
    // A parent's quota bounds its child's larger one.
    EXPECT_EQ(cgroup_cpu_limit(kHostCgroup, kHostMounts,
                               fake_files({{"/sys/fs/cgroup/user.slice/user-1000.slice/session-3.scope/cpu.max",
                                            "800000 100000\n"},
                                           {"/sys/fs/cgroup/user.slice/cpu.max", "200000 100000\n"}})),
              2.0);
    // Hybrid: the v1 cpu controller's quota counts (v2 here has no cpu controller, so no cpu.max).
    EXPECT_EQ(cgroup_cpu_limit(kHybridCgroup, kHybridMounts,
                               fake_files({{"/sys/fs/cgroup/cpu/job42/cpu.cfs_quota_us", "100000\n"},
                                           {"/sys/fs/cgroup/cpu/job42/cpu.cfs_period_us", "100000\n"},
                                           {"/sys/fs/cgroup/cpu/cpu.cfs_quota_us", "-1\n"},
                                           {"/sys/fs/cgroup/cpu/cpu.cfs_period_us", "100000\n"}})),
              1.0);
    EXPECT_EQ(cgroup_cpu_limit(kDockerCgroup, kDockerMounts,
                               fake_files({{"/sys/fs/cgroup/cpu,cpuacct/cpu.cfs_quota_us", "-1\n"},
                                           {"/sys/fs/cgroup/cpu,cpuacct/cpu.cfs_period_us", "100000\n"}})),
              std::nullopt);
}

TEST(CpuBudget, MasksOverlap) {
    EXPECT_TRUE(masks_overlap({0b11}, {0b10}));
    EXPECT_FALSE(masks_overlap({0b01}, {0b10}));
    EXPECT_FALSE(masks_overlap({0b01}, {0, 0b1}));
    EXPECT_TRUE(masks_overlap({0, 0b100}, {1, 0b110}));
    EXPECT_FALSE(masks_overlap({}, {1}));
}

// Against this process's own affinity: the count is never more than the CPUs it may run on, and
// resolve_thread_count(0) is that count.
TEST(CpuBudget, UsableCountFollowsThisProcessAffinity) {
    cpu_set_t set;
    CPU_ZERO(&set);
    ASSERT_EQ(sched_getaffinity(0, sizeof set, &set), 0);
    const int allowed = CPU_COUNT(&set);
    int from_mask = 0;
    for (const std::uint64_t w : affinity_mask()) from_mask += std::popcount(w);
    EXPECT_EQ(from_mask, allowed);
    const int usable = usable_cpu_count();
    EXPECT_GE(usable, 1);
    EXPECT_LE(usable, allowed);
    EXPECT_EQ(resolve_thread_count(0), usable);
    EXPECT_EQ(resolve_thread_count(3), 3);
    std::printf("this process may run on %d CPUs; usable_cpu_count() = %d\n", allowed, usable);
}

// Restricted to one CPU, as `taskset -c N` does, the count is 1. (sched_setaffinity(0) sets this
// thread's affinity, which is what affinity_mask reads; restored afterwards.)
TEST(CpuBudget, OneAllowedCpuGivesOneThread) {
    cpu_set_t before;
    CPU_ZERO(&before);
    ASSERT_EQ(sched_getaffinity(0, sizeof before, &before), 0);
    int first = -1;
    for (int c = 0; c < CPU_SETSIZE && first < 0; ++c) {
        if (CPU_ISSET(c, &before)) first = c;
    }
    ASSERT_GE(first, 0);
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(first, &one);
    ASSERT_EQ(sched_setaffinity(0, sizeof one, &one), 0);
    const int usable = usable_cpu_count();
    const int threads = resolve_thread_count(0);
    ASSERT_EQ(sched_setaffinity(0, sizeof before, &before), 0);
    EXPECT_EQ(usable, 1);
    EXPECT_EQ(threads, 1);
}

}  // namespace
}  // namespace vi
