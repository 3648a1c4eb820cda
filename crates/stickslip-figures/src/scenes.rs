//! Reference scenes the figures are drawn from: a box on the ground (incline creep), a sled
//! dragged over a vibrating plate (Popov's experiment), the seed's Example 1 and a vibratory
//! feeder in rapier. Private to this crate; the workspace's fixtures crate (unpublished)
//! compiles this same file for the tests and benches.

use stickslip_rapier::rapier::prelude::*;

/// A vector from its 3D components; the fixtures' 2D build (cfg `dim2`) drops z.
pub fn v3(x: f32, y: f32, z: f32) -> Vector {
    #[cfg(dim2)]
    let v = {
        let _ = z;
        Vector::new(x, y)
    };
    #[cfg(not(dim2))]
    let v = Vector::new(x, y, z);
    v
}

/// A cuboid collider from its 3D half-extents and its volume (area in 2D, z dropped).
pub fn cuboid3(hx: f32, hy: f32, hz: f32) -> (ColliderBuilder, f32) {
    #[cfg(dim2)]
    let c = {
        let _ = hz;
        (ColliderBuilder::cuboid(hx, hy), 4.0 * hx * hy)
    };
    #[cfg(not(dim2))]
    let c = (ColliderBuilder::cuboid(hx, hy, hz), 8.0 * hx * hy * hz);
    c
}

/// A box resting on a large fixed ground slab.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoxOnGround {
    /// Half-extent of the cubic box (m).
    pub half: f32,
    /// Mass of the box (kg).
    pub mass: f32,
    /// Incline angle θ (rad): gravity is tilted about z so the slope runs down along +x.
    pub incline: f64,
    /// Gravity magnitude (m/s²); 0 for a box pressed by forces only.
    pub gravity: f32,
    /// Time step (s).
    pub dt: f32,
    /// Whether the box may rotate (off: pure sliding, no rocking on the compliant contact).
    pub rotations: bool,
}

impl Default for BoxOnGround {
    fn default() -> Self {
        BoxOnGround {
            half: 0.25,
            mass: 125.0,
            incline: 0.0,
            gravity: 9.81,
            dt: 1.0 / 60.0,
            rotations: true,
        }
    }
}

/// The handles of a [`BoxOnGround`] world.
pub struct BoxScene {
    /// The world.
    pub world: PhysicsWorld,
    /// The box.
    pub body: RigidBodyHandle,
    /// The box's collider.
    pub box_collider: ColliderHandle,
    /// The ground's collider (attach the friction modifier to it).
    pub ground: ColliderHandle,
}

impl BoxOnGround {
    /// Builds the world: ground top at y = 0.1, box resting on it, sleeping disabled (a
    /// sleeping box would hide creep), colliders' own friction 0.
    pub fn build(&self) -> BoxScene {
        let mut world = PhysicsWorld::default();
        world.integration_parameters.dt = self.dt;
        let (s, c) = (self.incline.sin() as f32, self.incline.cos() as f32);
        world.gravity = v3(self.gravity * s, -self.gravity * c, 0.0);
        let ground = world.insert_collider(cuboid3(200.0, 0.1, 50.0).0.friction(0.0), None);
        let h = self.half;
        let body = RigidBodyBuilder::dynamic()
            .translation(v3(0.0, 0.1 + h, 0.0))
            .can_sleep(false);
        #[cfg(not(dim2))]
        let body = body.enabled_rotations(self.rotations, self.rotations, self.rotations);
        #[cfg(dim2)]
        let body = if self.rotations {
            body
        } else {
            body.lock_rotations()
        };
        let (cube, volume) = cuboid3(h, h, h);
        let (body, box_collider) =
            world.insert(body, cube.density(self.mass / volume).friction(0.0));
        BoxScene {
            world,
            body,
            box_collider,
            ground,
        }
    }
}

impl BoxScene {
    /// Position of the box's centre along x (m).
    pub fn x(&self) -> f64 {
        self.world.bodies[self.body].translation().x as f64
    }

    /// Velocity of the box along x (m/s).
    pub fn vx(&self) -> f64 {
        self.world.bodies[self.body].linvel().x as f64
    }

