#include "featloc/features/LineEllipseExtractor.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "featloc/config/ConfigValues.h"
#include "featloc/features/LineFit.h"
#include "featloc/features/PointScatter.h"
#include "featloc/scan/AdaptiveBreakpointSegmenter.h"

namespace featloc
{
namespace
{
/** A line feature's PCM parameters from (rho, alpha): the foot point and
 * the normal's outer product (the projection A_i). */
void setLineParameters(ScanFeature& f)
{
	const double ca = std::cos(f.alpha), sa = std::sin(f.alpha);
	f.x = f.rho * ca;
	f.y = f.rho * sa;
	f.a2 = ca * ca;
	f.b2 = sa * sa;
	f.c = ca * sa;
}

/** The foot point's covariance from (rho, alpha)'s: f = rho n(alpha),
 * df = n drho + rho u dalpha. */
void setFootPointCovariance(ScanFeature& f)
{
	const double ca = std::cos(f.alpha), sa = std::sin(f.alpha);
	const double ux = -sa * f.rho, uy = ca * f.rho;
	f.cxx = ca * ca * f.varRho + 2 * ca * ux * f.covRhoAlpha + ux * ux * f.varAlpha;
	f.cxy = ca * sa * f.varRho + (ca * uy + sa * ux) * f.covRhoAlpha + ux * uy * f.varAlpha;
	f.cyy = sa * sa * f.varRho + 2 * sa * uy * f.covRhoAlpha + uy * uy * f.varAlpha;
}

double gap(const ScanPoint& a, const ScanPoint& b)
{
	const double dx = a.x - b.x, dy = a.y - b.y;
	return std::sqrt(dx * dx + dy * dy);	// as PointNoiseEstimator::chordDistance
}

double chordDistance(const ScanPoint& a, const ScanPoint& b, const ScanPoint& p)
{
	return PointNoiseEstimator::chordDistance(a, b, p);
}

LineFit fitRun(const ScanPoints& s, size_t first, size_t last)
{
	return LineFit::fit(&s.points[first], last - first + 1);
}
}  // namespace

void LineEllipseExtractor::Parameters::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	read(c, s, "max_point_gap", max_point_gap);
	readDegrees(c, s, "grazing_incidence_DEG", grazing_incidence);
	read(c, s, "split_distance_min", split_distance_min);
	read(c, s, "split_sigmas", split_sigmas);
	read(c, s, "trim_sigmas", trim_sigmas);
	read(c, s, "merge_sigmas", merge_sigmas);
	read(c, s, "merge_step_points", merge_step_points);
	read(c, s, "line_outlier_sigmas", line_outlier_sigmas);
	read(c, s, "collinear_fusion_chi2", collinear_fusion_chi2);
	read(c, s, "max_line_sigma", max_line_sigma);
	read(c, s, "min_points", min_points);
	read(c, s, "min_length", min_length);
	read(c, s, "ellipse_max_length", ellipse_max_length);
	read(c, s, "refine_iterations", refine_iterations);
	read(c, s, "min_point_sigma", min_point_sigma);
	read(c, s, "ellipse_shape_sigma_ratio", ellipse_shape_sigma_ratio);
	readChoice(c, s, "line_fit", line_fit, {"weighted", "tls"});
	require(max_point_gap > 0, c, s, "max_point_gap", "> 0");
	require(grazing_incidence >= 0 && grazing_incidence < M_PI / 2, c, s, "grazing_incidence_DEG",
		"in [0, 90) degrees (0: max_point_gap alone)");
	require(split_distance_min > 0, c, s, "split_distance_min", "> 0");
	require(split_sigmas >= 0, c, s, "split_sigmas", ">= 0");
	require(trim_sigmas > 0, c, s, "trim_sigmas", "> 0");
	require(merge_sigmas > 0, c, s, "merge_sigmas", "> 0");
	require(merge_step_points != 1, c, s, "merge_step_points",
		"0 (off) or at least 2 (one point beyond the threshold is a noise spike)");
	require(line_outlier_sigmas >= 0, c, s, "line_outlier_sigmas", ">= 0 (0: off)");
	require(collinear_fusion_chi2 >= 0, c, s, "collinear_fusion_chi2",
		">= 0 (a chi-square value for 2 degrees of freedom; 0: off)");
	require(max_line_sigma > 0, c, s, "max_line_sigma", "> 0");
	require(min_points >= 3, c, s, "min_points", ">= 3");
	require(min_length >= 0, c, s, "min_length", ">= 0");
	require(ellipse_max_length >= 0, c, s, "ellipse_max_length", ">= 0");
	require(min_point_sigma > 0, c, s, "min_point_sigma", "> 0");
	require(ellipse_shape_sigma_ratio >= 0, c, s, "ellipse_shape_sigma_ratio", ">= 0");
}

