//! The router's tool and how it clears a pocket (issue 43 §1): one end
//! mill per job, its speeds and the pocketing choices. The depth and the
//! deepest pass are the job's [`super::Passes`] (n = ceil(H/d_max) passes
//! of H/n, paper 004 §2.6), the cutting feed the job's [`super::Process::feed`];
//! a profile's tool width is the kerf ([`crate::Settings::kerf`]), so
//! none of them is held twice.

/// How a pocket is cleared (paper 004 §2.7, §5.1 item 5).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PocketStrategy {
    /// Parallel passes at an angle, alternating direction, the tool kept
    /// down between passes where the link stays inside the pocket.
    ZigZag,
    /// Repeated inward offsets of the walls, in the order [`OffsetFrom`] says.
    Offset,
}

/// Which way contour-parallel clearing goes through its loops (paper 004
/// §5.1 item 5: "from the centre outwards or the reverse").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OffsetFrom {
    /// Innermost loop first: each loop widens what the one before cleared,
    /// the walls last.
    Centre,
    /// The loop along the walls first, then inwards: the walls are cut
    /// while the middle still holds the stock.
    Walls,
}

impl OffsetFrom {
    /// Both orders.
    pub const ALL: [OffsetFrom; 2] = [OffsetFrom::Centre, OffsetFrom::Walls];
    /// The name used by the CLI, the page and the report.
    pub fn name(self) -> &'static str {
        match self {
            OffsetFrom::Centre => "centre",
            OffsetFrom::Walls => "walls",
        }
    }
    /// The order called `name`.
    pub fn from_name(name: &str) -> Option<OffsetFrom> {
        OffsetFrom::ALL.into_iter().find(|s| s.name() == name)
    }
}

impl PocketStrategy {
    /// Every strategy.
    pub const ALL: [PocketStrategy; 2] = [PocketStrategy::ZigZag, PocketStrategy::Offset];
    /// The name used by the CLI, the page and the report.
    pub fn name(self) -> &'static str {
        match self {
            PocketStrategy::ZigZag => "zigzag",
            PocketStrategy::Offset => "offset",
        }
    }
    /// The strategy called `name`.
    pub fn from_name(name: &str) -> Option<PocketStrategy> {
        PocketStrategy::ALL.into_iter().find(|s| s.name() == name)
    }
}

/// How the tool goes down into a pocket's material at each depth.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Entry {
    /// Straight down at the plunge feed (a centre-cutting end mill).
    Plunge,
    /// Down along the first pass at [`Tool::ramp_angle_deg`].
    Ramp,
    /// Down a helix of [`Tool::helix_diameter`].
    Helix,
}

impl Entry {
    /// Every entry.
    pub const ALL: [Entry; 3] = [Entry::Plunge, Entry::Ramp, Entry::Helix];
    /// The name used by the CLI, the page and the report.
    pub fn name(self) -> &'static str {
        match self {
            Entry::Plunge => "plunge",
            Entry::Ramp => "ramp",
            Entry::Helix => "helix",
        }
    }
    /// The entry called `name`.
    pub fn from_name(name: &str) -> Option<Entry> {
        Entry::ALL.into_iter().find(|s| s.name() == name)
    }
}