    /// Replaces the user forces on the box by `force` (N, world).
    pub fn set_force(&mut self, force: Vector) {
        let b = &mut self.world.bodies[self.body];
        b.reset_forces(true);
        b.add_force(force, true);
    }
}

/// A weightless 0.2 m sled of `mass` on a fixed plate, stepped at `dt`, its contact
/// elasto-plastic in the seed's sharp limit (μ_ba = μ_max = μ0, flat curve) with stiffness `c`,
/// per-contact reports on: the setup of [`PopovDrag`] and of the fixtures' `VibratingPlate`.
pub fn sled_on_plate(
    mass: f32,
    dt: f64,
    c: f64,
    mu0: f64,
) -> Result<(BoxScene, stickslip_rapier::StickSlip), stickslip_core::ParamError> {
    use stickslip_core::law::Law;
    use stickslip_core::sliding_curve::Curve;
    let mut scene = BoxOnGround {
        half: 0.1,
        mass,
        gravity: 0.0,
        dt: dt as f32,
        rotations: false,
        ..BoxOnGround::default()
    }
    .build();
    let law = Law::elasto_plastic(c, mu0, mu0, Curve::constant(mu0)?)?;
    let mut modifier =
        stickslip_rapier::StickSlip::new(stickslip_rapier::FrictionMaterial::new(law))
            .with_read_back(stickslip_rapier::ReadBack::Contacts);
    // Both sides attached: the pair is the material's alone (not combined with the box's
    // rapier friction).
    modifier.attach(&mut scene.world.colliders, scene.ground, None);
    modifier.attach(&mut scene.world.colliders, scene.box_collider, None);
    Ok((scene, modifier))
}

/// How the normal force of a [`PopovDrag`] is modulated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PopovDrive {
    /// A real vertical force F̄ α w(f t) on the sled, carried by the solver's contact.
    RealLoad,
    /// A normal [`stickslip_rapier::VibrationSource`] on the plate, in the given mode.
    Source(stickslip_rapier::VibrationMode),
}

/// Popov's experiment in rapier: a massive sled pressed onto a fixed plate by F̄ and dragged at
/// constant velocity v0 (its horizontal velocity is imposed every step and one step's friction
/// impulse cannot stop it, so the solver applies the contact's full friction), the normal force
/// modulated as F̄ (1 + α w(f t)). Its contact is elasto-plastic in the seed's sharp limit
/// (μ_ba = μ_max = μ0, flat sliding curve) with stiffness c, so Popov's contact spring is
/// k_t = c F̄ and β = c v0 / (μ0 α f).
#[derive(Debug, Clone)]
pub struct PopovDrag {
    /// Coefficient of friction μ0.
    pub mu0: f64,
    /// Law stiffness c (1/m).
    pub c: f64,
    /// Amplitude ratio α.
    pub alpha: f64,
    /// Vibration frequency f (Hz).
    pub frequency: f64,
    /// Mean normal force F̄ (N).
    pub normal_force: f64,
    /// Waveform.
    pub waveform: stickslip_core::waveform::Waveform,
    /// Modulation.
    pub drive: PopovDrive,
    /// Steps per vibration period (time-resolved needs tens; averaged mode needs few).
    pub steps_per_period: usize,
    /// Mass of the dragged sled (kg); its velocity is imposed every step.
    pub sled_mass: f32,
}

impl PopovDrag {
    /// The setup of stickslip's tests: μ0 = 0.5, c = 1e4 1/m, α = 0.5, f = 5 Hz, F̄ = 9.81 N,
    /// 400 steps per period (40 in averaged mode).
    pub fn new(waveform: stickslip_core::waveform::Waveform, drive: PopovDrive) -> Self {
        PopovDrag {
            mu0: 0.5,
            c: 1e4,
            alpha: 0.5,
            frequency: 5.0,
            normal_force: 9.81,
            waveform,
            drive,
            steps_per_period: match drive {
                PopovDrive::Source(stickslip_rapier::VibrationMode::Averaged) => 40,
                _ => 400,
            },
            sled_mass: 1000.0,
        }
    }

