//! The invariant checker (issue 24): every JSON output of collide is checked against what can
//! never be, whatever produced it and whatever the input:
//!
//! - no number that is not a number (binary64's NaN and infinity serialise as `null`);
//! - bodies in order and inside the walls at every reported state and every logged event (a
//!   track's `--log` is replayed: each event must find its pair touching, at the velocities the
//!   previous events left);
//! - energy never created where the model cannot create it (`e <= 1`, contact laws that only
//!   push), and kept where the model keeps it;
//! - momentum kept where no wall acts.
//!
//! The checks are relations between the printed numbers, so they hold in any frame and unit;
//! their tolerances are stated at each (ulps of the terms for a single solve, the integration
//! tolerance for contact). Generated inputs (proptest) feed the contact checker through the
//! library, as the track tests do.

use crate::common;
use common::stdout;

use serde_json::Value;

/// A number of the output: a JSON number, or an exact value's string (`"-7/3"`, `"2e323"`, an
/// approximate `"0.333..."`) as its nearest binary64.
pub fn num(v: &Value) -> f64 {
    match v {
        Value::Number(n) => n.as_f64().expect("a JSON number"),
        Value::String(s) => s
            .parse::<collide::values::number::Number>()
            .unwrap_or_else(|e| panic!("{s:?} is not a number: {e}"))
            .value(),
        other => panic!("{other} is not a number"),
    }
}

pub fn nums(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap_or_else(|| panic!("{v} is not a list"))
        .iter()
        .map(num)
        .collect()
}

/// Binary64's epsilon: the tolerances below are multiples of it times the terms' magnitudes.
pub const EPS: f64 = f64::EPSILON;

/// Every value of `v` is a real result: no `null` (a NaN or infinity serialised), no NaN or
/// infinity spelled out in a string.
pub fn all_real(v: &Value) -> Result<(), String> {
    fn walk(v: &Value, path: &str) -> Result<(), String> {
        match v {
            Value::Null => Err(format!("{path} is null (NaN or infinite)")),
            Value::String(s) => {
                let t = s.trim().trim_start_matches(['+', '-', '≈']).to_lowercase();
                if ["nan", "inf", "infinity"].contains(&t.as_str()) {
                    Err(format!("{path} = {s:?}"))
                } else {
                    Ok(())
                }
            }
            Value::Number(n) if !n.as_f64().is_some_and(f64::is_finite) => {
                Err(format!("{path} = {n} is not finite"))
            }
            Value::Array(a) => a
                .iter()
                .enumerate()
                .try_for_each(|(i, x)| walk(x, &format!("{path}[{i}]"))),
            Value::Object(o) => o
                .iter()
                .try_for_each(|(k, x)| walk(x, &format!("{path}.{k}"))),
            _ => Ok(()),
        }
    }
    walk(v, "")
}

/// `|a - b| <= tol`, or a message naming `what`.
pub(crate) fn near(a: f64, b: f64, tol: f64, what: &str) -> Result<(), String> {
    if (a - b).abs() <= tol {
        Ok(())
    } else {
        Err(format!("{what}: {a} against {b} (tolerance {tol:e})"))
    }
}

/// `a <= b + tol`.
pub(crate) fn at_most(a: f64, b: f64, tol: f64, what: &str) -> Result<(), String> {
    if a <= b + tol {
        Ok(())
    } else {
        Err(format!("{what}: {a} > {b} (tolerance {tol:e})"))
    }
}

/// A two-body collision as any command reports it: the inertia tensor `[[M11, M12], [M12, M22]]`,
/// `e`, IN and FIN, and when present `v_com` and the energies.
pub struct TwoBody {
    pub inertia: [[f64; 2]; 2],
    pub e: f64,
    pub v_in: [f64; 2],
    pub fin: [f64; 2],
    pub v_com: Option<f64>,
    /// `in, fin, com, crunch, lost` (lost negative when released).
    pub energy: Option<[f64; 5]>,
}

