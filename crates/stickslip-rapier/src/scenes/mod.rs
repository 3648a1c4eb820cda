//! Ready-made reference scenes: the worlds stickslip's tests, examples and benchmarks measure
//! against analytic results (a box on an incline, on a belt, dragged over a vibrating plate, the
//! seed's Example 1), plus [`Conveyor`], a surface-velocity hook to wrap.

use rapier::prelude::*;

pub mod ordinary;

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
        world.gravity = Vector::new(self.gravity * s, -self.gravity * c, 0.0);
        let ground = world.insert_collider(
            ColliderBuilder::cuboid(200.0, 0.1, 50.0).friction(0.0),
            None,
        );
        let h = self.half;
        let (body, box_collider) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(0.0, 0.1 + h, 0.0))
                .can_sleep(false)
                .enabled_rotations(self.rotations, self.rotations, self.rotations),
            ColliderBuilder::cuboid(h, h, h)
                .density(self.mass / (8.0 * h * h * h))
                .friction(0.0),
        );
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

/// A conveyor written as a user's own hook (the tests of wrapped hooks; stickslip's own is
/// [`crate::StickSlip::set_surface_velocity`]): the `belt` collider's surface moves at
/// `velocity` (world), through rapier's per-contact target tangent velocity. Flag the belt
/// collider with
/// `ActiveHooks::MODIFY_SOLVER_CONTACTS` (as without stickslip), wrap the conveyor with
/// [`crate::StickSlip::with_hooks`], and the friction law works relative to the moving
/// surface.
#[derive(Debug, Clone, Copy)]
pub struct Conveyor {
    /// The belt collider.
    pub belt: ColliderHandle,
    /// Surface velocity (m/s, world).
    pub velocity: Vector,
}

#[cfg(rapier_035)]
use crate::rapier_compat::RigidManifold;

impl PhysicsHooks for Conveyor {
    fn modify_solver_contacts(&self, ctx: &mut ContactModificationContext) {
        // tangent_velocity is the target velocity of collider 2 relative to collider 1.
        let v = if ctx.collider1 == self.belt {
            self.velocity
        } else if ctx.collider2 == self.belt {
            -self.velocity
        } else {
            return;
        };
        if let Some(m) = ctx.rigid_mut() {
            for c in m.solver_contacts.iter_mut() {
                c.tangent_velocity = v;
            }
        }
    }
}

