//! The engine-free part of rolling and spinning resistance (see
//! [`crate::FrictionMaterial::with_rolling`]): what an adapter steps once per physics step
//! for each touching pair whose materials resist rotation, before its solver runs.
//!
//! The resistance is a contact's friction law on the rolled arc: the "slip" is the arm times
//! the relative angular velocity (its tangential part for rolling, its normal part for
//! spinning), the "measured friction" the resisting angular impulse of the last solve over
//! arm times normal impulse. [`step_rolling`] and [`step_axis`] give the solver what it needs
//! for the coming step: each resisting axis' torque cap (the law's limit times arm times
//! normal force) and target relative angular velocity (zero unless the law creeps). An
//! adapter's solver then drives each axis' relative angular velocity to its target with a
//! torque within its cap, in the same iterations as the contact's rows.
//!
//! [`freedom`] tells which turns a contact can roll at all: a point about any axis of the
//! contact plane, a line of points only about the line, a patch not at all (its normal forces
//! hold every turn, with their lever).

use crate::contact::{ContactInput, ContactState, TangentBasis, World, dot, length, step_contact};
use crate::law::Law;

/// How a contact's points let its bodies roll against each other.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Freedom {
    /// A point (or points within the lever): about any axis of the contact plane.
    Any,
    /// A line of points (a cylinder on its side), along this unit vector: only about the
    /// line; turning about the axis across it lifts one end, which the contact's normal rows
    /// hold.
    About(World),
    /// A patch (a box on its face): not at all; the normal rows hold every turn.
    Blocked,
}

/// How points at `offsets` (in the contact plane of normal `n`, from their centroid) let the
/// bodies roll, and their spread (largest distance from the centroid). An axis is blocked
/// when the points reach farther than `lever` across it: the normal forces then carry the law's
/// break-away torque (μ R F_n = F_n × lever) on their own, and a resistance beside them would
/// only share their load. `three_d`: whether the bodies can turn about in-plane axes at all;
/// in 2D the one axis of rotation is across every line of points, so a line is a patch.
pub fn freedom<I>(offsets: impl Fn() -> I, n: World, lever: f32, three_d: bool) -> (Freedom, f32)
where
    I: Iterator<Item = World>,
{
    let farthest = offsets().fold(
        [0.0f32; 3],
        |a, d| {
            if dot(d, d) > dot(a, a) { d } else { a }
        },
    );
    let spread = length(farthest);
    if !(spread > lever) {
        return (Freedom::Any, spread);
    }
    if three_d {
        // Points along the farthest one's line, within the lever across it: a line.
        let line = scale(farthest, 1.0 / spread);
        let across = cross(n, line);
        let width = offsets().fold(0.0f32, |a, d| a.max(dot(d, across).abs()));
        if !(width > lever) {
            return (Freedom::About(line), spread);
        }
    }
    (Freedom::Blocked, spread)
}

/// The rolling arm of two bodies whose centres of mass are `r1` and `r2` from the contact
/// plane (infinite for a fixed or kinematic body or none): R₁R₂/(R₁+R₂), the other's when one is infinite.
pub fn reduced_arm(r1: f32, r2: f32) -> f32 {
    if r1.is_infinite() {
        r2
    } else if r2.is_infinite() {
        r1
    } else {
        r1 * r2 / (r1 + r2)
    }
}

/// What stepping a resistance needs besides its law and motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxisStep {
    /// The pair's normal force (N), the last solve's.
    pub normal_force: f64,
    /// The step (s).
    pub dt: f64,
    /// Time at the step's start (s).
    pub time: f64,
    /// Averaging time of the mean normal force (s).
    pub stiffness_time: f64,
    /// The bodies' summed largest inverse inertia (1/(kg m²); 0 for fixed bodies).
    pub inv_inertia: f64,
}

/// The kernel's basis for a resistance about one axis: the "slip" is its first component.
fn axis_basis() -> TangentBasis {
    TangentBasis::plane([0.0, 0.0, 1.0], [1.0, 0.0, 0.0])
}

/// Steps the law of a resistance about one axis (spinning, or rolling in 2D) with arm `arm`,
/// relative angular velocity `rate` about the axis and the last solve's measured "friction"
/// `measured` (its resisting angular impulse along `rate`'s sense over arm times normal
/// impulse): the axis' torque cap (N·m) and target rate (rad/s).
pub fn step_axis(
    state: &mut ContactState,
    law: &Law,
    arm: f32,
    rate: f32,
    measured: f64,
    s: AxisStep,
) -> (f64, f64) {
    let basis = axis_basis();
    let out = step_contact(
        state,
        &ContactInput::new(law, &basis, s.dt)
            .with_solve(s.normal_force, [measured, 0.0], [(rate * arm) as f64, 0.0])
            .at_time(s.time)
            .with_inv_mass(s.inv_inertia * (arm as f64).powi(2))
            .with_stiffness_time(s.stiffness_time),
    );
    (
        out.limit * arm as f64 * s.normal_force,
        out.target[0] / arm as f64,
    )
}