impl TwoBody {
    /// From a solve or scene report (`inertia`, `restitution`, `in`, `fin`, `v_com`, `energy`).
    pub fn of_report(r: &Value) -> TwoBody {
        let m = &r["inertia"];
        let pair = |v: &Value| -> [f64; 2] { nums(v).try_into().expect("a pair") };
        TwoBody {
            inertia: [pair(&m[0]), pair(&m[1])],
            e: num(&r["restitution"]),
            v_in: pair(&r["in"]),
            fin: pair(&r["fin"]),
            v_com: r.get("v_com").map(num),
            energy: energy_of(&r["energy"]),
        }
    }
}

/// `in, fin, com, crunch, lost` of an energy object (`released` as a negative loss).
pub(crate) fn energy_of(en: &Value) -> Option<[f64; 5]> {
    let get = |k: &str| en.get(k).map(num);
    let lost = get("lost").or_else(|| get("released").map(|r| -r))?;
    Some([get("in")?, get("fin")?, get("com")?, get("crunch")?, lost])
}

/// Momentum kept (Axiom 1: `u.M.V_IN = u.M.V_FIN`), `V_COM` the mass-weighted mean, restitution
/// (`FIN2 - FIN1 = e (IN1 - IN2)`: after an approach the bodies do not pass through each other),
/// and the energies: none negative, `KE_IN = KE_COM + crunch` (Koenig), `KE_FIN <= KE_IN` and
/// the loss `(1 - e^2) crunch >= 0` when `e <= 1`. Each is a short sum of the printed values:
/// held to 16 ulps of the magnitudes summed.
pub fn two_body(c: &TwoBody) -> Result<(), String> {
    let [[a, b], [_, d]] = c.inertia;
    let (k1, k2) = (a + b, b + d);
    let [v1, v2] = c.v_in;
    let [f1, f2] = c.fin;
    let scale = (k1 * v1).abs() + (k2 * v2).abs() + (k1 * f1).abs() + (k2 * f2).abs();
    near(
        k1 * f1 + k2 * f2,
        k1 * v1 + k2 * v2,
        16.0 * EPS * scale,
        "momentum",
    )?;
    if c.e.is_nan() || c.e < 0.0 {
        return Err(format!("restitution {} < 0", c.e));
    }
    let vscale = v1.abs() + v2.abs() + f1.abs() + f2.abs();
    near(
        f2 - f1,
        c.e * (v1 - v2),
        16.0 * EPS * (vscale + c.e * (v1.abs() + v2.abs())),
        "restitution FIN2 - FIN1 = e (IN1 - IN2)",
    )?;
    if let Some(vc) = c.v_com {
        let mean = (k1 * v1 + k2 * v2) / (k1 + k2);
        near(vc, mean, 16.0 * EPS * (v1.abs() + v2.abs()), "V_COM")?;
    }
    if let Some([ke_in, ke_fin, ke_com, crunch, lost]) = c.energy {
        for (what, x) in [("KE_IN", ke_in), ("KE_FIN", ke_fin), ("KE_COM", ke_com)] {
            at_most(0.0, x, 0.0, &format!("{what} >= 0"))?;
        }
        at_most(0.0, crunch, 0.0, "crunch >= 0")?;
        near(
            ke_in,
            ke_com + crunch,
            16.0 * EPS * ke_in,
            "KE_IN = KE_COM + crunch",
        )?;
        if c.e <= 1.0 {
            at_most(0.0, lost, 0.0, "energy lost >= 0 (e <= 1)")?;
            at_most(
                ke_fin,
                ke_in,
                16.0 * EPS * ke_in,
                "KE_FIN <= KE_IN (e <= 1)",
            )?;
        }
        near(
            ke_in - ke_fin,
            lost,
            16.0 * EPS * ke_in,
            "KE_IN - KE_FIN = lost",
        )?;
    }
    Ok(())
}

