//! The built-in challenges, reachable by name wherever a challenge link is accepted. Each has a
//! known solution within the motor's 4 A rating; the tests check that it passes and that the
//! untouched base fails.

use super::{Challenge, Submission};

/// A built-in challenge.
#[derive(Clone, Copy, Debug)]
pub struct Builtin {
    /// Name, e.g. `step-tune`.
    pub name: &'static str,
    /// One line on the task.
    pub summary: &'static str,
    /// The challenge's canonical text.
    pub text: &'static str,
    /// A passing set of the allowed fields, `FIELD=VALUE&…` (for the tests and the lecturer).
    pub solution: &'static str,
}

impl Builtin {
    /// The challenge.
    pub fn challenge(&self) -> Challenge {
        Challenge::parse(self.text).expect("a built-in challenge parses")
    }

    /// The known solution as a submission.
    pub fn solved(&self) -> Submission {
        let tries: String = self
            .solution
            .split('&')
            .map(|p| format!("&try.{p}"))
            .collect();
        Submission::parse(&format!("{}{tries}", self.text)).expect("a built-in solution parses")
    }
}

/// The built-in challenges.
pub const BUILTINS: &[Builtin] = &[
    Builtin {
        name: "step-tune",
        summary: "Tune k1–k4 so a sharp 0.5 rad/s step settles within 4 ms while |i_s| stays within the 4 A rating",
        // The paper's step goes through a 200 Hz filter whose own 2 % settling takes 4.6 ms, so
        // the gains could not move it; a 1.6 kHz filter (ω_n = 10⁴ rad/s) leaves it to them.
        text: "c=1&title=Fast%20step%20within%20the%20rating&base=v%3D1%26preset%3Dstep%26step.wn%3D10000\
               &allow.k1=300..5000&allow.k2=300..5000&allow.k3=300..5000&allow.k4=300..5000\
               &need.settling_time=max:0.004&need.current_peak=max:4\
               &vary=seeds:2..3&robust=settling_time,current_peak",
        solution: "k1=2000&k2=2000&k3=1500&k4=1500",
    },
    Builtin {
        name: "load-observer",
        summary: "Keep 50 rad/s through an unknown 2 N m load step with observer settings only: settled final speed error within ±0.05 rad/s and a consistent EKF",
        // Tuning Q alone cannot do it: with the 5-state EKF no ekf.q, ekf.q_speed, ekf.r_std or
        // predictor gives a settled final error (the speed chatters at the voltage limit) or a
        // mean NIS inside its band; the load must become a state of the EKF.
        text: "c=1&title=Observe%20the%20unknown%20load&base=v%3D1%26preset%3Dload-step%26duration%3D1\
               &allow.ekf=euler|rk4&allow.ekf.q=0.000001..1&allow.ekf.q_speed=0..1000000000\
               &allow.ekf.r_std=0.0005..0.02&allow.ekf.load=0..1&allow.ekf.q_load=0.01..1000\
               &need.speed_error_final=abs:0.05&need.mean_nis=band&need.current_peak=max:4\
               &vary=seeds:2..3&robust=speed_error_final",
        solution: "ekf=rk4&ekf.q=0.00001&ekf.load=1",
    },
    Builtin {
        name: "ifoc-load",
        summary: "Tune the sensorless IFOC baseline to recover from an unknown 2 N m load step within 0.1 s without exceeding the 4 A rating",
        text: "c=1&title=IFOC%20load%20rejection&base=v%3D1%26preset%3Difoc-step%26load.time%3D0.5%26load.torque%3D2%26duration%3D1.5\
               &allow.ifoc.bw_i=100..3000&allow.ifoc.bw_w=1..100&allow.ifoc.bw_mras=5..1000\
               &allow.ifoc.i_max=1..20&allow.ifoc.ff=0..1\
               &need.load_recovery_time=max:0.1&need.current_peak=max:4",
        solution: "ifoc.bw_w=20&ifoc.bw_mras=20&ifoc.i_max=3.6",
    },
];

/// The built-in challenge named `name`.
pub fn builtin(name: &str) -> Option<&'static Builtin> {
    BUILTINS.iter().find(|b| b.name == name)
}
