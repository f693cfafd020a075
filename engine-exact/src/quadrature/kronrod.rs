//! The Gauss–Kronrod pairs [`Adaptive`](super::Adaptive) integrates with (QUADPACK's tables,
//! 21 and 41 nodes), the trust each pair's error estimate gets, and the tables of its nodes'
//! offsets per halving depth.

use super::DEPTH_LIMIT;
use std::f64::consts::FRAC_PI_2;
use std::sync::OnceLock;

/// A Gauss–Kronrod pair on [−1, 1]: the `2n + 1`-node Kronrod rule and the `n`-node Gauss
/// rule whose nodes are every other one of it, so one set of values gives both and their
/// difference estimates the Gauss rule's error (QUADPACK's tables, Piessens et al. 1983).
pub(super) struct KronrodPair {
    /// The non-negative nodes, decreasing, the last one 0.
    pub(super) nodes: &'static [f64],
    /// The Kronrod weight of each (the negative nodes mirror them).
    pub(super) kronrod: &'static [f64],
    /// The Gauss weights of the nodes at odd positions (1, 3, …) of `nodes`.
    pub(super) gauss: &'static [f64],
}

/// The 10-node Gauss rule (exact to degree 19) in the 21-node Kronrod rule (to degree 31).
#[allow(
    clippy::excessive_precision,
    reason = "the tables as published; f64 rounds them"
)]
pub(super) const GAUSS_KRONROD_10_21: KronrodPair = KronrodPair {
    nodes: &[
        0.995657163025808080735527280689003,
        0.973906528517171720077964012084452,
        0.930157491355708226001207180059508,
        0.865063366688984510732096688423493,
        0.780817726586416897063717578345042,
        0.679409568299024406234327365114874,
        0.562757134668604683339000099272694,
        0.433395394129247190799265943165784,
        0.294392862701460198131126603103866,
        0.148874338981631210884826001129720,
        0.0,
    ],
    kronrod: &[
        0.011694638867371874278064396062192,
        0.032558162307964727478818972459390,
        0.054755896574351996031381300244580,
        0.075039674810919952767043140916190,
        0.093125454583697605535065465083366,
        0.109387158802297641899210590325805,
        0.123491976262065851077958109831074,
        0.134709217311473325928054001771707,
        0.142775938577060080797094273138717,
        0.147739104901338491374841515972068,
        0.149445554002916905664936468389821,
    ],
    gauss: &[
        0.066671344308688137593568809893332,
        0.149451349150580593145776339657697,
        0.219086362515982043995534934228163,
        0.269266719309996355091226921569469,
        0.295524224714752870173892994651338,
    ],
};

/// The 20-node Gauss rule (exact to degree 39) in the 41-node Kronrod rule (to degree 61).
#[allow(
    clippy::excessive_precision,
    reason = "the tables as published; f64 rounds them"
)]
pub(super) const GAUSS_KRONROD_20_41: KronrodPair = KronrodPair {
    nodes: &[
        0.998859031588277663838315576545863,
        0.993128599185094924786122388471320,
        0.981507877450250259193342994720217,
        0.963971927277913791267666131197277,
        0.940822633831754753519982722212443,
        0.912234428251325905867752441203298,
        0.878276811252281976077442995113078,
        0.839116971822218823394529061701521,
        0.795041428837551198350638833272788,
        0.746331906460150792614305070355642,
        0.693237656334751384805490711845932,
        0.636053680726515025452836696226286,
        0.575140446819710315342946036586425,
        0.510867001950827098004364050955251,
        0.443593175238725103199992213492640,
        0.373706088715419560672548177024927,
        0.301627868114913004320555356858592,
        0.227785851141645078080496195368575,
        0.152605465240922675505220241022678,
        0.076526521133497333754640409398838,
        0.0,
    ],
    kronrod: &[
        0.003073583718520531501218293246031,
        0.008600269855642942198661787950102,
        0.014626169256971252983787960308868,
        0.020388373461266523598010231432755,
        0.025882133604951158834505067096153,
        0.031287306777032798958543119323801,
        0.036600169758200798030557240707211,
        0.041668873327973686263788305936895,
        0.046434821867497674720231880926108,
        0.050944573923728691932707670050345,
        0.055195105348285994744832372419777,
        0.059111400880639572374967220648594,
        0.062653237554781168025870122174255,
        0.065834597133618422111563556969398,
        0.068648672928521619345623411885368,
        0.071054423553444068305790361723210,
        0.073030690332786667495189417658913,
        0.074582875400499188986581418362488,
        0.075704497684556674659542775376617,
        0.076377867672080736705502835038061,
        0.076600711917999656445049901530102,
    ],
    gauss: &[
        0.017614007139152118311861962351853,
        0.040601429800386941331039952274932,
        0.062672048334109063569506535187042,
        0.083276741576704748724758143222046,
        0.101930119817240435036750135480350,
        0.118194531961518417312377377711382,
        0.131688638449176626898494499748163,
        0.142096109318382051329298325067165,
        0.149172986472603746787828737001969,
        0.152753387130725850698084331955098,
    ],
};

