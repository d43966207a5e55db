//! Job settings as the user gives them, validated once; later stages trust them.

use crate::dxf::{ReadOptions, Units};
use crate::gcode::Post;
use crate::geom::Tolerance;
use crate::kerf::Join;
use crate::origin::ProgramOrigin;
use crate::par::Threads;
use crate::plan::PlanOptions;
use crate::process::{LayerOps, Process};
use crate::text;
use crate::warning::{dec, Lang};

mod build;
mod process;
mod read;
mod spec;
mod tools;
pub use spec::{Choice, LayerDepthSpec, LoopKeySpec, SideChoice, Spec, ToolSpec};

/// The cut-chart entry a job was set from (shown where the user looks:
/// an example entry is not a machine's chart).
#[derive(Clone, Debug, PartialEq)]
pub struct MaterialUsed {
    /// The entry's name.
    pub name: String,
    /// A starter example, to check against the machine's own chart.
    pub example: bool,
}

/// Validated settings of one job.
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    /// How the DXF is read (curve chord, units override, layers).
    pub(crate) read: ReadOptions,
    /// The one geometric tolerance (chaining, degenerate checks), mm.
    pub(crate) tolerance: Tolerance,
    /// Open ends up to this far apart are joined (mm).
    pub(crate) gap: f64,
    /// Convex corners of the kerf path (its width is the process's).
    pub(crate) join: Join,
    /// Ordering and directions.
    pub(crate) plan: PlanOptions,
    /// Decimal places of the program's numbers.
    pub(crate) decimals: u32,
    /// The program's dialect; None writes plain LinuxCNC ([`crate::gcode::emit`]).
    pub(crate) post: Option<Post>,
    /// Language of the report's messages (the program never changes with it).
    pub(crate) lang: Lang,
    /// Which drawing point becomes the program's zero.
    pub(crate) origin: ProgramOrigin,
    /// What each layer is for (cut, mark, spot, ignore).
    pub(crate) layer_ops: LayerOps,
    /// How the job cuts: the one place kerf, feed, delay, rapid, heights
    /// and the small-hole rule live ([`Settings::kerf`] and
    /// [`Settings::gcode`] are views of it).
    pub(crate) process: Process,
    /// Sweep the plan's kerf over the parts and report what it takes
    /// ([`crate::plan::verify`]).
    pub(crate) verify: bool,
    /// Loops that cross themselves repaired into their region's outline
    /// (issue 45 §2); false: refused by the kerf stage, as drawn.
    pub(crate) repair: bool,
    /// The cut-chart entry the job's process came from, if any.
    pub(crate) material: Option<MaterialUsed>,
    /// Threads the stages may use (each stage's options carry the count).
    pub(crate) threads: Threads,
    /// The router's other tools and the layers they mill (issue 43 §1).
    pub(crate) tools: crate::process::Tools,
    /// Milling layers at their own depth and direction (issue 43 §1).
    pub(crate) layer_depths: crate::process::LayerDepths,
}

pub use crate::settings_error::SettingsError;

/// Default gap closed between open ends, in point tolerances (0.05 mm by
/// default: CAD end points that miss by more were not meant to meet).
const GAP_PER_TOLERANCE: f64 = 50.0;

/// Chord tolerance of curves (splines, ellipses) in point tolerances.
const CHORD_PER_TOLERANCE: f64 = 10.0;

pub use crate::process::DEFAULT_RAPID;

fn check(field: &'static str, v: f64, min: f64, max: f64) -> Result<f64, SettingsError> {
    if v.is_finite() && v >= min && v <= max {
        Ok(v)
    } else {
        Err(SettingsError {
            field,
            reason: text!("{v} is not between {min} and {max}"; "{} não está entre {} e {}", dec(v), dec(min), dec(max)),
        })
    }
}

