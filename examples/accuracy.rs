use kli::*;
fn main() {
    let p = from_wxyz([0.0, 0.0, 0.0, 1.0]);
    let r = from_wxyz([0.5; 4]);
    for integ in Integrator::ALL {
        let path = kli(p, r, &KliOptions { integrator: integ, ..Default::default() }).unwrap();
        let mut err: f64 = 0.0; let mut drift: f64 = 0.0;
        for (t, q) in path.times().iter().zip(path.quaternions()) {
            err = err.max((*q - path.at(*t).unwrap()).length());
            drift = drift.max((q.length() - 1.0).abs());
        }
        println!("{integ}: T={} steps={} max|q-exact|={err:e} max||q|-1|={drift:e}", path.final_time(), path.steps());
    }
}