void LineEllipseExtractor::Parameters::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	write(c, s, "max_point_gap", max_point_gap,
		"[m] features: consecutive points farther apart start a new cluster");
	writeDegrees(c, s, "grazing_incidence_DEG", grazing_incidence,
		"[deg] features: ... unless a surface seen this grazingly spaces its points so (adaptive breakpoint detector; 0: off)");
	write(c, s, "split_distance_min", split_distance_min,
		"[m] features: split where a point is farther than max(this, split_sigmas * noise) from the chord");
	write(c, s, "split_sigmas", split_sigmas,
		"features: split threshold in units of the cluster's estimated point noise");
	write(c, s, "trim_sigmas", trim_sigmas,
		"features: drop line end points farther than this many noise sigmas");
	write(c, s, "merge_sigmas", merge_sigmas,
		"features: merge neighbouring runs whose joint RMS residual is below this many noise sigmas");
	write(c, s, "merge_step_points", merge_step_points,
		"features: ... unless this many consecutive points of the joint line lie beyond the split "
		"threshold on one side (a step, not a spike; 0: off)");
	write(c, s, "line_outlier_sigmas", line_outlier_sigmas,
		"features: drop a line's points farther than this many of their sigmas (range noise at "
		"their incidence) from it, and refit (0: off)");
	write(c, s, "collinear_fusion_chi2", collinear_fusion_chi2,
		"features: consecutive lines whose (rho, alpha) differ by less than this chi-square "
		"(2 dof) become one line fitted to their points (0: off)");
	write(c, s, "max_line_sigma", max_line_sigma,
		"[m] features: max RMS residual of a line, eq. (8)");
	write(c, s, "min_points", min_points, "features: min points of a line");
	write(c, s, "min_length", min_length, "[m] features: min length of a line");
	write(c, s, "ellipse_max_length", ellipse_max_length,
		"[m] features: lines up to this long become ellipsoidal clusters");
	write(c, s, "refine_iterations", refine_iterations,
		"features: boundary re-assignment passes (clustering refinement)");
	write(c, s, "min_point_sigma", min_point_sigma,
		"[m] features: floor of the point noise estimated from a fit");
	write(c, s, "ellipse_shape_sigma_ratio", ellipse_shape_sigma_ratio,
		"features: ellipse centroid sigma added per metre of its length");
	write(c, s, "line_fit", line_fit,
		"features: weighted (lines refitted with each point's variance under range noise) | tls (eqs. 3-8, as published)");
}

bool LineEllipseExtractor::clusterBreak(const ScanPoint& a, const ScanPoint& b) const
{
	if (gap(a, b) <= params.max_point_gap) return false;
	if (!(params.grazing_incidence > 0)) return true;
	// Eq. (3) as written: a missing return between a and b widens dphi, and
	// dphi >= lambda always breaks.
	AdaptiveBreakpointSegmenter::Parameters abd;
	abd.lambda = params.grazing_incidence;
	abd.breakAtMissingReturns = false;
	return AdaptiveBreakpointSegmenter(abd).isBreakpoint(a, b);
}

double LineEllipseExtractor::splitThreshold(double noise) const
{
	return std::max(params.split_distance_min, params.split_sigmas * noise);
}

bool LineEllipseExtractor::hasStep(const ScanPoints& s, size_t first, size_t last,
	const LineFit& fit, double threshold) const
{
	// On a range lattice (rangeNoiseFloor: its cell's sigma) the readings'
	// errors come in runs of equal range, so consecutive points off the line
	// on one side are the lattice's, not a step's: the test is off there.
	if (params.merge_step_points == 0 || rangeNoiseFloor > 0) return false;
	unsigned int run = 0;
	int side = 0;
	for (size_t k = first; k <= last; k++)
	{
		const double r = fit.residual(s.points[k].x, s.points[k].y);
		const int here = r > threshold ? 1 : (r < -threshold ? -1 : 0);
		run = here == 0 ? 0 : (here == side ? run + 1 : 1);
		side = here;
		if (run >= params.merge_step_points) return true;
	}
	return false;
}