impl Settings {
    /// Settings from the three everyday values (mm, mm, mm/min).
    pub fn new(kerf: f64, tolerance: f64, feed: f64) -> Result<Settings, SettingsError> {
        let kerf = check("kerf", kerf, 0.0, 100.0)?;
        let tolerance = check("tolerance", tolerance, 1e-6, 1.0)?;
        let feed = check("feed", feed, 1e-3, 1e6)?;
        Ok(Settings {
            // Curves become lines within ten point tolerances (0.01 mm by default):
            // far below a cutting machine's accuracy, far above float noise.
            read: ReadOptions {
                chord: CHORD_PER_TOLERANCE * tolerance,
                ..ReadOptions::DEFAULT
            },
            tolerance: Tolerance(tolerance),
            gap: GAP_PER_TOLERANCE * tolerance,
            join: Join::Round,
            plan: PlanOptions::DEFAULT,
            decimals: 3,
            post: None,
            lang: Lang::En,
            origin: ProgramOrigin::Auto,
            layer_ops: LayerOps::new(),
            process: Process {
                kerf,
                feed,
                ..Process::DEFAULT
            },
            verify: false,
            repair: true,
            material: None,
            threads: Threads::ONE,
            tools: crate::process::Tools::default(),
            layer_depths: crate::process::LayerDepths::default(),
        }
        .with_threads(Threads::available()))
    }
    /// The same settings running the stages on `threads` (natively; the
    /// page has one). The program, plan and report are the same with any.
    pub fn with_threads(mut self, threads: Threads) -> Settings {
        self.threads = threads;
        self.read.threads = threads;
        self.plan.threads = threads;
        self
    }
    /// The same settings reading the file in `units` whatever it says.
    pub fn with_units(mut self, units: Units) -> Settings {
        self.read.units = Some(units);
        self
    }
    /// The same settings with the program's zero at `origin` (a picked
    /// point within ±10 km).
    pub fn with_origin(mut self, origin: ProgramOrigin) -> Result<Settings, SettingsError> {
        if let ProgramOrigin::Point(p) = origin {
            check("program_origin_x", p.x, -1e7, 1e7)?;
            check("program_origin_y", p.y, -1e7, 1e7)?;
        }
        self.origin = origin;
        Ok(self)
    }
    /// The same settings cutting only the named layers.
    pub fn with_layers(mut self, layers: Vec<String>) -> Settings {
        self.read.layers = Some(layers);
        self
    }
    /// The same settings joining open ends up to `mm` apart (0..=10).
    pub fn with_gap(mut self, mm: f64) -> Result<Settings, SettingsError> {
        self.gap = check("gap", mm, 0.0, 10.0)?;
        Ok(self)
    }
    /// The same settings with mitred convex corners.
    pub fn with_join(mut self, join: Join) -> Settings {
        self.join = join;
        self
    }
    /// The same settings with another number of decimals (1..=6).
    pub fn with_decimals(mut self, decimals: u32) -> Result<Settings, SettingsError> {
        if !(1..=6).contains(&decimals) {
            return Err(SettingsError {
                field: "decimals",
                reason: text!("{decimals} is not between 1 and 6"; "{decimals} não está entre 1 e 6"),
            });
        }
        self.decimals = decimals;
        Ok(self)
    }
    /// The same settings with another plan (order, leads, directions…),
    /// its lengths checked.
    pub fn with_plan(mut self, plan: PlanOptions) -> Result<Settings, SettingsError> {
        check("lead_outer", plan.leads.outer_length, 0.0, 1000.0)?;
        check("lead_hole", plan.leads.hole_length, 0.0, 1000.0)?;
        check("overcut", plan.leads.overcut, 0.0, 1000.0)?;
        check("max_link", plan.max_link, 0.0, 1e5)?;
        check("origin_x", plan.origin.x, -1e7, 1e7)?;
        check("origin_y", plan.origin.y, -1e7, 1e7)?;
        check("tabs", plan.tabs.count as f64, 0.0, 100.0)?;
        check("tab_width", plan.tabs.width, 0.0, 1000.0)?;
        let tabs = plan.tabs.count > 0 || !plan.tabs_at.is_empty();
        if tabs && plan.tabs.width <= 0.0 {
            return Err(SettingsError {
                field: "tab_width",
                reason: text!("tabs need a width above 0 mm"; "pontes precisam de largura acima de 0 mm"),
            });
        }
        if tabs && plan.controller_comp {
            // A restart after a tab probes and pierces again, which
            // LinuxCNC refuses with cutter compensation on.
            return Err(SettingsError {
                field: "tabs",
                reason: text!("tabs cannot be left with the controller's compensation (the torch restarts after each tab with the compensation on)";
                              "pontes não podem ser deixadas com a compensação do controlador (a tocha reinicia depois de cada ponte com a compensação ligada)"),
            });
        }
        if plan.controller_comp && plan.order != crate::plan::Order::Contour {
            return Err(SettingsError {
                field: "controller_comp",
                reason: text!("the controller's compensation is written for the contour order only (order '{}')", plan.order.name();
                              "a compensação do controlador é escrita só na ordem contorno a contorno (ordem '{}')", plan.order.name()),
            });
        }
        self.plan = PlanOptions {
            threads: self.threads,
            ..plan
        };
        Ok(self)
    }
    /// The same settings writing the program with `post` (checked: an
    /// invalid post names its field).
    pub fn with_post(mut self, post: Post) -> Result<Settings, SettingsError> {
        post.validate().map_err(|e| SettingsError {
            field: "post",
            reason: e.text(),
        })?;
        self.post = Some(post);
        Ok(self)
    }
    /// The same settings with the report's messages in `lang`.
    pub fn with_lang(mut self, lang: Lang) -> Settings {
        self.lang = lang;
        self
    }
    /// The same settings with another rapid speed, mm/min.
    pub fn with_rapid(mut self, mm_per_min: f64) -> Result<Settings, SettingsError> {
        self.process.rapid = check("rapid", mm_per_min, 1.0, 1e6)?;
        Ok(self)
    }
    /// The same settings with the plan changed by `edit`, checked as
    /// [`Settings::with_plan`] checks a new plan.
    pub fn map_plan(self, edit: impl FnOnce(&mut PlanOptions)) -> Result<Settings, SettingsError> {
        let mut plan = self.plan.clone();
        edit(&mut plan);
        self.with_plan(plan)
    }
    /// The same settings in another order (every other plan option kept).
    pub fn with_order(self, order: crate::plan::Order) -> Result<Settings, SettingsError> {
        let plan = PlanOptions {
            order,
            ..self.plan.clone()
        };
        self.with_plan(plan)
    }
    /// The same settings with a pierce delay in seconds (0..=60).
    pub fn with_pierce_delay(mut self, seconds: f64) -> Result<Settings, SettingsError> {
        self.process.pierce_delay = check("pierce_delay", seconds, 0.0, 60.0)?;
        Ok(self)
    }
    /// The same settings repairing loops that cross themselves, or not.
    pub fn with_repair(mut self, on: bool) -> Settings {
        self.repair = on;
        self
    }
    /// The same settings checking the plan's cut against the parts.
    pub fn with_verify(mut self, on: bool) -> Settings {
        self.verify = on;
        self
    }
    /// The same settings cut by several torches at once (paper 001 §6.5):
    /// the program names them, and parks and stops for the operator when
    /// a park position is given. Count 1 is one torch.
    pub fn with_torches(
        mut self,
        count: usize,
        spacing: f64,
        park: Option<crate::geom::Point>,
    ) -> Result<Settings, SettingsError> {
        self.process.torches = crate::process::Torches::new(count, spacing, park)?;
        Ok(self)
    }
    /// The same settings with these layer operations.
    pub fn with_layer_ops(mut self, ops: LayerOps) -> Settings {
        self.layer_ops = ops;
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::process::SmallHole;

    #[test]
    fn out_of_range_settings_name_the_field() {
        assert_eq!(Settings::new(-1.0, 0.001, 100.0).unwrap_err().field, "kerf");
        assert_eq!(
            Settings::new(1.0, f64::NAN, 100.0).unwrap_err().field,
            "tolerance"
        );
        assert_eq!(Settings::new(1.0, 0.001, 0.0).unwrap_err().field, "feed");
        assert!(Settings::new(0.0, 0.001, 100.0).is_ok());
    }

    #[test]
    fn a_material_sets_the_job_from_its_entry() {
        let lib = crate::materials::Library::starter();
        let mut e = lib.find("Mild steel 6 mm 45 A (example)").unwrap().clone();
        e.number = Some(7);
        let s = Settings::new(1.0, 0.001, 100.0)
            .unwrap()
            .with_pierce_delay(9.0)
            .unwrap()
            .with_material(&e)
            .unwrap();
        assert_eq!((s.kerf().width, s.process.kerf), (1.6, 1.6));
        assert_eq!((s.job().process, s.process.feed), (s.process, 1500.0));
        assert_eq!(s.process.pierce_delay, 0.6);
        assert_eq!((s.process.pierce_height, s.process.cut_height), (3.8, 1.5));
        assert_eq!(s.process.material, 7);
        // 1.5 × 6 mm at the entry's 60 %, in the plan too.
        assert_eq!(
            (
                s.process.small_hole.diameter,
                s.process.small_hole.speed_pct
            ),
            (9.0, 60.0)
        );
        // A diameter set by the job stays.
        let s = Settings::new(1.0, 0.001, 100.0)
            .unwrap()
            .with_small_hole(SmallHole {
                diameter: 4.0,
                ..SmallHole::OFF
            })
            .unwrap()
            .with_material(&e)
            .unwrap();
        assert_eq!(s.process.small_hole.diameter, 4.0);
        e.kerf = 200.0;
        let err = Settings::new(1.0, 0.001, 100.0).unwrap().with_material(&e);
        assert_eq!(err.unwrap_err().field, "kerf");
    }
}
