//! The hash maps of the hook's hot path. Their keys are collider handles and slot indices
//! that stickslip makes itself, so they need no protection from chosen keys; std's SipHash
//! took 11.5 % of stickslip's own profile samples (2.2 % of the step) on the
//! `heightfield_384` bench scene, foldhash 5.1 % (1.0 %). Its fixed state also orders a map
//! the same in every run.

/// A `HashMap` with foldhash's fixed state.
pub(crate) type HashMap<K, V> = std::collections::HashMap<K, V, foldhash::fast::FixedState>;
