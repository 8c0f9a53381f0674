//! What `solve` reports: the sections a user asked for, each computed only when asked for, as one
//! serializable structure that the text and JSON formats render.

pub mod json;
pub mod text;

use std::collections::BTreeSet;

use nalgebra::Vector2;
use serde::{Deserialize, Serialize};

use crate::case::Case;
use crate::collision::Collision;
use crate::ellipse::Ellipse;

/// A section of the report (`--show`, `show = [...]` in a scene).
#[derive(
    Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Deserialize, clap::ValueEnum,
)]
#[serde(rename_all = "kebab-case")]
pub enum Section {
    /// IN, COM and FIN vectors and V_COM
    Vectors,
    /// P = M.V at IN and FIN, P_total and the momentum line
    Momentum,
    /// The quadratic forms V.M.V
    Forms,
    /// Kinetic energies, crunch energy, energy lost
    Energy,
    /// Radii (and axes) of the IN, FIN and COM energy ellipses
    Ellipses,
    /// Plain dot product V_FIN.V_IN and outer product V_IN (x) V_FIN
    Products,
    /// Every section
    All,
}

impl Section {
    pub const EVERY: [Section; 6] = [
        Section::Vectors,
        Section::Momentum,
        Section::Forms,
        Section::Energy,
        Section::Ellipses,
        Section::Products,
    ];
    /// The design card's default: IN/COM/FIN vectors, quadratic forms and the crunch energy.
    pub const DEFAULT: [Section; 3] = [Section::Vectors, Section::Forms, Section::Energy];

    /// The JSON key this section's values live under (`vectors` are at the top level).
    pub fn json_keys(self) -> &'static [&'static str] {
        match self {
            Section::Vectors => &["in", "com", "fin", "v_com"],
            Section::Momentum => &["momentum"],
            Section::Forms => &["forms"],
            Section::Energy => &["energy"],
            Section::Ellipses => &["ellipses"],
            Section::Products => &["products"],
            Section::All => &[],
        }
    }

    /// The section a top-level JSON key belongs to (`None` for `inertia` and `restitution`, which
    /// are always present).
    pub fn of_json_key(key: &str) -> Option<Section> {
        Section::EVERY
            .into_iter()
            .find(|s| s.json_keys().contains(&key))
    }
}

/// A set of sections, with `all` expanded.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Sections(BTreeSet<Section>);

impl Sections {
    pub fn new(list: impl IntoIterator<Item = Section>) -> Sections {
        let mut set = BTreeSet::new();
        for s in list {
            if s == Section::All {
                set.extend(Section::EVERY);
            } else {
                set.insert(s);
            }
        }
        Sections(set)
    }
    pub fn contains(&self, s: Section) -> bool {
        self.0.contains(&s)
    }
    pub fn insert(&mut self, s: Section) {
        self.0.extend(Sections::new([s]).0);
    }
}

/// The solved collision, with the requested sections filled in. Field names are the JSON schema.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Report {
    pub restitution: f64,
    pub inertia: [[f64; 2]; 2],
    #[serde(flatten, default, skip_serializing_if = "Option::is_none")]
    pub vectors: Option<Vectors>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub momentum: Option<Momentum>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub forms: Option<Forms>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub energy: Option<Energy>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ellipses: Option<Ellipses>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub products: Option<Products>,
}

#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Vectors {
    #[serde(rename = "in")]
    pub v_in: [f64; 2],
    pub com: [f64; 2],
    pub fin: [f64; 2],
    pub v_com: f64,
}

#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Momentum {
    #[serde(rename = "in")]
    pub p_in: [f64; 2],
    pub fin: [f64; 2],
    pub total: f64,
}

/// The quadratic forms `X.M.Y` of Sec. 2.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Forms {
    pub com_m_in: f64,
    pub fin_m_in: f64,
    pub in_m_in: f64,
    pub fin_m_fin: f64,
    pub com_m_com: f64,
}

#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Energy {
    #[serde(rename = "in")]
    pub ke_in: f64,
    pub fin: f64,
    pub com: f64,
    pub crunch: f64,
    pub lost: f64,
}

#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Ellipses {
    #[serde(rename = "in")]
    pub e_in: Ellipse,
    pub fin: Ellipse,
    pub com: Ellipse,
}

#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Products {
    pub dot_fin_in: f64,
    pub outer_in_fin: [[f64; 2]; 2],
}

