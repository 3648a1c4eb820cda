//! Property-test configuration shared by the test suites: deterministic by default.
//!
//! Without environment variables every run uses the same seed and the given case count, so
//! the suite passes or fails the same way on every machine. `PROPTEST_CASES=N` and
//! `PROPTEST_RNG_SEED=N` (proptest's own variables) override both; `scripts/long_tests.sh`
//! runs many cases with a fresh seed.

use proptest::test_runner::{Config, RngSeed};

/// The fixed seed of the default runs.
pub const SEED: u64 = 0x5715_C5A1_1D00_0009;

/// A proptest configuration with `cases` cases and a fixed seed, unless overridden.
pub fn deterministic(cases: u32) -> Config {
    // Config::default() reads PROPTEST_CASES / PROPTEST_RNG_SEED from the environment.
    let mut config = Config::default();
    if std::env::var_os("PROPTEST_CASES").is_none() {
        config.cases = cases;
    }
    if std::env::var_os("PROPTEST_RNG_SEED").is_none() {
        config.rng_seed = RngSeed::Fixed(SEED);
    }
    config
}