/// A row of `sweep` or `batch` (default columns) as a two-body collision.
pub fn table_row(row: &Value) -> Result<(), String> {
    let g = |k: &str| row.get(k).map(num);
    let inertia = match (g("m1"), g("m2")) {
        (Some(m1), Some(m2)) => [[m1, 0.0], [0.0, m2]],
        _ => {
            let (a, b, d) = (g("m11").unwrap(), g("m12").unwrap(), g("m22").unwrap());
            [[a, b], [b, d]]
        }
    };
    let energy = match (g("ke_in"), g("ke_fin"), g("crunch"), g("lost")) {
        (Some(ke_in), Some(ke_fin), Some(crunch), Some(lost)) => {
            Some([ke_in, ke_fin, ke_in - crunch, crunch, lost])
        }
        _ => None,
    };
    two_body(&TwoBody {
        inertia,
        e: g("e").unwrap(),
        v_in: [g("v1").unwrap(), g("v2").unwrap()],
        fin: [g("fin1").unwrap(), g("fin2").unwrap()],
        v_com: g("v_com"),
        energy,
    })
}

/// A frames table (`collide frames --format json`) of a case with `inertia`: every row a
/// two-body collision, every row's crunch and loss the invariants'.
pub fn frames(inertia: [[f64; 2]; 2], t: &Value) -> Result<(), String> {
    let inv = &t["invariants"];
    let e = num(&inv["restitution"]);
    for row in t["frames"].as_array().unwrap() {
        let pair = |v: &Value| -> [f64; 2] { nums(v).try_into().unwrap() };
        let c = TwoBody {
            inertia,
            e,
            v_in: pair(&row["in"]),
            fin: pair(&row["fin"]),
            v_com: None,
            energy: energy_of(&row["energy"]),
        };
        two_body(&c).map_err(|m| format!("frame {}: {m}", row["name"]))?;
        let en = c.energy.unwrap();
        near(
            en[3],
            num(&inv["crunch"]),
            4.0 * EPS * en[3],
            "crunch in every frame",
        )?;
    }
    Ok(())
}

/// A layout on the track (`track` and `contact`).
#[derive(Clone, Debug)]
pub struct Layout {
    pub m: Vec<f64>,
    pub x: Vec<f64>,
    pub v: Vec<f64>,
    pub sizes: Vec<f64>,
    pub left: Option<f64>,
    pub right: Option<f64>,
    pub gravity: f64,
}

impl Layout {
    pub fn new(m: &[f64], x: &[f64], v: &[f64], sizes: &[f64]) -> Layout {
        Layout {
            m: m.to_vec(),
            x: x.to_vec(),
            v: v.to_vec(),
            sizes: sizes.to_vec(),
            left: None,
            right: None,
            gravity: 0.0,
        }
    }

    pub fn walls(mut self, left: Option<f64>, right: Option<f64>) -> Layout {
        self.left = left;
        self.right = right;
        self
    }

    /// The command-line flags of the layout.
    pub fn args(&self) -> Vec<String> {
        let list = |x: &[f64]| {
            x.iter()
                .map(|v| format!("{v:e}"))
                .collect::<Vec<_>>()
                .join(",")
        };
        let mut a = vec![
            "-m".into(),
            list(&self.m),
            "-x".into(),
            list(&self.x),
            "-v".into(),
            list(&self.v),
            "--sizes".into(),
            list(&self.sizes),
        ];
        if let Some(l) = self.left {
            a.extend(["--left-wall".into(), format!("{l:e}")]);
        }
        if let Some(r) = self.right {
            a.extend(["--right-wall".into(), format!("{r:e}")]);
        }
        a
    }

    fn momentum(&self, v: &[f64]) -> (f64, f64) {
        let p = self.m.iter().zip(v).map(|(m, v)| m * v).sum();
        let scale = self.m.iter().zip(v).map(|(m, v)| (m * v).abs()).sum();
        (p, scale)
    }

