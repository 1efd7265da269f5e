//! The machine and the build the back ends run on: what a figure needs beside it to be
//! compared with another (the CPU, its cores, the vector instructions compiled in).

/// The CPU model string from `/proc/cpuinfo`, or `"unknown"`.
#[must_use]
pub fn cpu_model() -> String {
    std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|info| {
            info.lines()
                .find(|line| line.starts_with("model name"))
                .and_then(|line| line.split_once(':'))
                .map(|(_, model)| model.trim().to_owned())
        })
        .unwrap_or_else(|| "unknown".to_owned())
}

/// The cores this process may use (`std::thread::available_parallelism`, 1 if unknown).
#[must_use]
pub fn cores() -> usize {
    std::thread::available_parallelism().map_or(1, std::num::NonZeroUsize::get)
}

/// The x86-64 target features this build compiled in, of those that change the code the
/// kernels, the BVH and the compiler's vectoriser choose, e.g. `"sse4.2 avx avx2 fma"` for the
/// workspace's `x86-64-v3` baseline, more with `RUSTFLAGS="-C target-cpu=native"`, `"none"`
/// for the plain `x86-64` baseline or another architecture. (Every crate of the workspace is
/// built with the same flags, so this crate's view is the kernels'.)
#[must_use]
pub fn target_features() -> String {
    let compiled_in = [
        ("sse4.2", cfg!(target_feature = "sse4.2")),
        ("avx", cfg!(target_feature = "avx")),
        ("avx2", cfg!(target_feature = "avx2")),
        ("fma", cfg!(target_feature = "fma")),
        ("avx512f", cfg!(target_feature = "avx512f")),
        ("avx512vl", cfg!(target_feature = "avx512vl")),
    ];
    let names: Vec<&str> = compiled_in.iter().filter(|(_, on)| *on).map(|(n, _)| *n).collect();
    if names.is_empty() { "none".to_owned() } else { names.join(" ") }
}

/// The instruction sets of the BVH's node test in this process, `f32` and `f64` rays
/// (`bvh::Isa::current`, `current_f64`), e.g. `"f32 avx512, f64 avx2"`: chosen at run time from
/// the CPU, so they may be wider than [`target_features`], and set by `WEDGE_ISA`.
#[must_use]
pub fn node_test() -> String {
    format!("f32 {}, f64 {}", bvh::Isa::current().name(), bvh::Isa::current_f64().name())
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_build_names_its_features() {
        let features = super::target_features();
        assert!(!features.is_empty());
        // The workspace's x86-64 builds are x86-64-v3 (`.cargo/config.toml`) unless RUSTFLAGS
        // replaces the flags, as CI does for the plain baseline.
        if cfg!(all(target_arch = "x86_64", target_feature = "avx2")) {
            assert!(features.contains("avx2") && features.contains("fma"), "{features}");
        } else {
            assert!(!features.contains("avx2"), "{features}");
        }
        assert!(super::cores() >= 1);
        assert!(super::node_test().starts_with("f32 ") && super::node_test().contains(", f64 "));
        assert!(!super::cpu_model().is_empty());
    }
}