void LineEllipseExtractor::split(
	const ScanPoints& s, size_t first, size_t last, double noise)
{
	const double threshold = splitThreshold(noise);
	// Iterative end-point fit with an explicit stack (no recursion).
	m_stack.clear();
	m_stack.emplace_back(first, last);
	while (!m_stack.empty())
	{
		const auto [a, b] = m_stack.back();
		m_stack.pop_back();
		double worst = 0;
		size_t at = a;
		// PointNoiseEstimator::chordDistance with the chord's length
		// computed once.
		const ScanPoint &pa = s.points[a], &pb = s.points[b];
		const double ex = pb.x - pa.x, ey = pb.y - pa.y;
		const double len = std::sqrt(ex * ex + ey * ey);
		for (size_t k = a + 1; k < b; k++)
		{
			const ScanPoint& p = s.points[k];
			const double d = len < 1e-12 ? chordDistance(pa, pb, p)
										 : std::abs(ex * (p.y - pa.y) - ey * (p.x - pa.x)) / len;
			if (d > worst)
			{
				worst = d;
				at = k;
			}
		}
		if (worst > threshold)
		{
			// Second half first on the stack so runs come out in order.
			m_stack.emplace_back(at, b);
			m_stack.emplace_back(a, at);
		}
		else
		{
			m_runs.emplace_back(a, b);
			m_runNoise.push_back(noise);
		}
	}
}

void LineEllipseExtractor::mergeRuns(const ScanPoints& s)
{
	// m_pairKept[r]: runs r and r + 1, as they are, were fitted jointly and
	// stayed apart; a later pass would fit them again to the same end.
	m_pairKept.assign(m_runs.size(), 0);
	bool merged = true;
	while (merged)
	{
		merged = false;
		for (size_t r = 0; r + 1 < m_runs.size(); r++)
		{
			auto& A = m_runs[r];
			const auto& B = m_runs[r + 1];
			// Only runs of the same cluster (sharing or adjacent points).
			if (B.first > A.second + 1) continue;
			if (clusterBreak(s.points[A.second], s.points[B.first])) continue;
			if (m_pairKept[r]) continue;
			// One line if the joint fit is as good as the noise allows: a
			// single noise spike (which may have caused the split) must not
			// keep a straight wall in pieces.
			const LineFit f = fitRun(s, A.first, B.second);
			const double noise = std::max(m_runNoise[r], params.min_point_sigma);
			if (f.sigma <= params.merge_sigmas * noise && f.sigma <= params.max_line_sigma &&
				!hasStep(s, A.first, B.second, f, splitThreshold(m_runNoise[r])))
			{
				A.second = B.second;
				m_runs.erase(m_runs.begin() + static_cast<long>(r) + 1);
				m_runNoise.erase(m_runNoise.begin() + static_cast<long>(r) + 1);
				m_pairKept.erase(m_pairKept.begin() + static_cast<long>(r) + 1);
				// Run r changed: both its pairs are to be fitted again.
				m_pairKept[r] = 0;
				if (r > 0) m_pairKept[r - 1] = 0;
				merged = true;
			}
			else
				m_pairKept[r] = 1;
		}
	}
}