    /// Bodies in order (gaps at least the half sizes, less `slack` of length) and inside the
    /// walls, at state `x` (time `t`, for the message).
    fn in_order(&self, x: &[f64], slack: f64, t: f64) -> Result<(), String> {
        let s = &self.sizes;
        for i in 1..x.len() {
            at_most(
                (s[i - 1] + s[i]) / 2.0,
                x[i] - x[i - 1],
                slack,
                &format!("t = {t}: bodies {i} and {} in order", i + 1),
            )?;
        }
        if let Some(l) = self.left {
            at_most(
                l,
                x[0] - s[0] / 2.0,
                slack,
                &format!("t = {t}: body 1 right of the left wall"),
            )?;
        }
        if let Some(r) = self.right {
            let n = x.len() - 1;
            at_most(
                x[n] + s[n] / 2.0,
                r,
                slack,
                &format!("t = {t}: body {} left of the right wall", n + 1),
            )?;
        }
        Ok(())
    }

    /// The length scale of positions, for tolerances.
    fn length(&self) -> f64 {
        self.x
            .iter()
            .chain(self.left.iter())
            .chain(self.right.iter())
            .fold(1.0f64, |a, b| a.max(b.abs()))
    }

    fn speed(&self) -> f64 {
        self.v.iter().fold(0.0f64, |a, b| a.max(b.abs()))
    }
}

