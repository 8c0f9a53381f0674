//! Every number of lecture Fig. 1.3 (physics.md case A) from the library API:
//! a 4-ton SUV at 60 mph rear-ends a 1-ton VW at 10 mph.
//!
//!     cargo run --example case_a

use collide::line::case::{Case, parse_masses, parse_velocities};
use collide::line::inertia::InertiaTensor;
use collide::report::{Report, Section, Sections};
use collide::solver::binary64::Binary64;

fn main() -> anyhow::Result<()> {
    let [m1, m2] = parse_masses("4,1").map_err(anyhow::Error::msg)?;
    let inertia = InertiaTensor::diagonal(&m1, &m2)?;
    let velocities = parse_velocities("60,10").map_err(anyhow::Error::msg)?;
    for e in ["elastic", "inelastic"] {
        let case = Case::new(
            inertia.clone(),
            velocities.clone(),
            e.parse().map_err(anyhow::Error::msg)?,
        );
        let r = Report::build(
            &Binary64::lab(&case.collision),
            &Sections::new([Section::All]),
        )?;
        let (v, m, f) = (r.vectors.unwrap(), r.momentum.unwrap(), r.forms.unwrap());
        let (en, el, p) = (r.energy.unwrap(), r.ellipses.unwrap(), r.products.unwrap());
        println!(
            "Fig. 1.3, {e}: M = {}, V_IN = {:?}",
            inertia.describe(),
            v.v_in
        );
        let mm = inertia.matrix();
        let (k1, k2) = (mm[(0, 0)] + mm[(0, 1)], mm[(0, 1)] + mm[(1, 1)]);
        println!(
            "  P_total = {}   (momentum line {k1}x + {k2}y = {})",
            m.total, m.total
        );
        println!("  V_COM = {}, COM = {:?}", v.v_com, v.com);
        println!("  FIN = {:?}", v.fin);
        println!("  V_FIN . V_IN = {}", p.dot_fin_in);
        println!("  V_IN (x) V_FIN = {:?}", p.outer_in_fin);
        println!(
            "  V_COM.M.V_IN = V_COM.M.V_FIN = V_COM P_total = {}",
            f.com_m_in
        );
        println!(
            "  V_FIN.M.V_IN = {}   V_IN.M.V_IN = {}",
            f.fin_m_in, f.in_m_in
        );
        println!(
            "  quarter forms V_IN.M.V_IN/4 = {}, V_FIN.M.V_IN/4 = {}",
            f.in_m_in / 4.0,
            f.fin_m_in / 4.0
        );
        println!(
            "  KE_IN = {}, KE_FIN = {}, KE_COM = {}",
            en.ke_in, en.fin, en.com
        );
        println!("  crunch = {}, lost = {}", en.crunch, en.lost_signed());
        println!("  IN ellipse a = {:.2}, b = {:.2}", el.e_in.a, el.e_in.b);
        println!("  COM ellipse a = {:.2}, b = {:.2}", el.com.a, el.com.b);
    }
    Ok(())
}