void LineEllipseExtractor::refine(const ScanPoints& s)
{
	// A run's fit depends on its points only: each run's last fit is kept
	// with the points it was made on, and used again while the run keeps
	// them (across pairs and passes).
	m_runFits.assign(m_runs.size(), {Run{1, 0}, LineFit()});
	auto fitOf = [&](size_t r) -> const LineFit& {
		auto& [fitted, fit] = m_runFits[r];
		if (fitted != m_runs[r])
		{
			fit = fitRun(s, m_runs[r].first, m_runs[r].second);
			fitted = m_runs[r];
		}
		return fit;
	};
	for (unsigned it = 0; it < params.refine_iterations; it++)
	{
		bool moved = false;
		for (size_t r = 0; r + 1 < m_runs.size(); r++)
		{
			auto& A = m_runs[r];
			auto& B = m_runs[r + 1];
			if (B.first > A.second + 1) continue;  // not neighbours
			if (A.second - A.first < 2 || B.second - B.first < 2) continue;
			const LineFit fa = fitOf(r);
			const LineFit fb = fitOf(r + 1);
			// Split runs share their boundary point: give it (and its
			// neighbours, one at a time) to the closer line.
			auto closerToB = [&](size_t k) {
				return std::abs(fb.residual(s.points[k].x, s.points[k].y)) <
					std::abs(fa.residual(s.points[k].x, s.points[k].y));
			};
			if (A.second >= B.first)  // shared boundary point
			{
				const size_t k = A.second;
				if (closerToB(k))
					A.second = k - 1;
				else
					B.first = k + 1;
				moved = true;
				continue;
			}
			if (closerToB(A.second))
			{
				B.first = A.second;
				A.second--;
				moved = true;
			}
			else if (!closerToB(B.first))
			{
				A.second = B.first;
				B.first++;
				moved = true;
			}
		}
		if (!moved) break;
	}
}

bool LineEllipseExtractor::Parameters::operator==(const Parameters& o) const
{
	auto fields = [](const Parameters& p) {
		return std::tie(p.max_point_gap, p.grazing_incidence, p.split_distance_min, p.split_sigmas,
			p.trim_sigmas, p.merge_sigmas, p.merge_step_points, p.line_outlier_sigmas,
			p.collinear_fusion_chi2, p.max_line_sigma, p.min_points, p.min_length,
			p.ellipse_max_length, p.refine_iterations, p.min_point_sigma,
			p.ellipse_shape_sigma_ratio, p.line_fit);
	};
	return fields(*this) == fields(o);
}

void LineEllipseExtractor::extract(const ScanPoints& s, std::vector<ScanFeature>& out)
{
	if (m_memo.valid && m_memo.params == params && m_memo.rangeNoiseFloor == rangeNoiseFloor &&
		m_memo.scan.samePointsAs(s))
	{
		out = m_memo.features;
		return;
	}
	extractAnew(s, out);
	m_memo.valid = true;
	m_memo.params = params;
	m_memo.rangeNoiseFloor = rangeNoiseFloor;
	m_memo.scan = s;
	m_memo.features = out;
}

void LineEllipseExtractor::extractAnew(const ScanPoints& s, std::vector<ScanFeature>& out)
{
	out.clear();
	m_runs.clear();
	m_runNoise.clear();
	const size_t n = s.size();
	// 1. Clusters of consecutive close points, 2. split each.
	for (size_t start = 0; start < n;)
	{
		size_t end = start;
		while (end + 1 < n && !clusterBreak(s.points[end], s.points[end + 1])) end++;
		if (end > start) split(s, start, end, m_noise.estimate(s.points, start, end));
		start = end + 1;
	}
	mergeRuns(s);  // 3.
	refine(s);	// 4.

	for (size_t r = 0; r < m_runs.size(); r++)
	{
		auto [a, b] = m_runs[r];
		if (b - a + 1 < params.min_points) continue;
		// 5. Trim ends that do not belong to the line.
		const double trim =
			params.trim_sigmas * std::max(m_runNoise[r], params.min_point_sigma);
		LineFit f = fitRun(s, a, b);
		while (b - a + 1 > params.min_points)
		{
			const double ra = std::abs(f.residual(s.points[a].x, s.points[a].y));
			const double rb = std::abs(f.residual(s.points[b].x, s.points[b].y));
			if (std::max(ra, rb) <= trim) break;
			if (ra >= rb)
				a++;
			else
				b--;
			f = fitRun(s, a, b);
		}
		// 6. Selection.
		if (f.sigma > params.max_line_sigma || f.length < params.min_length) continue;

		ScanFeature feat;
		feat.firstPoint = static_cast<uint32_t>(a);
		feat.lastPoint = static_cast<uint32_t>(b);
		feat.length = f.length;
		feat.sigma = f.sigma;
		feat.rho = f.rho;
		feat.alpha = f.alpha;
		if (f.length <= params.ellipse_max_length)
		{
			feat.kind = ScanFeature::Kind::Ellipse;
			feat.x = f.cx;
			feat.y = f.cy;
			feat.a2 = feat.b2 = 1;
			feat.c = 0;
		}
		else
		{
			feat.kind = ScanFeature::Kind::Line;
			setLineParameters(feat);
		}
		out.push_back(feat);
	}
	const double pooled2 = pooledRangeVariance(s, out);
	setCovariances(s, out, pooled2);
	cleanAndFuseLines(s, out, pooled2);	 // 7., 8.
}

