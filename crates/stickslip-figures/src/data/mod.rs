//! The numbers behind each figure, as plain structs (serializable, so the CLI can write them
//! next to the pictures and tests can check them against the physics tests' references).

pub mod example1;
pub mod feeder;
pub mod incline;
pub mod popov;
pub mod switch;

/// Every `k`-th element, so that at most `max` remain (the last one always kept).
pub fn thin<T: Clone>(v: &[T], max: usize) -> Vec<T> {
    if v.len() <= max || max < 2 {
        return v.to_vec();
    }
    let k = v.len().div_ceil(max - 1);
    let mut out: Vec<T> = v.iter().step_by(k).cloned().collect();
    if !(v.len() - 1).is_multiple_of(k) {
        out.push(v[v.len() - 1].clone());
    }
    out
}