/// What the solver is to do about rolling (3D) for the coming step: two axes of the contact
/// plane, `axis_x` and `axis_z = axis_x × n`, each with a torque cap (N·m; 0 leaves the axis
/// free) and a target for the relative angular velocity along it (rad/s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollingCommand {
    /// First rolling axis (unit, in the contact plane): along the rolling, or the last one
    /// carried onto the plane while the contact holds, so that its cap is the law's limit
    /// along the way the load acts.
    pub axis_x: World,
    /// Second rolling axis, `axis_x × n`.
    pub axis_z: World,
    /// Torque caps along `axis_x`, `axis_z` (N·m).
    pub caps: [f64; 2],
    /// Target relative angular velocities along `axis_x`, `axis_z` (rad/s).
    pub targets: [f64; 2],
}

/// The motion and last solve of a pair that resists rolling (3D).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollingInput {
    /// How the contact's points let the bodies roll.
    pub freedom: Freedom,
    /// The relative angular velocity ω₂ − ω₁ (rad/s, world).
    pub relative_angular_velocity: World,
    /// The contact normal (unit, from body 1 towards body 2).
    pub normal: World,
    /// The rolling arm R (m).
    pub arm: f32,
    /// The first rolling axis of the last step (zero before the first).
    pub last_axis: World,
    /// The last solve's resisting "friction" as a world vector in the contact plane: its
    /// resisting angular impulse on body 1 (the opposite of body 2's) over arm times normal
    /// impulse, both of the last step.
    pub measured: World,
}

/// Steps the rolling law of a pair (3D; `law` `None` when its materials do not resist
/// rolling): the solver's rolling axes, caps and targets for the coming step. A blocked
/// contact (a patch) starts its state over and leaves both axes free; a line leaves the axis
/// across it free.
pub fn step_rolling(
    state: &mut ContactState,
    law: Option<&Law>,
    input: &RollingInput,
    s: AxisStep,
) -> RollingCommand {
    let RollingInput {
        freedom,
        relative_angular_velocity: w,
        normal: n,
        arm,
        last_axis,
        measured,
    } = *input;
    let w_spin = dot(n, w);
    let w_roll = match freedom {
        Freedom::Any => sub(w, scale(n, w_spin)),
        // Only the turn about the line rolls.
        Freedom::About(d) => scale(d, dot(d, w)),
        Freedom::Blocked => [0.0; 3],
    };
    let roll_speed = length(w_roll) * arm;
    let axis_x = match freedom {
        Freedom::About(d) if dot(d, last_axis) < 0.0 => scale(d, -1.0),
        Freedom::About(d) => d,
        // The rolling direction of the contact point is ω × n: its axis is ω's own
        // tangential direction.
        _ if roll_speed > 1e-6 => scale(w_roll, 1.0 / length(w_roll)),
        _ => tangent_axis(last_axis, n),
    };
    let axis_z = cross(axis_x, n);
    // The kernel's components are (x, −z): t1 = x, t2 = n × x.
    let basis = TangentBasis::plane(n, axis_x);
    let mut command = RollingCommand {
        axis_x,
        axis_z,
        caps: [0.0; 2],
        targets: [0.0; 2],
    };
    if freedom == Freedom::Blocked {
        // A patch does not roll: its normal rows hold the turn, with their lever.
        *state = ContactState::default();
        return command;
    }
    let Some(law) = law else {
        return command;
    };
    let slip = basis.project(scale(w_roll, arm));
    let out = step_contact(
        state,
        &ContactInput::new(law, &basis, s.dt)
            .with_solve(s.normal_force, basis.project(measured), slip)
            .at_time(s.time)
            .with_inv_mass(s.inv_inertia * (arm as f64).powi(2))
            .with_stiffness_time(s.stiffness_time),
    );
    let cap = out.limit * arm as f64 * s.normal_force;
    command.caps = [
        cap,
        // A line rolls about itself only: the turn across it is the normal rows'.
        if freedom == Freedom::Any { cap } else { 0.0 },
    ];
    command.targets = [out.target[0] / arm as f64, -out.target[1] / arm as f64];
    command
}

/// A unit vector normal to the unit `n`: `hint` made normal to it, else any.
pub fn tangent_axis(hint: World, n: World) -> World {
    let t = sub(hint, scale(n, dot(n, hint)));
    if dot(t, t) > 1e-12 {
        scale(t, 1.0 / length(t))
    } else {
        any_normal(n)
    }
}

/// A unit vector normal to the unit `n` (glam's `any_orthonormal_vector`).
fn any_normal(n: World) -> World {
    let sign = 1.0f32.copysign(n[2]);
    let a = -1.0 / (sign + n[2]);
    let b = n[0] * n[1] * a;
    [b, sign + n[1] * n[1] * a, -n[1]]
}

fn scale(a: World, k: f32) -> World {
    [a[0] * k, a[1] * k, a[2] * k]
}