/// A weightless 0.2 m sled of `mass` on a fixed plate, stepped at `dt`, its contact
/// elasto-plastic in the seed's sharp limit (μ_ba = μ_max = μ0, flat curve) with stiffness `c`,
/// per-contact reports on: the setup of [`PopovDrag`] and [`VibratingPlate`].
fn sled_on_plate(
    mass: f32,
    dt: f64,
    c: f64,
    mu0: f64,
) -> Result<(BoxScene, crate::StickSlip), stickslip_core::ParamError> {
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
    let mut modifier = crate::StickSlip::new(crate::FrictionMaterial::new(law))
        .with_read_back(crate::ReadBack::Contacts);
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
    /// A normal [`crate::VibrationSource`] on the plate, in the given mode.
    Source(crate::VibrationMode),
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
                PopovDrive::Source(crate::VibrationMode::Averaged) => 40,
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
            let src = crate::VibrationSource::new(
                crate::VibrationDirection::Normal,
                crate::Amplitude::Ratio(self.alpha),
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
                (5.0 * crate::StickSlipConfig::default().stiffness_time * f).ceil() as usize
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
            b.set_linvel(Vector::new(v0 as f32, b.linvel().y, 0.0), true);
            scene.set_force(Vector::new(0.0, -((self.normal_force + extra) as f32), 0.0));
            modifier.step(&mut scene.world);
            if k >= warm * self.steps_per_period
                && let Some(r) = modifier.reports().ok().and_then(|r| r.first())
            {
                sum_fx += -r.friction_force[0] as f64;
                sum_fz += match self.drive {
                    // The law saw F̄ (1 + α w); the solver's normal force is F̄.
                    PopovDrive::Source(crate::VibrationMode::TimeResolved) => {
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

/// The seed's Example 1 in rapier: a 1 kg box (rotations locked) on the ground under the
/// tangential force `profile`, with the friction `law`, at step `dt`. Returns the box's
/// displacement at each of `times` (s) and its velocity at the end.
pub fn example1(
    law: stickslip_core::law::Law,
    profile: &stickslip_core::block::ForceProfile,
    dt: f64,
    times: &[f64],
) -> (Vec<f64>, f64) {
    let end = times.iter().cloned().fold(0.0, f64::max);
    let trace = example1_trace(law, profile, dt, end);
    let mut out = Vec::with_capacity(times.len());
    for s in &trace {
        for &ti in times {
            if (s.t - ti).abs() < 0.5 * dt {
                out.push(s.x);
            }
        }
    }
    (out, trace.last().map_or(0.0, |s| s.v))
}

/// [`example1`] step by step: the box's displacement, velocity and friction force after every
/// step up to `end` (s).
pub fn example1_trace(
    law: stickslip_core::law::Law,
    profile: &stickslip_core::block::ForceProfile,
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
    let mut modifier = crate::StickSlip::new(crate::FrictionMaterial::new(law))
        .with_read_back(crate::ReadBack::Contacts);
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
        scene.set_force(Vector::new(profile.value(t_mid) as f32, 0.0, 0.0));
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

/// The vibratory feeder of `tests/rapier_feeder.rs` in rapier: a kinematic trough (friction
/// μ) moving as `feeder`'s trough at frequency `frequency` carries a 4 cm cube (rotations
/// locked). With `ep = Some(c)` the trough's contact uses the elasto-plastic law (μ_ba = μ_max
/// = μ, flat curve, stiffness c), otherwise plain rapier Coulomb friction. Returns the part's
/// mean speed along x (m/s) over `measure` periods after `settle` periods, at step `dt`.
pub fn feeder_speed(
    feeder: &stickslip_core::feeder::VibratoryFeeder,
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
    let trough_collider = world.insert_collider(
        ColliderBuilder::cuboid(50.0, 0.05, 1.0).friction(mu as f32),
        Some(trough),
    );
    let half = 0.02f32;
    let (v0x, v0y) = feeder.trough_velocity(0.0);
    let (part, part_collider) = world.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, 0.05 + half, 0.0))
            .linvel(Vector::new(v0x as f32, v0y as f32, 0.0))
            .lock_rotations()
            .can_sleep(false),
        ColliderBuilder::cuboid(half, half, half)
            .density(1000.0)
            .friction(mu as f32),
    );
    let mut friction = match ep {
        Some(c) => {
            let law = Law::elasto_plastic(c, mu, mu, Curve::constant(mu)?)?;
            let mut m = crate::StickSlip::new(crate::FrictionMaterial::new(law));
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
        world.bodies[trough].set_next_kinematic_translation(Vector::new(x as f32, y as f32, 0.0));
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

/// A sled on a fixed plate that carries a vibration source of any components (normal,
/// tangential along x, transverse along z), pressed by the force F̄ with gravity off. Its
/// contact is elasto-plastic in the seed's sharp limit (μ_ba = μ_max = μ0, flat sliding curve)
/// with stiffness c, so the theory's contact is
/// [`CompliantContact`](stickslip_core::popov::CompliantContact)`(k_x = c F̄, k_z = F̄, μ0,
/// ū_z = 1)`: a normal amplitude ratio r is A_z = r, an in-plane one A = r F̄/k_x = r/c, and
/// the theory's x axis is −x (the plate moves the sled's base by −A w relative to it).
///
/// [`VibratingPlate::drag`] imposes the sled's velocity and measures μ̄ (Popov's experiment),
/// [`VibratingPlate::run_free`] lets the sled go with no tangential force and measures its
/// mean speed. The theory assumes a quasi-static sled: the sled's resonance on the contact
/// spring, √(c F̄/m), must lie well below 2πf.
#[derive(Debug, Clone)]
pub struct VibratingPlate {
    /// Coefficient of friction μ0.
    pub mu0: f64,
    /// Law stiffness c (1/m).
    pub c: f64,
    /// Vibration frequency f (Hz).
    pub frequency: f64,
    /// Mean normal force F̄ (N).
    pub normal_force: f64,
    /// The source's components (amplitudes as [`crate::Amplitude::Ratio`] of F̄).
    pub components: Vec<crate::VibrationComponent>,
    /// Mode of the source.
    pub mode: crate::VibrationMode,
    /// Steps per vibration period.
    pub steps_per_period: usize,
    /// Mass of the sled (kg).
    pub sled_mass: f32,
}

/// What a [`VibratingPlate`] run measured.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlateMeasurement {
    /// μ̄ = −⟨F_x⟩/⟨F_z⟩ of the friction on the sled along x (positive: resisting +x).
    pub mu_eff: f64,
    /// Mean sled velocity along x over the measured periods (m/s).
    pub velocity: f64,
}

impl VibratingPlate {
    /// Elliptical vibration: normal ratio `alpha` (phase 0) and tangential ratio
    /// `tangential` along +x shifted by `phase_shift` periods, both sines (either may be 0);
    /// μ0 = 0.5, c = 1e4 1/m, F̄ = 9.81 N, f = 50 Hz, 400 steps per period (40 averaged), a
    /// 100 kg sled (resonance √(c F̄/m)/2π = 5 Hz, a tenth of f).
    pub fn elliptical(
        alpha: f64,
        tangential: f64,
        phase_shift: f64,
        mode: crate::VibrationMode,
    ) -> Result<Self, stickslip_core::ParamError> {
        use stickslip_core::waveform::Waveform;
        let mut components = Vec::new();
        if alpha > 0.0 || tangential <= 0.0 {
            components.push(crate::VibrationComponent::new(
                crate::VibrationDirection::Normal,
                crate::Amplitude::Ratio(alpha),
                Waveform::Sine,
                0.0,
            )?);
        }
        if tangential > 0.0 {
            components.push(crate::VibrationComponent::new(
                crate::VibrationDirection::Tangential {
                    axis: [1.0, 0.0, 0.0],
                },
                crate::Amplitude::Ratio(tangential),
                Waveform::Sine,
                phase_shift,
            )?);
        }
        Ok(VibratingPlate {
            mu0: 0.5,
            c: 1e4,
            frequency: 50.0,
            normal_force: 9.81,
            components,
            mode,
            steps_per_period: match mode {
                crate::VibrationMode::Averaged => 40,
                crate::VibrationMode::TimeResolved => 400,
            },
            sled_mass: 100.0,
        })
    }

    /// The vibration source on the plate.
    pub fn source(&self) -> Result<crate::VibrationSource, stickslip_core::ParamError> {
        crate::VibrationSource::superimposed(&self.components, self.frequency, self.mode)
    }

    /// The theory's contact.
    pub fn contact(
        &self,
    ) -> Result<stickslip_core::popov::CompliantContact, stickslip_core::ParamError> {
        let f = self.normal_force;
        stickslip_core::popov::CompliantContact::new(self.c * f, f, self.mu0, 1.0)
    }

    /// The theory's excitation (displacements, see the type's docs).
    pub fn excitation(
        &self,
    ) -> Result<stickslip_core::popov::Excitation, stickslip_core::ParamError> {
        let mut ex = self.source()?.excitation(self.mu0, self.normal_force)?;
        // In-plane amplitudes come in slip lengths of 1; the contact's is μ0/c.
        let len = self.mu0 / self.c;
        for o in [&mut ex.tangential, &mut ex.transverse]
            .into_iter()
            .flatten()
        {
            *o = stickslip_core::popov::Oscillation::new(
                o.amplitude() * len,
                o.waveform().clone(),
                o.phase(),
            )?;
        }
        Ok(ex)
    }

    /// The theory's μ̄ of the sled dragged at `vx` along x (positive: resisting +x).
    pub fn theory_mu(&self, vx: f64) -> Result<f64, stickslip_core::ParamError> {
        let mu = stickslip_core::popov::mean_friction(
            &self.contact()?,
            &self.excitation()?,
            self.frequency,
            -vx,
        )?;
        Ok(-mu)
    }

    /// The theory's free drive velocity of the sled along x (0 if it rests).
    pub fn theory_drive_velocity(&self) -> Result<f64, stickslip_core::ParamError> {
        let v = stickslip_core::popov::free_drive_velocity(
            &self.contact()?,
            &self.excitation()?,
            self.frequency,
        )?;
        Ok(-v.unwrap_or(0.0))
    }

    /// The theory's blocking force along x (N): the force that holds the sled at rest
    /// (negative when the vibration drives it towards +x).
    pub fn theory_blocking_force(&self) -> Result<f64, stickslip_core::ParamError> {
        let b = stickslip_core::popov::blocking_force(&self.contact()?, &self.excitation()?)?;
        Ok(-b)
    }

    /// Drags the sled at `vx` (imposed every step) for `warm` periods, then measures μ̄ over
    /// `periods` periods.
    pub fn drag(
        &self,
        vx: f64,
        warm: usize,
        periods: usize,
    ) -> Result<PlateMeasurement, stickslip_core::ParamError> {
        self.run(Some(vx), 0.0, warm, periods)
    }

    /// Lets the sled go from `v_start` with no tangential force for `warm` periods, then
    /// measures its mean velocity and μ̄ over `periods` periods.
    pub fn run_free(
        &self,
        v_start: f64,
        warm: usize,
        periods: usize,
    ) -> Result<PlateMeasurement, stickslip_core::ParamError> {
        self.run(None, v_start, warm, periods)
    }

    fn run(
        &self,
        imposed: Option<f64>,
        v_start: f64,
        warm: usize,
        periods: usize,
    ) -> Result<PlateMeasurement, stickslip_core::ParamError> {
        let f = self.frequency;
        let spp = self.steps_per_period.max(1);
        let dt = 1.0 / (f * spp as f64);
        let (mut scene, mut modifier) = sled_on_plate(self.sled_mass, dt, self.c, self.mu0)?;
        let source = self.source()?;
        let normal = source.normal().cloned();
        modifier.set_vibration(scene.ground, source);
        let press = Vector::new(0.0, -(self.normal_force as f32), 0.0);
        let v0 = imposed.unwrap_or(v_start);
        scene.world.bodies[scene.body].set_linvel(Vector::new(v0 as f32, 0.0, 0.0), true);
        let (mut sum_fx, mut sum_fz) = (0.0, 0.0);
        let mut x_start = 0.0;
        let total = (warm + periods) * spp;
        for k in 0..total {
            if k == warm * spp {
                x_start = scene.x();
            }
            if let Some(v) = imposed {
                let b = &mut scene.world.bodies[scene.body];
                b.set_linvel(Vector::new(v as f32, b.linvel().y, 0.0), true);
            }
            scene.set_force(press);
            let t_mid = (k as f64 + 0.5) * dt;
            modifier.step(&mut scene.world);
            if k >= warm * spp
                && let Some(r) = modifier.reports().ok().and_then(|r| r.first())
            {
                // The report's friction acts on body 2.
                let on_sled = if r.collider2 == scene.ground {
                    -1.0
                } else {
                    1.0
                };
                sum_fx += -on_sled * r.friction_force[0] as f64;
                let factor = match (&normal, self.mode) {
                    // The law saw F̄ (1 + α w)⁺; the solver's normal force is F̄.
                    (Some(c), crate::VibrationMode::TimeResolved) => {
                        let a = c.amplitude().force(1.0);
                        (1.0 + a * c.waveform().value(f * t_mid + c.phase())).max(0.0)
                    }
                    _ => 1.0,
                };
                sum_fz += r.normal_force * factor;
            }
        }
        let time = periods as f64 / f;
        Ok(PlateMeasurement {
            mu_eff: if sum_fz > 0.0 { sum_fx / sum_fz } else { 0.0 },
            velocity: (scene.x() - x_start) / time,
        })
    }
}