double LineEllipseExtractor::pooledRangeVariance(
	const ScanPoints& s, const std::vector<ScanFeature>& features) const
{
	// Range noise of the scan, pooled over every feature's points: a point
	// at incidence theta to its line (theta between the beam and the
	// line's normal) is off the line by range noise times |cos theta|.
	// Hundreds of points make this estimate steady; a feature's own few
	// residuals would not (an under-estimate by chance makes the
	// covariance over-confident).
	double sumR2 = 0, sumC2 = 0;
	size_t points = 0;
	for (const auto& f : features)
	{
		const double ca = std::cos(f.alpha), sa = std::sin(f.alpha);
		for (uint32_t k = f.firstPoint; k <= f.lastPoint; k++)
		{
			const auto& p = s.points[k];
			const double r = f.rho - p.x * ca - p.y * sa;
			const double cosT = (p.x * ca + p.y * sa) / p.range;
			sumR2 += r * r;
			sumC2 += cosT * cosT;
		}
		points += f.lastPoint - f.firstPoint + 1;
	}
	const size_t dof = points > 2 * features.size() ? points - 2 * features.size() : 0;
	return std::max(rangeNoiseFloor * rangeNoiseFloor,
		dof > 0 && sumC2 > 0 ? sumR2 / sumC2 * static_cast<double>(points) / static_cast<double>(dof)
							 : 0.0);
}

void LineEllipseExtractor::setCovariances(
	const ScanPoints& s, std::vector<ScanFeature>& features, double pooled2) const
{
	for (auto& f : features)
		setCovariance(&s.points[f.firstPoint], f.lastPoint - f.firstPoint + 1, f, pooled2);
}

void LineEllipseExtractor::setCovariance(
	const ScanPoint* pts, size_t n, ScanFeature& f, double pooled2) const
{
	const double floor2 = params.min_point_sigma * params.min_point_sigma;
	const double ca = std::cos(f.alpha), sa = std::sin(f.alpha);
	const double dn = static_cast<double>(n);
	// Per-point perpendicular variances v_k; a feature fitting much worse
	// than the scan's noise predicts (a curved or cluttered surface)
	// keeps its own, larger residual variance.
	double predicted = 0;
	for (size_t k = 0; k < n; k++)
	{
		const auto& p = pts[k];
		const double cosT = (p.x * ca + p.y * sa) / p.range;
		predicted += std::max(floor2, pooled2 * cosT * cosT);
	}
	predicted /= dn;
	const double own = f.sigma * f.sigma * dn / (dn - 2);
	const double inflate = own > 2 * predicted ? own / predicted : 1.0;
	if (f.kind == ScanFeature::Kind::Ellipse)
	{
		// Centroid: the points' noise (along their beams, taken
		// isotropic here) averaged, plus the shift of the visible part
		// of an object between viewpoints.
		const double shape = params.ellipse_shape_sigma_ratio * f.length;
		const double var = inflate * std::max(floor2, pooled2) / dn + shape * shape;
		f.cxx = f.cyy = var;
		f.cxy = 0;
		return;
	}
	if (params.line_fit == "weighted")
	{
		weightedRefit(pts, n, f, inflate, pooled2, floor2);
		return;
	}
	double cxm = 0, cym = 0;
	for (size_t k = 0; k < n; k++)
	{
		cxm += pts[k].x;
		cym += pts[k].y;
	}
	cxm /= dn;
	cym /= dn;
	double sumV = 0, sumS2 = 0, sumSV = 0, sumS2V = 0;
	for (size_t k = 0; k < n; k++)
	{
		const auto& p = pts[k];
		const double cosT = (p.x * ca + p.y * sa) / p.range;
		const double v = inflate * std::max(floor2, pooled2 * cosT * cosT);
		const double sk = -(p.x - cxm) * sa + (p.y - cym) * ca;
		sumV += v;
		sumS2 += sk * sk;
		sumSV += sk * v;
		sumS2V += sk * sk * v;
	}
	// Unweighted TLS with perpendicular errors e_k of variances v_k: a
	// point at s_k along the line (from the centroid) is off the fitted
	// line by e_k + (s_c + s_k) d(alpha) - d(rho), so the fit gives
	// d(alpha) = -sum s_k e_k / sum s_k^2 and d(rho) = mean(e) + s_c d(alpha)
	// (s_c = centroid . u, u = (-sin alpha, cos alpha)). The mean error
	// and the tilt are correlated when v_k varies along the line.
	const double sc = -cxm * sa + cym * ca;
	const double vA = sumS2V / (sumS2 * sumS2);
	const double cEA = -sumSV / (dn * sumS2);
	const double vR = sumV / (dn * dn) + 2 * sc * cEA + sc * sc * vA;
	const double cRA = cEA + sc * vA;
	f.varRho = vR;
	f.varAlpha = vA;
	f.covRhoAlpha = cRA;
	setFootPointCovariance(f);
}

