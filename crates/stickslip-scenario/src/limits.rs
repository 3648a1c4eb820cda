//! What a scenario may ask of the machine that runs it. Validation refuses anything beyond
//! these bounds with the field and its line, so that no scenario file can exhaust memory
//! (a `repeat.count` of 1e9), hang a run (`solver_iterations` of 1e9, a 1e18-step run), or
//! put numbers into rapier's f32 world that overflow, underflow to zero, or lose all meaning.

/// Bodies in a scenario, repeats expanded (rapier holds 1e5 bodies in a few hundred MB).
pub const MAX_BODIES: u64 = 100_000;
/// Colliders in a scenario, repeats expanded.
pub const MAX_COLLIDERS: u64 = 200_000;
/// rapier solver iterations per step (its default is 4; more than this only burns time).
pub const MAX_SOLVER_ITERATIONS: usize = 256;
/// Steps of one run.
pub const MAX_STEPS: u64 = 100_000_000;
/// Steps × (bodies + colliders) of one run: about an hour of this machine's time per 1e10.
pub const MAX_WORK: u64 = 10_000_000_000;
/// The time step's range (s): below 0.1 µs rapier's f32 clock and positions stop resolving
/// a step; above 1 s no contact is resolved.
pub const MIN_DT: f64 = 1e-7;
/// See [`MIN_DT`].
pub const MAX_DT: f64 = 1.0;
/// Largest magnitude of any number that becomes one of rapier's f32 values (positions,
/// velocities, sizes, masses, densities, forces, stiffnesses): products of two stay finite.
pub const MAX_MAGNITUDE: f64 = 1e12;
/// Smallest collider size (m): half extents, radii, half heights.
pub const MIN_SIZE: f64 = 1e-6;
/// Smallest mass (kg) or density (kg/m³): a positive normal f32 with room for products.
pub const MIN_MASS: f64 = 1e-9;
/// Contacts whose per-contact series a logger keeps.
pub const MAX_CONTACT_SERIES: usize = 100_000;