fn arr(v: Vector2<f64>) -> [f64; 2] {
    [v.x, v.y]
}

/// Why a report cannot be given in binary64.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error(
    "{quantity} is not representable in binary64 (its magnitude is beyond 1.8e308): \
     rescale the units (e.g. use tons instead of kilograms), or ask only for other sections with --show"
)]
pub struct Unrepresentable {
    pub quantity: String,
}

impl Report {
    /// Solves `case` and computes the requested sections, and nothing else.
    pub fn build(case: &Case, sections: &Sections) -> Result<Report, Unrepresentable> {
        let c: &Collision = &case.collision;
        let m = c.inertia.matrix();
        let need_fin = [
            Section::Vectors,
            Section::Momentum,
            Section::Forms,
            Section::Products,
        ]
        .iter()
        .any(|&s| sections.contains(s));
        let fin = need_fin.then(|| c.v_fin());
        let fin = || fin.expect("FIN is computed for every section that uses it");
        let v_com = c.v_com();
        let energy = sections.contains(Section::Energy) || sections.contains(Section::Ellipses);
        let energy = energy.then(|| Energy {
            ke_in: c.ke_in(),
            fin: c.ke_fin(),
            com: c.ke_com(),
            crunch: c.crunch(),
            lost: c.energy_lost(),
        });
        let report = Report {
            restitution: c.restitution.value(),
            inertia: [[m[(0, 0)], m[(0, 1)]], [m[(1, 0)], m[(1, 1)]]],
            vectors: sections.contains(Section::Vectors).then(|| Vectors {
                v_in: arr(c.v_in),
                com: [v_com, v_com],
                fin: arr(fin()),
                v_com,
            }),
            momentum: sections.contains(Section::Momentum).then(|| Momentum {
                p_in: arr(c.inertia.momentum(&c.v_in)),
                fin: arr(c.inertia.momentum(&fin())),
                total: c.total_momentum(),
            }),
            forms: sections.contains(Section::Forms).then(|| {
                let com_com = v_com * c.total_momentum();
                Forms {
                    com_m_in: com_com,
                    fin_m_in: c.inertia.form(&fin(), &c.v_in),
                    in_m_in: c.inertia.form(&c.v_in, &c.v_in),
                    fin_m_fin: c.inertia.form(&fin(), &fin()),
                    com_m_com: com_com,
                }
            }),
            ellipses: sections.contains(Section::Ellipses).then(|| {
                let e = energy
                    .as_ref()
                    .expect("energies are computed for the ellipses");
                let axes = (!c.inertia.is_diagonal()).then(|| c.inertia.principal_axes());
                let ellipse = |ke| Ellipse::new(&c.inertia, ke, axes.as_ref());
                Ellipses {
                    e_in: ellipse(e.ke_in),
                    fin: ellipse(e.fin),
                    com: ellipse(e.com),
                }
            }),
            products: sections.contains(Section::Products).then(|| {
                let (i, f) = (c.v_in, fin());
                Products {
                    dot_fin_in: crate::compensated::dot2(&[f.x, f.y], &[i.x, i.y]),
                    outer_in_fin: [[i.x * f.x, i.x * f.y], [i.y * f.x, i.y * f.y]],
                }
            }),
            energy: energy.filter(|_| sections.contains(Section::Energy)),
        };
        report.check_representable()?;
        Ok(report)
    }

    /// Every number in the report must be finite: an overflow is reported by name, never printed.
    fn check_representable(&self) -> Result<(), Unrepresentable> {
        let value = serde_json::to_value(self).expect("a report serializes");
        // serde_json turns non-finite floats into null.
        fn find_null(v: &serde_json::Value, path: &str) -> Option<String> {
            match v {
                serde_json::Value::Null => Some(path.to_string()),
                serde_json::Value::Array(a) => a
                    .iter()
                    .enumerate()
                    .find_map(|(i, x)| find_null(x, &format!("{path}[{i}]"))),
                serde_json::Value::Object(o) => o.iter().find_map(|(k, x)| {
                    let p = if path.is_empty() {
                        k.clone()
                    } else {
                        format!("{path}.{k}")
                    };
                    find_null(x, &p)
                }),
                _ => None,
            }
        }
        match find_null(&value, "") {
            Some(quantity) => Err(Unrepresentable { quantity }),
            None => Ok(()),
        }
    }
}