bool LineEllipseExtractor::sameLine(const ScanFeature& a, const ScanFeature& b) const
{
	// The two lines' (rho, alpha) are independent estimates (disjoint
	// points); their difference against the sum of their covariances is
	// chi-square with 2 degrees of freedom if they are one line. A line
	// through the sensor's side of the origin may come out with alpha
	// turned by pi and rho negated: compare it so.
	double dAlpha = mrpt::math::wrapToPi(a.alpha - b.alpha);
	double rhoB = b.rho, covB = b.covRhoAlpha;
	if (std::abs(dAlpha) > M_PI / 2)
	{
		dAlpha = mrpt::math::wrapToPi(dAlpha - M_PI);
		rhoB = -rhoB;
		covB = -covB;
	}
	const double dRho = a.rho - rhoB;
	const double sRR = a.varRho + b.varRho, sAA = a.varAlpha + b.varAlpha,
				 sRA = a.covRhoAlpha + covB;
	const double det = sRR * sAA - sRA * sRA;
	if (!(det > 0)) return false;
	const double d2 = (sAA * dRho * dRho - 2 * sRA * dRho * dAlpha + sRR * dAlpha * dAlpha) / det;
	return d2 <= params.collinear_fusion_chi2;
}

bool LineEllipseExtractor::dropOutliers(LineFit& fit, double pooled2)
{
	// A point's perpendicular sigma under range noise at its incidence, as
	// the covariance takes it; points beyond line_outlier_sigmas of it are
	// not on the line (a rack's upright, its side seen obliquely, the
	// corner of an adjoining wall), refitted until none is (3 passes at
	// most). Never below min_points: then the line keeps its points.
	std::vector<ScanPoint>& pts = m_linePoints;
	const double k2 = params.line_outlier_sigmas * params.line_outlier_sigmas;
	const double floor2 = params.min_point_sigma * params.min_point_sigma;
	bool dropped = false;
	for (int pass = 0; pass < 3 && k2 > 0; pass++)
	{
		const double ca = std::cos(fit.alpha), sa = std::sin(fit.alpha);
		auto outlier = [&](const ScanPoint& p) {
			const double cosT = (p.x * ca + p.y * sa) / p.range;
			const double r = fit.residual(p.x, p.y);
			return r * r > k2 * std::max(floor2, pooled2 * cosT * cosT);
		};
		const size_t kept =
			pts.size() - static_cast<size_t>(std::count_if(pts.begin(), pts.end(), outlier));
		if (kept == pts.size() || kept < params.min_points) break;
		pts.erase(std::remove_if(pts.begin(), pts.end(), outlier), pts.end());
		fit = LineFit::fit(pts.data(), pts.size());
		dropped = true;
	}
	return dropped;
}

void LineEllipseExtractor::refitLine(ScanFeature& f, const LineFit& fit, double pooled2) const
{
	f.rho = fit.rho;
	f.alpha = fit.alpha;
	f.sigma = fit.sigma;
	f.length = fit.length;
	setLineParameters(f);
	setCovariance(m_linePoints.data(), m_linePoints.size(), f, pooled2);
}

