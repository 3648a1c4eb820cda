//! A sled on a plate under superimposed vibration, measured against Popov's compliant theory.

use crate::sled_on_plate;
use stickslip_rapier::rapier::prelude::*;

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
    /// The source's components (amplitudes as [`stickslip_rapier::Amplitude::Ratio`] of F̄).
    pub components: Vec<stickslip_rapier::VibrationComponent>,
    /// Mode of the source.
    pub mode: stickslip_rapier::VibrationMode,
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
        mode: stickslip_rapier::VibrationMode,
    ) -> Result<Self, stickslip_core::ParamError> {
        use stickslip_core::waveform::Waveform;
        let mut components = Vec::new();
        if alpha > 0.0 || tangential <= 0.0 {
            components.push(stickslip_rapier::VibrationComponent::new(
                stickslip_rapier::VibrationDirection::Normal,
                stickslip_rapier::Amplitude::Ratio(alpha),
                Waveform::Sine,
                0.0,
            )?);
        }
        if tangential > 0.0 {
            components.push(stickslip_rapier::VibrationComponent::new(
                stickslip_rapier::VibrationDirection::Tangential {
                    axis: [1.0, 0.0, 0.0],
                },
                stickslip_rapier::Amplitude::Ratio(tangential),
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
                stickslip_rapier::VibrationMode::Averaged => 40,
                stickslip_rapier::VibrationMode::TimeResolved => 400,
            },
            sled_mass: 100.0,
        })
    }

    /// The vibration source on the plate.
    pub fn source(&self) -> Result<stickslip_rapier::VibrationSource, stickslip_core::ParamError> {
        stickslip_rapier::VibrationSource::superimposed(&self.components, self.frequency, self.mode)
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
                    (Some(c), stickslip_rapier::VibrationMode::TimeResolved) => {
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