/// A track run (`collide track --format json`) with restitutions `(e, e_wall)`, and the events of
/// its `--log` (JSON Lines, in order): the final state in order and inside the walls; every
/// event replayed by free flight from the layout (under gravity: parabolas), finding its bodies
/// touching, with the velocities the events before left them, and bodies in order and inside
/// the walls at that instant; each pair collision keeping the pair's momentum, creating no
/// energy and leaving them apart; each wall collision reversing the velocity by `e_wall`; total
/// energy never created (`e, e_wall <= 1`), kept when elastic, momentum kept without walls and
/// gravity. Tolerances: 1e-9 of the layout's length and speed scales, after many events.
pub fn track(
    l: &Layout,
    (e, e_wall): (f64, f64),
    out: &Value,
    log: &[Value],
) -> Result<(), String> {
    all_real(out)?;
    let (len, speed) = (l.length(), l.speed().max(1.0));
    let n = l.m.len();
    let mut x = l.x.clone();
    let mut v = l.v.clone();
    let mut t = 0.0;
    // Bodies at rest on the floor (a rebound logged as 0 there): gravity does not move them
    // until an event changes their velocity.
    let mut resting = vec![false; n];
    for ev in log {
        all_real(ev)?;
        let at = num(&ev["t"]);
        let dt = at - t;
        at_most(0.0, dt, 0.0, "events in time order")?;
        for i in 0..n {
            if resting[i] {
                continue;
            }
            x[i] += v[i] * dt - 0.5 * l.gravity * dt * dt;
            v[i] -= l.gravity * dt;
        }
        t = at;
        let slack = 1e-9 * (len + speed * t.max(1.0));
        l.in_order(&x, slack, t)?;
        let who = ev["who"].as_str().unwrap();
        let (before, after) = (nums(&ev["before"]), nums(&ev["after"]));
        // Under gravity the engine puts a body at rest on its support when its speed is within
        // what the positions resolve (`|v| <= sqrt(2 g slack)`, slack = 2^-40 of the positions'
        // magnitudes, docs/track.md): a replay in free fall may differ from it by a few times
        // that speed.
        let settle = if l.gravity > 0.0 {
            8.0 * (2.0 * l.gravity * len / (1u64 << 40) as f64).sqrt()
        } else {
            0.0
        };
        let vtol = 1e-9 * (speed + l.gravity * t) + settle;
        if let Some((a, b)) = who.split_once(" & ") {
            match (a.parse::<usize>(), b.parse::<usize>()) {
                (Ok(i), Ok(j)) => {
                    let (i, j) = (i - 1, j - 1);
                    near(
                        x[j] - x[i],
                        (l.sizes[i] + l.sizes[j]) / 2.0,
                        slack,
                        &format!("t = {t}: {who} touching"),
                    )?;
                    near(
                        before[0],
                        v[i],
                        vtol,
                        &format!("t = {t}: {who} v{} before", i + 1),
                    )?;
                    near(
                        before[1],
                        v[j],
                        vtol,
                        &format!("t = {t}: {who} v{} before", j + 1),
                    )?;
                    let (mi, mj) = (l.m[i], l.m[j]);
                    let p_scale = (mi * before[0]).abs() + (mj * before[1]).abs();
                    near(
                        mi * after[0] + mj * after[1],
                        mi * before[0] + mj * before[1],
                        16.0 * EPS * p_scale,
                        &format!("t = {t}: {who} momentum"),
                    )?;
                    let ke = |a: f64, b: f64| 0.5 * mi * a * a + 0.5 * mj * b * b;
                    let ke0 = ke(before[0], before[1]);
                    at_most(
                        ke(after[0], after[1]),
                        ke0,
                        16.0 * EPS * ke0,
                        &format!("t = {t}: {who} energy"),
                    )?;
                    at_most(
                        after[0],
                        after[1],
                        16.0 * EPS * speed,
                        &format!("t = {t}: {who} apart after"),
                    )?;
                    v[i] = after[0];
                    v[j] = after[1];
                    resting[i] = false;
                    resting[j] = false;
                }
                _ => {
                    // "left wall & 1" or "3 & right wall".
                    let (i, wall) = if a == "left wall" {
                        (b.parse::<usize>().unwrap() - 1, l.left.unwrap())
                    } else {
                        (a.parse::<usize>().unwrap() - 1, l.right.unwrap())
                    };
                    let edge = if a == "left wall" {
                        x[i] - l.sizes[i] / 2.0
                    } else {
                        x[i] + l.sizes[i] / 2.0
                    };
                    near(edge, wall, slack, &format!("t = {t}: {who} touching"))?;
                    near(before[0], v[i], vtol, &format!("t = {t}: {who} v before"))?;
                    // Under gravity a rebound too small to lift the body by more than the
                    // engine's position tolerance (2^-40 of the positions' magnitudes,
                    // `track::motion::slack`) is a body at rest on the floor (docs/track.md):
                    // 0, where e v would rise v^2 / 2g below that tolerance.
                    let tolerance = (x[i].abs() + wall.abs() + l.sizes[i]) / (1u64 << 40) as f64;
                    let rests = l.gravity > 0.0
                        && after[0] == 0.0
                        && (e_wall * before[0]).powi(2) / (2.0 * l.gravity) <= 2.0 * tolerance;
                    if !rests {
                        near(
                            after[0],
                            -e_wall * before[0],
                            4.0 * EPS * before[0].abs(),
                            &format!("t = {t}: {who} rebound"),
                        )?;
                    }
                    resting[i] = rests;
                    v[i] = after[0];
                }
            }
        }
    }
    let (xe, ve) = (nums(&out["x"]), nums(&out["v"]));
    let t_end = num(&out["time"]);
    l.in_order(&xe, 1e-9 * (len + speed * t_end.max(1.0)), t_end)?;
    let (e0, e1) = (num(&out["energy"]["start"]), num(&out["energy"]["end"]));
    if e <= 1.0 && e_wall <= 1.0 {
        at_most(
            e1,
            e0,
            1e-12 * e0.abs().max(1e-300),
            "track energy never created",
        )?;
    }
    if e == 1.0 && e_wall == 1.0 && l.gravity == 0.0 {
        near(e1, e0, 1e-12 * e0, "elastic track energy kept")?;
    }
    if l.left.is_none() && l.right.is_none() && l.gravity == 0.0 {
        let (p0, scale) = l.momentum(&l.v);
        let (p1, _) = l.momentum(&ve);
        near(p1, p0, 1e-12 * scale, "track momentum without walls")?;
    }
    Ok(())
}