void LineEllipseExtractor::cleanAndFuseLines(
	const ScanPoints& s, std::vector<ScanFeature>& features, double pooled2)
{
	// Steps 7 and 8, one line at a time in bearing order: m_linePoints
	// holds the points of the last line kept, which the next line may join.
	const bool fuse = params.collinear_fusion_chi2 > 0;
	if (!fuse && !(params.line_outlier_sigmas > 0)) return;
	std::vector<ScanPoint>& pts = m_linePoints;
	size_t out = 0;
	long lastLine = -1;	 // index in the compacted list of the last line kept
	for (size_t i = 0; i < features.size(); i++)
	{
		const ScanFeature f = features[i];
		const auto first = s.points.begin() + f.firstPoint, last = s.points.begin() + f.lastPoint + 1;
		if (f.kind == ScanFeature::Kind::Line && fuse && lastLine >= 0 &&
			sameLine(features[static_cast<size_t>(lastLine)], f))
		{
			// 8. One line with the last: fitted to both lines' points (the
			// last's kept points and f's), not to what lies between.
			ScanFeature& g = features[static_cast<size_t>(lastLine)];
			pts.insert(pts.end(), first, last);
			LineFit fit = LineFit::fit(pts.data(), pts.size());
			dropOutliers(fit, pooled2);
			g.firstPoint = std::min(g.firstPoint, f.firstPoint);
			g.lastPoint = std::max(g.lastPoint, f.lastPoint);
			refitLine(g, fit, pooled2);
			continue;
		}
		features[out] = f;
		if (f.kind == ScanFeature::Kind::Line)
		{
			// 7. The line's outliers; a line that has none keeps the fit
			// and covariance it has.
			lastLine = static_cast<long>(out);
			pts.assign(first, last);
			if (params.line_outlier_sigmas > 0)
			{
				LineFit fit = LineFit::fit(pts.data(), pts.size());
				if (dropOutliers(fit, pooled2)) refitLine(features[out], fit, pooled2);
			}
		}
		out++;
	}
	features.resize(out);
}

void LineEllipseExtractor::weightedRefit(const ScanPoint* pts, size_t n, ScanFeature& f,
	double inflate, double pooled2, double floor2)
{
	// Weighted TLS, w_k = 1 / v_k with v_k the point's perpendicular
	// variance at the incidence the previous fit gives; twice (the second
	// pass's incidences barely move).
	auto weight = [&](const ScanPoint& p, double ca, double sa) {
		const double cosT = (p.x * ca + p.y * sa) / p.range;
		return 1.0 / (inflate * std::max(floor2, pooled2 * cosT * cosT));
	};
	for (int pass = 0; pass < 2; pass++)
	{
		const double ca = std::cos(f.alpha), sa = std::sin(f.alpha);
		// The normal: the weighted scatter's direction of least spread
		// (eq. 4 on weighted sums), through the weighted centroid.
		PointScatter scatter;
		for (size_t k = 0; k < n; k++) scatter.add(pts[k].x, pts[k].y, weight(pts[k], ca, sa));
		const double sw = scatter.weight(), mx = scatter.cx(), my = scatter.cy();
		const PointScatter::Line line = scatter.line();
		double alpha = std::atan2(line.ny, line.nx);
		double rho = mx * line.nx + my * line.ny;
		if (rho < 0)
		{
			rho = -rho;
			alpha += M_PI;
		}
		f.alpha = mrpt::math::wrapToPi(alpha);
		f.rho = rho;
		if (pass == 0) continue;
		// Covariance: the tilt from sum w s^2, the offset at the weighted
		// centroid from sum w, uncorrelated there; rho = offset + s_c alpha.
		const double na = std::cos(f.alpha), nb = std::sin(f.alpha);
		double sumWS2 = 0;
		for (size_t k = 0; k < n; k++)
		{
			const auto& p = pts[k];
			const double w = weight(p, na, nb);
			const double sk = -(p.x - mx) * nb + (p.y - my) * na;
			sumWS2 += w * sk * sk;
		}
		const double vA = 1.0 / sumWS2;
		const double sc = -mx * nb + my * na;
		f.varAlpha = vA;
		f.varRho = 1.0 / sw + sc * sc * vA;
		f.covRhoAlpha = sc * vA;
	}
	setLineParameters(f);
	setFootPointCovariance(f);
}
}  // namespace featloc
