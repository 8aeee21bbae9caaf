//! The limits every front end of the pipeline applies (the command line, the Python package):
//! the largest grid and the default memory budget.

/// The largest grid resolution accepted: a sphere at 2048 already takes about 4 GB.
pub const MAX_RESOLUTION: usize = 2048;

/// Half of this machine's memory (`MemTotal` of `/proc/meminfo`, 8 GiB where it cannot be read),
/// and at most half of this process's address-space limit (`ulimit -v`, from
/// `/proc/self/limits`): threads' stacks and allocator arenas reserve address space beyond
/// what is used, and running out of it aborts.
pub fn default_max_memory() -> u64 {
    let total = std::fs::read_to_string("/proc/meminfo")
        .ok()
        .and_then(|text| {
            text.lines()
                .find_map(|l| l.strip_prefix("MemTotal:"))
                .and_then(|v| v.trim().trim_end_matches("kB").trim().parse::<u64>().ok())
        })
        .map_or(8 << 30, |kib| kib.saturating_mul(1024));
    let address_space = std::fs::read_to_string("/proc/self/limits")
        .ok()
        .and_then(|text| {
            let line = text.lines().find(|l| l.starts_with("Max address space"))?;
            // "Max address space  <soft>  <hard>  bytes": the soft limit, unless unlimited.
            line["Max address space".len()..]
                .split_whitespace()
                .next()?
                .parse::<u64>()
                .ok()
        })
        .unwrap_or(u64::MAX);
    total.min(address_space) / 2
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_default_budget_is_positive_and_below_the_machine() {
        let m = super::default_max_memory();
        assert!(m > 0);
        assert!(m < u64::MAX / 2);
    }
}
