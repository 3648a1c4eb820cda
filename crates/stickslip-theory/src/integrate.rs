//! The one place the reference simulators pick an adaptive method from
//! `differential-equations` (a macro, because the explicit and implicit method types differ).

/// Solves the IVP `$ivp` with the method `$integrator` ([`crate::block::Integrator`]) at the
/// tolerances `$tol` ([`crate::block::Tolerances`]), mapping failures to
/// [`crate::block::SimError::Solver`].
macro_rules! solve_with {
    ($integrator:expr, $tol:expr, $ivp:expr) => {
        match $integrator {
            $crate::block::Integrator::Explicit => $ivp
                .method(
                    ExplicitRungeKutta::rkf45()
                        .rtol($tol.rtol)
                        .atol($tol.atol)
                        .max_steps($tol.max_steps)
                        .max_rejects(10_000),
                )
                .solve(),
            $crate::block::Integrator::DormandPrince => $ivp
                .method(
                    ExplicitRungeKutta::dopri5()
                        .rtol($tol.rtol)
                        .atol($tol.atol)
                        .max_steps($tol.max_steps)
                        .max_rejects(10_000),
                )
                .solve(),
            $crate::block::Integrator::Implicit => $ivp
                .method(
                    DiagonallyImplicitRungeKutta::esdirk324l2sa()
                        .rtol($tol.rtol)
                        .atol($tol.atol)
                        .max_steps($tol.max_steps)
                        // differential-equations 0.7's DIRK never resets its rejection counter
                        // on an accepted step, so the cap bounds the rejections of the whole
                        // run: make it the step budget.
                        .max_rejects($tol.max_steps),
                )
                .solve(),
        }
        .map_err(|e| $crate::block::SimError::Solver(format!("{e:?}")))
    };
}

pub(crate) use solve_with;