    /// Popov's μ̄ = μ0 (1 − α Ψ_w(β)) for this setup.
    pub fn theory(&self, beta: f64) -> f64 {
        let psi = stickslip_core::popov::psi(&self.waveform, beta).unwrap_or(f64::NAN);
        self.mu0 * (1.0 - self.alpha * psi)
    }

    /// Measures μ̄ = ⟨F_x⟩/⟨F_z⟩ at `beta` after the spring has loaded up to the cone.
    pub fn measure(&self, beta: f64) -> Result<f64, stickslip_core::ParamError> {
        let f = self.frequency;
        let dt = 1.0 / (f * self.steps_per_period as f64);
        let (mut scene, mut modifier) = sled_on_plate(self.sled_mass, dt, self.c, self.mu0)?;
        if let PopovDrive::Source(mode) = self.drive {
            let src = stickslip_rapier::VibrationSource::new(
                stickslip_rapier::VibrationDirection::Normal,
                stickslip_rapier::Amplitude::Ratio(self.alpha),
                f,
                self.waveform.clone(),
                0.0,
                mode,
            )?;
            modifier.set_vibration(scene.ground, src);
        }
        let v0 = beta * self.mu0 * self.alpha * f / self.c;
        // Warm-up: the spring needs ~(1−α)/(αβ) periods to reach the cone, and under a real
        // oscillating load the mean normal force behind k_t ~5 averaging times.
        let settle = match self.drive {
            PopovDrive::RealLoad => {
                (5.0 * stickslip_rapier::StickSlipConfig::default().stiffness_time * f).ceil()
                    as usize
            }
            PopovDrive::Source(_) => 0,
        };
        let warm = ((1.0 - self.alpha) / (self.alpha * beta)).ceil() as usize + 3 + settle;
        let periods = warm + 4;
        let (mut sum_fx, mut sum_fz) = (0.0, 0.0);
        for k in 0..(periods * self.steps_per_period) {
            let t_mid = (k as f64 + 0.5) * dt;
            let w = self.waveform.value(f * t_mid);
            let extra = match self.drive {
                PopovDrive::RealLoad => self.normal_force * self.alpha * w,
                PopovDrive::Source(_) => 0.0,
            };
            let b = &mut scene.world.bodies[scene.body];
            b.set_linvel(v3(v0 as f32, b.linvel().y, 0.0), true);
            scene.set_force(v3(0.0, -((self.normal_force + extra) as f32), 0.0));
            modifier.step(&mut scene.world);
            if k >= warm * self.steps_per_period
                && let Some(r) = modifier.reports().ok().and_then(|r| r.first())
            {
                sum_fx += -r.friction_force[0] as f64;
                sum_fz += match self.drive {
                    // The law saw F̄ (1 + α w); the solver's normal force is F̄.
                    PopovDrive::Source(stickslip_rapier::VibrationMode::TimeResolved) => {
                        r.normal_force * (1.0 + self.alpha * w).max(0.0)
                    }
                    _ => r.normal_force,
                };
            }
        }
        Ok(sum_fx / sum_fz)
    }
}

/// One sample of [`example1_trace`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Example1Sample {
    /// Time since the force started (s).
    pub t: f64,
    /// Displacement of the box (m).
    pub x: f64,
    /// Velocity of the box (m/s).
    pub v: f64,
    /// Friction force on the box along x (N), from the contact's report (0 without contact).
    pub friction: f64,
}