/// The Gauss–Kronrod pair an [`Adaptive`](super::Adaptive) rule integrates each interval with.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Pair {
    /// 10 Gauss nodes in 21 Kronrod nodes: the cheaper look at an interval, for integrands
    /// whose pieces may hide a kink (each halving then costs 42 evaluations, not 82).
    Kronrod21,
    /// 20 Gauss nodes in 41 Kronrod nodes: for analytic pieces whose nearest singularity
    /// (off the real line) is too close for the 21-node rule to meet 1e-13 in one look, and
    /// for which 41 evaluations replace a few levels of halving.
    Kronrod41,
}

impl Pair {
    pub(super) fn table(self) -> &'static KronrodPair {
        match self {
            Self::Kronrod21 => &GAUSS_KRONROD_10_21,
            Self::Kronrod41 => &GAUSS_KRONROD_20_41,
        }
    }

    /// The largest relative difference of an interval's two values at which the error
    /// estimate is trusted: [`TRUSTED_DIFFERENCE`] for the 21-node pair, whose pieces may
    /// hide a kink; for the 41-node pair, used on pieces cut at every kink (analytic, with
    /// square-root ends the sine map smooths), the difference `d` is the Gauss rule's error
    /// `≈ ρ⁻⁴⁰` for the integrand's Bernstein ellipse `ρ`, and the Kronrod rule's is then
    /// `≈ ρ⁻⁶² = d^1.55`: 1e-13 at `d` = 4e-9.
    pub(super) fn trusted(self) -> f64 {
        match self {
            Self::Kronrod21 => TRUSTED_DIFFERENCE,
            Self::Kronrod41 => 4e-9,
        }
    }
}

/// The largest number of non-negative nodes of a pair.
pub(super) const MAX_NODES: usize = 21;

/// The largest relative difference between an interval's two values
/// [`Adaptive`](super::Adaptive) accepts, whatever its tolerance: past it the Kronrod value
/// is not trusted to be the better one by the margin the error estimate assumes (a kink
/// between the nodes), so the interval is halved. The accepted value's error is then below
/// this even there.
pub(super) const TRUSTED_DIFFERENCE: f64 = 1e-10;

/// `(sin, cos)` of a pair's node offsets at one halving depth.
pub(super) type OffsetRow = [(f64, f64); MAX_NODES];

/// Per halving depth `d` of `[−π/2, π/2]`, `(sin, cos)` of each of the pair's node offsets
/// from an interval's middle, `x_k·π/2^(d+1)` (computed once per pair).
pub(super) fn node_offsets(pair: Pair) -> &'static [OffsetRow] {
    static TABLES: [OnceLock<Vec<OffsetRow>>; 2] = [OnceLock::new(), OnceLock::new()];
    let slot = match pair {
        Pair::Kronrod21 => 0,
        Pair::Kronrod41 => 1,
    };
    TABLES[slot].get_or_init(|| {
        (0..=DEPTH_LIMIT)
            .map(|d| {
                let width = FRAC_PI_2 / 2f64.powi(d as i32);
                let mut row = [(0.0, 1.0); MAX_NODES];
                for (entry, &x) in row.iter_mut().zip(pair.table().nodes) {
                    *entry = (width * x).sin_cos();
                }
                row
            })
            .collect()
    })
}

/// Calls `f(x, kronrod_weight, gauss_weight)` at the pair's nodes mapped onto `[a, b]`
/// (weights scaled to it; 0 for the nodes that are Kronrod nodes only): the tables' check.
#[cfg(test)]
pub(super) fn for_each_kronrod_node(
    pair: &KronrodPair,
    a: f64,
    b: f64,
    mut f: impl FnMut(f64, f64, f64),
) {
    let half = 0.5 * (b - a);
    let mid = 0.5 * (a + b);
    let last = pair.nodes.len() - 1;
    for (k, (&x, &w)) in pair.nodes.iter().zip(pair.kronrod).enumerate() {
        let g = if k % 2 == 1 { pair.gauss[k / 2] } else { 0.0 };
        if k == last {
            f(mid, half * w, half * g);
        } else {
            f(mid - half * x, half * w, half * g);
            f(mid + half * x, half * w, half * g);
        }
    }
}