fn sub(a: World, b: World) -> World {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn cross(a: World, b: World) -> World {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sliding_curve::Curve;

    fn sharp(mu: f64) -> Law {
        Law::elasto_plastic(1e4, mu, mu, Curve::constant(mu).unwrap()).unwrap()
    }

    fn step(f_n: f64) -> AxisStep {
        AxisStep {
            normal_force: f_n,
            dt: 1.0 / 60.0,
            time: 0.0,
            stiffness_time: 1.0,
            inv_inertia: 0.0,
        }
    }

    #[test]
    fn points_within_the_lever_roll_a_line_rolls_about_itself_a_patch_not_at_all() {
        let n = [0.0, 1.0, 0.0];
        let point = || [[0.0; 3]].into_iter();
        assert_eq!(freedom(point, n, 0.01, true), (Freedom::Any, 0.0));
        let line = || [[0.0, 0.0, 0.5], [0.0, 0.0, -0.5]].into_iter();
        let (f, spread) = freedom(line, n, 0.01, true);
        assert_eq!(spread, 0.5);
        assert!(matches!(f, Freedom::About(d) if d[2].abs() == 1.0));
        // In 2D a line of points is across the one axis: held.
        assert_eq!(freedom(line, n, 0.01, false).0, Freedom::Blocked);
        let patch = || {
            [
                [0.5, 0.0, 0.5],
                [-0.5, 0.0, 0.5],
                [0.5, 0.0, -0.5],
                [-0.5, 0.0, -0.5],
            ]
            .into_iter()
        };
        assert_eq!(freedom(patch, n, 0.01, true).0, Freedom::Blocked);
    }

    #[test]
    fn the_reduced_arm_is_the_finite_one_or_the_harmonic_combination() {
        assert_eq!(reduced_arm(f32::INFINITY, 0.1), 0.1);
        assert_eq!(reduced_arm(0.2, f32::INFINITY), 0.2);
        assert!((reduced_arm(0.1, 0.1) - 0.05).abs() < 1e-7);
    }

    /// A rolling contact gets the law's sliding torque μ R F_n on both axes of a point
    /// contact, the first along the rolling axis; a held one keeps its last axis.
    #[test]
    fn rolling_caps_are_the_laws_torque_along_the_rolling_axis() {
        let (n, arm, f_n) = ([0.0, 1.0, 0.0], 0.1f32, 10.0);
        let law = sharp(0.05);
        let mut state = ContactState::default();
        let input = RollingInput {
            freedom: Freedom::Any,
            relative_angular_velocity: [0.0, 0.0, -5.0],
            normal: n,
            arm,
            last_axis: [0.0; 3],
            measured: [0.0; 3],
        };
        let mut command = step_rolling(&mut state, Some(&law), &input, step(f_n));
        for _ in 0..10 {
            let measured = scale(command.axis_x, 0.05);
            command = step_rolling(
                &mut state,
                Some(&law),
                &RollingInput {
                    measured,
                    last_axis: command.axis_x,
                    ..input
                },
                step(f_n),
            );
        }
        assert_eq!(command.axis_x, [0.0, 0.0, -1.0]);
        for cap in command.caps {
            assert!((cap - 0.05 * 0.1 * f_n).abs() < 1e-6, "{command:?}");
        }
        let held = step_rolling(
            &mut ContactState::default(),
            Some(&law),
            &RollingInput {
                relative_angular_velocity: [0.0; 3],
                last_axis: [1.0, 0.0, 0.0],
                ..input
            },
            step(f_n),
        );
        assert_eq!(held.axis_x, [1.0, 0.0, 0.0]);
        assert_eq!(held.targets, [0.0, 0.0]);
    }

    #[test]
    fn a_patch_resets_and_frees_a_line_frees_the_axis_across_it() {
        let law = sharp(0.05);
        let mut state = ContactState {
            slide: 0.5,
            ..ContactState::default()
        };
        let input = RollingInput {
            freedom: Freedom::Blocked,
            relative_angular_velocity: [0.0, 0.0, -5.0],
            normal: [0.0, 1.0, 0.0],
            arm: 0.1,
            last_axis: [0.0; 3],
            measured: [0.0; 3],
        };
        let blocked = step_rolling(&mut state, Some(&law), &input, step(10.0));
        assert_eq!(blocked.caps, [0.0, 0.0]);
        assert_eq!(state, ContactState::default());
        let line = step_rolling(
            &mut state,
            Some(&law),
            &RollingInput {
                freedom: Freedom::About([0.0, 0.0, 1.0]),
                ..input
            },
            step(10.0),
        );
        assert!(line.caps[0] > 0.0 && line.caps[1] == 0.0, "{line:?}");
        assert_eq!(line.axis_x, [0.0, 0.0, 1.0]);
    }

    #[test]
    fn any_normal_is_a_unit_vector_normal_to_n() {
        for n in [[0.0, 1.0, 0.0], [0.0, 0.0, -1.0], [0.6, 0.0, 0.8]] {
            let t = any_normal(n);
            assert!(dot(t, n).abs() < 1e-6 && (length(t) - 1.0).abs() < 1e-6);
        }
    }
}