/// The seed's Example 1 in rapier (a 1 kg box, rotations locked, on the ground under the
/// tangential force `profile`, with the friction `law`, at step `dt`) step by step: the box's
/// displacement, velocity and friction force after every step up to `end` (s).
pub fn example1_trace(
    law: stickslip_core::law::Law,
    profile: &stickslip_core::profile::ForceProfile,
    dt: f64,
    end: f64,
) -> Vec<Example1Sample> {
    let mut scene = BoxOnGround {
        half: 0.1,
        mass: 1.0,
        dt: dt as f32,
        rotations: false,
        ..BoxOnGround::default()
    }
    .build();
    let mut modifier =
        stickslip_rapier::StickSlip::new(stickslip_rapier::FrictionMaterial::new(law))
            .with_read_back(stickslip_rapier::ReadBack::Contacts);
    modifier.attach(&mut scene.world.colliders, scene.ground, None);
    modifier.attach(&mut scene.world.colliders, scene.box_collider, None);
    // Settle on the ground first, then t = 0.
    for _ in 0..(0.1 / dt).ceil() as usize {
        modifier.step(&mut scene.world);
    }
    let x0 = scene.x();
    let steps = (end / dt).round() as usize;
    let mut out = Vec::with_capacity(steps);
    for k in 0..steps {
        let t_mid = (k as f64 + 0.5) * dt;
        scene.set_force(v3(profile.value(t_mid) as f32, 0.0, 0.0));
        modifier.step(&mut scene.world);
        // The report's friction force acts on collider 2 when it is the box.
        let friction = modifier
            .reports()
            .ok()
            .and_then(|r| r.first())
            .map_or(0.0, |r| {
                let f = r.friction_force[0] as f64;
                if r.collider1 == scene.box_collider {
                    -f
                } else {
                    f
                }
            });
        out.push(Example1Sample {
            t: (k + 1) as f64 * dt,
            x: scene.x() - x0,
            v: scene.vx(),
            friction,
        });
    }
    out
}

/// The vibratory feeder of `crates/stickslip-fixtures/tests/rapier_feeder.rs` in rapier: a kinematic trough (friction
/// μ) moving as `feeder`'s trough at frequency `frequency` carries a 4 cm cube (rotations
/// locked). With `ep = Some(c)` the trough's contact uses the elasto-plastic law (μ_ba = μ_max
/// = μ, flat curve, stiffness c), otherwise plain rapier Coulomb friction. Returns the part's
/// mean speed along x (m/s) over `measure` periods after `settle` periods, at step `dt`.
pub fn feeder_speed(
    feeder: &stickslip_theory::feeder::VibratoryFeeder,
    frequency: f64,
    mu: f64,
    dt: f64,
    ep: Option<f64>,
    settle: usize,
    measure: usize,
) -> Result<f64, stickslip_core::ParamError> {
    use stickslip_core::law::Law;
    use stickslip_core::sliding_curve::Curve;
    let mut world = PhysicsWorld::default();
    world.integration_parameters.dt = dt as f32;
    let trough = world.insert_body(RigidBodyBuilder::kinematic_position_based());
    let trough_collider =
        world.insert_collider(cuboid3(50.0, 0.05, 1.0).0.friction(mu as f32), Some(trough));
    let half = 0.02f32;
    let (v0x, v0y) = feeder.trough_velocity(0.0);
    let (part, part_collider) = world.insert(
        RigidBodyBuilder::dynamic()
            .translation(v3(0.0, 0.05 + half, 0.0))
            .linvel(v3(v0x as f32, v0y as f32, 0.0))
            .lock_rotations()
            .can_sleep(false),
        cuboid3(half, half, half)
            .0
            .density(1000.0)
            .friction(mu as f32),
    );
    let mut friction = match ep {
        Some(c) => {
            let law = Law::elasto_plastic(c, mu, mu, Curve::constant(mu)?)?;
            let mut m =
                stickslip_rapier::StickSlip::new(stickslip_rapier::FrictionMaterial::new(law));
            m.attach(&mut world.colliders, trough_collider, None);
            m.attach(&mut world.colliders, part_collider, None);
            Some(m)
        }
        None => None,
    };
    let period = 1.0 / frequency;
    let (settle, measure) = (settle as f64 * period, measure as f64 * period);
    let steps = ((settle + measure) / dt).round() as usize;
    let mut x_start = None;
    for k in 0..steps {
        let t_next = (k + 1) as f64 * dt;
        let (x, y) = feeder.trough_position(t_next);
        world.bodies[trough].set_next_kinematic_translation(v3(x as f32, y as f32, 0.0));
        match friction.as_mut() {
            Some(m) => m.step(&mut world),
            None => world.step(),
        }
        if x_start.is_none() && t_next >= settle {
            x_start = Some((world.bodies[part].translation().x as f64, t_next));
        }
    }
    let (x0, t0) = x_start.unwrap_or((0.0, 0.0));
    Ok((world.bodies[part].translation().x as f64 - x0) / (steps as f64 * dt - t0))
}
