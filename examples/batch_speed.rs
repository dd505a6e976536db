use kli::batch::*;
fn main() {
    let n = 1_000_000;
    let a: Vec<f64> = (0..4 * n).map(|i| if i % 4 == 0 { 1.0 } else { 0.1 }).collect();
    let b: Vec<f64> = (0..4 * n).map(|i| if i % 4 == 1 { 1.0 } else { 0.2 }).collect();
    let s = vec![0.3; n];
    let mut out = vec![0.0; 4 * n];
    for _ in 0..3 {
        let t = std::time::Instant::now();
        nlerp_batch(&a, &b, &s, &mut out).unwrap();
        let t1 = t.elapsed();
        let t = std::time::Instant::now();
        slerp_batch(&a, &b, &s, &mut out, true).unwrap();
        let t2 = t.elapsed();
        let t = std::time::Instant::now();
        kli_exact_batch(&a, &b, &s, &mut out, true).unwrap();
        println!("nlerp {t1:?} slerp {t2:?} kli {:?}", t.elapsed());
    }
}
#[allow(dead_code)]
fn calibrate() {}