/// A contact run (`collide contact --format json`, or the library's run serialised): the final
/// state with the centres in order and inside the walls; every contact shallower than where the
/// centres meet, of non-negative duration (its speed may be negative: a contact whose bodies
/// still overlap can begin to push as they separate, pressed by another), with a restitution,
/// when it has one, never below 0 (a
/// contact ends when its force reaches 0, where the overlap no longer grows) and, when no other
/// contact overlaps it in time, at most 1 (a law that only pushes returns no more speed than it
/// met; several at once can pass energy from one pair to another); energy never created (to
/// `tol`, the run's tolerance), the dissipation the energy's fall; momentum kept without walls
/// (to `tol` of the momenta). A restitution's slack is `tol` of the fastest speed over the
/// contact's own.
pub fn contact(l: &Layout, out: &Value, tol: f64) -> Result<(), String> {
    all_real(out)?;
    let (x, v) = (nums(&out["x"]), nums(&out["v"]));
    let t = num(&out["time"]);
    for i in 1..x.len() {
        at_most(
            x[i - 1],
            x[i],
            0.0,
            &format!("t = {t}: centres {i} and {} in order", i + 1),
        )?;
    }
    if let Some(left) = l.left {
        at_most(left, x[0], 0.0, "centre of body 1 inside the left wall")?;
    }
    if let Some(right) = l.right {
        at_most(
            x[x.len() - 1],
            right,
            0.0,
            "last centre inside the right wall",
        )?;
    }
    let contacts = out["contacts"].as_array().unwrap();
    let span = |c: &Value| {
        let start = num(&c["start"]);
        (start, start + c.get("duration").map_or(f64::INFINITY, num))
    };
    let fastest = l.speed().max(1e-300);
    for (i, c) in contacts.iter().enumerate() {
        let between = &c["between"];
        let size = |w: &Value| w.as_u64().map_or(0.0, |i| l.sizes[i as usize - 1]);
        let reach = (size(&between[0]) + size(&between[1])) / 2.0;
        let what = |k: &str| format!("contact {between} at {}: {k}", c["start"]);
        if num(&c["max_overlap"]) >= reach {
            return Err(what(&format!(
                "max_overlap {} >= {reach}: went through",
                c["max_overlap"]
            )));
        }
        if let Some(d) = c.get("duration") {
            at_most(0.0, num(d), 0.0, &what("duration >= 0"))?;
        }
        if let Some(e) = c.get("restitution") {
            let e = num(e);
            let slack = 10.0 * tol * fastest / num(&c["speed"]);
            at_most(-slack, e, 0.0, &what("restitution >= 0"))?;
            let (a, b) = span(c);
            let alone = contacts.iter().enumerate().all(|(j, o)| {
                let (p, q) = span(o);
                j == i || q <= a || b <= p
            });
            if alone {
                at_most(e, 1.0, slack, &what("restitution <= 1 (alone)"))?;
            }
        }
    }
    let en = &out["energy"];
    let (start, end, lost) = (num(&en["start"]), num(&en["end"]), num(&en["dissipated"]));
    at_most(0.0, lost, 0.0, "dissipated >= 0")?;
    at_most(end, start, tol * start, "contact energy never created")?;
    near(start - end, lost, tol * start, "dissipated = start - end")?;
    if l.left.is_none() && l.right.is_none() {
        let (p0, scale) = l.momentum(&l.v);
        let (p1, _) = l.momentum(&v);
        near(
            p1,
            p0,
            tol * scale.max(1e-300),
            "contact momentum without walls",
        )?;
    }
    Ok(())
}

/// Runs `collide args` expecting success and JSON on stdout.
pub fn json(args: &[&str]) -> Value {
    serde_json::from_str(&stdout(args)).unwrap_or_else(|e| panic!("{args:?}: {e}"))
}

/// `collide CMD` (track or contact) on a layout with `extra` flags, as JSON.
pub fn layout_json(cmd: &str, l: &Layout, extra: &[&str]) -> Value {
    let mut args: Vec<String> = vec![cmd.into()];
    args.extend(l.args());
    args.extend(extra.iter().map(|s| s.to_string()));
    args.extend(["--format".into(), "json".into()]);
    json(&args.iter().map(String::as_str).collect::<Vec<_>>())
}