/// One end mill and how it clears pockets, drills and engraves. Lengths
/// mm, feeds mm/min.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tool {
    /// Cutting diameter; 0 = no tool (a cutting job: torch, laser, knife).
    pub diameter: f64,
    /// Distance between neighbouring passes, % of the diameter (0 < · ≤ 100).
    pub stepover_pct: f64,
    /// Feed of moves that go down into material (plunges, ramps, helices, drilling).
    pub plunge_feed: f64,
    /// Spindle speed, rev/min (the post's `{spindle_rpm}`).
    pub spindle_rpm: f64,
    /// Climb milling on the walls (true, the default with a clockwise
    /// spindle: walls on the tool's right) or conventional.
    pub climb: bool,
    /// Pocket clearing.
    pub pocket: PocketStrategy,
    /// Contour-parallel clearing: from the centre outwards or from the walls in.
    pub offset_from: OffsetFrom,
    /// Direction of the zig-zag passes, degrees from X.
    pub angle_deg: f64,
    /// Entry into each depth of a pocket.
    pub entry: Entry,
    /// Ramp angle, degrees from the horizontal.
    pub ramp_angle_deg: f64,
    /// Helix diameter (the helix's centre path).
    pub helix_diameter: f64,
    /// Stock left on the walls by the roughing, taken by the finishing pass.
    pub allowance: f64,
    /// Drilling: depth of each peck before the tool clears the chips (0 =
    /// the deepest pass).
    pub peck: f64,
    /// Drilling: circles up to this diameter are drilled at their centre.
    pub drill_max: f64,
    /// A V-bit's included angle, degrees (0: a flat end mill). An
    /// engraving's width is then 2·depth·tan(angle/2).
    pub v_angle_deg: f64,
    /// Engraving with a V-bit: the width wanted at the stock's top, mm;
    /// the engraving's depth follows from it (0: the job's depth, and the
    /// width follows).
    pub engrave_width: f64,
    /// Engraving with a V-bit: its depth, mm, when given instead of the
    /// width (which follows); 0: from the width, else the job's depth.
    pub engrave_depth: f64,
    /// Radius of the tangent arcs a profile enters and leaves each depth
    /// pass by, on the waste side, with the arc lead kind (0: the tool's
    /// diameter).
    pub lead_radius: f64,
    /// A profile's tabs: the height of the bridge they leave at the
    /// bottom, mm (0: the tab is the stock's whole thickness, the tool
    /// lifts out of the cut over it).
    pub tab_height: f64,
    /// The tool's number in the machine's tool table (the post's
    /// `{tool_number}`: LinuxCNC's and Mach3's `T… M6` and `G43 H…`).
    pub number: u32,
}

impl Tool {
    /// No tool: a cutting job.
    pub const OFF: Tool = Tool {
        diameter: 0.0,
        stepover_pct: 40.0,
        plunge_feed: 300.0,
        spindle_rpm: 18_000.0,
        climb: true,
        pocket: PocketStrategy::ZigZag,
        offset_from: OffsetFrom::Centre,
        angle_deg: 0.0,
        entry: Entry::Plunge,
        ramp_angle_deg: 3.0,
        helix_diameter: 0.0,
        allowance: 0.0,
        peck: 0.0,
        drill_max: 0.0,
        v_angle_deg: 0.0,
        engrave_width: 0.0,
        engrave_depth: 0.0,
        lead_radius: 0.0,
        tab_height: 0.0,
        number: 1,
    };
    /// True when a tool is set.
    pub fn on(&self) -> bool {
        self.diameter > 0.0
    }
    /// Tool radius.
    pub fn radius(&self) -> f64 {
        self.diameter / 2.0
    }
    /// Distance between passes, mm.
    pub fn stepover(&self) -> f64 {
        self.diameter * self.stepover_pct / 100.0
    }
    /// A V-bit's cut width at `depth` below the top: 2·depth·tan(angle/2)
    /// (None for a flat end mill).
    pub fn v_width(&self, depth: f64) -> Option<f64> {
        (self.v_angle_deg > 0.0).then(|| 2.0 * depth * (self.v_angle_deg.to_radians() / 2.0).tan())
    }
    /// An engraving's depth: the one given a V-bit, or from the width
    /// asked of it (width / (2·tan(angle/2))), else the job's `depth`.
    pub fn engrave_depth(&self, depth: f64) -> f64 {
        if self.v_angle_deg > 0.0 && self.engrave_depth > 0.0 {
            self.engrave_depth
        } else if self.v_angle_deg > 0.0 && self.engrave_width > 0.0 {
            self.engrave_width / (2.0 * (self.v_angle_deg.to_radians() / 2.0).tan())
        } else {
            depth
        }
    }
    /// The profiles' lead arc radius: the one given, else the tool's
    /// diameter (an arc as wide as the cut turns the tool into the wall
    /// gently, and still fits beside most neighbours).
    pub fn lead_arc(&self) -> f64 {
        if self.lead_radius > 0.0 {
            self.lead_radius
        } else {
            self.diameter
        }
    }
    /// The Z of the top of a tab's bridge, `depth` deep: −(depth −
    /// tab height), when the tab is lower than the stock (a tab height
    /// above 0 and below `depth`); None: the tool lifts out over tabs.
    pub fn tab_top(&self, depth: f64) -> Option<f64> {
        (self.on() && self.tab_height > 0.0 && self.tab_height < depth)
            .then(|| -(depth - self.tab_height))
    }
    /// The helix diameter used: the one given, else the tool's radius
    /// (a helix twice as wide as the tool would leave a core standing).
    pub fn helix(&self) -> f64 {
        if self.helix_diameter > 0.0 {
            self.helix_diameter
        } else {
            self.radius()
        }
    }
}
