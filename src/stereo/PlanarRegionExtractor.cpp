#include "featloc/stereo/PlanarRegionExtractor.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace featloc
{
namespace
{
/** chi2 with 2 degrees of freedom at the probability of 3 sigma (99.73%). */
constexpr double kChi2TwoDof3Sigma = 11.83;
/** A wall is hidden where another is nearer by more than this fraction of
 * the depth plus this many metres. */
constexpr double kOcclusionMargin = 0.05;
/** [m] A wall is visible in a column from the predicted pose when no other
 * wall meets the ray more than this before it. */
constexpr double kVisibleTolerance = 0.01;
/** [m] Height of the band above the camera over which a wall's coverage
 * is counted (PlanarRegion::bandPixels). */
constexpr double kCoverageBand = 0.3;
}  // namespace

namespace
{
/** Eqs. (9)-(10): the disparity d = D(X) of camera point c (a point of the
 * world, seen from X) and its sigma, sqrt(dD/dX Sigma_X dD/dX^T + s2nu). */
double predictedDisparity(
	const StereoHead& head, const Eigen::Vector3d& X, const Eigen::Matrix3d& SigmaX, const Eigen::Vector2d& c,
	double s2nu, double& sigma)
{
	Eigen::Matrix<double, 2, 3> Jc;
	head.toCamera(X, head.toWorld(X, c), &Jc);
	const double d = head.fx * head.baseline / c.y();
	const Eigen::RowVector3d JD = -d / c.y() * Jc.row(1);
	sigma = std::sqrt(JD * SigmaX * JD.transpose() + s2nu);
	return d;
}
}  // namespace

bool PlanarRegionExtractor::disparityRange(
	const MapWall& wall, const StereoHead& head, const Eigen::Vector3d& X, const Eigen::Matrix3d& SigmaX,
	double& dMin, double& dMax) const
{
	const Eigen::Vector2d ca = head.toCamera(X, wall.a), cb = head.toCamera(X, wall.b);
	// Liang-Barsky clipping of ca + t (cb - ca), t in [0, 1], to c_y >=
	// near and the columns' wedge k0 c_y <= c_x <= k1 c_y.
	const double k0 = (0 - head.cx) / head.fx, k1 = (head.width - 1 - head.cx) / head.fx;
	double t0 = 0, t1 = 1;
	auto keep = [&](const Eigen::Vector2d& g, double h) {	// g . p + h >= 0
		const double fa = g.dot(ca) + h, fb = g.dot(cb) + h;
		if (fa < 0 && fb < 0) return false;
		if (fa < 0) t0 = std::max(t0, fa / (fa - fb));
		if (fb < 0) t1 = std::min(t1, fa / (fa - fb));
		return t0 <= t1;
	};
	if (!keep({0, 1}, -options.near_limit) || !keep({1, -k0}, 0) || !keep({-1, k1}, 0)) return false;
	dMin = 1e300, dMax = -1e300;
	const double s2nu = 2 * options.sigma_img * options.sigma_img;
	for (const double t : {t0, t1})
	{
		double sigma = 0;
		const double d = predictedDisparity(head, X, SigmaX, ca + t * (cb - ca), s2nu, sigma);
		dMin = std::min(dMin, d - options.window_sigmas * sigma);
		dMax = std::max(dMax, d + options.window_sigmas * sigma);
	}
	return true;
}

PlanarRegion PlanarRegionExtractor::extract(
	const MapWall& wall, size_t wallIndex, const StereoHead& head, const Eigen::Vector3d& X,
	const Eigen::Matrix3d& SigmaX, const cv::Mat& disparity, const std::vector<double>* nearest) const
{
	PlanarRegion r;
	r.wall = wallIndex;
	const double s2img = options.sigma_img * options.sigma_img;
	const double k = options.window_sigmas;

	// The wall in camera coordinates, clipped to near_limit ahead.
	Eigen::Vector2d ca = head.toCamera(X, wall.a), cb = head.toCamera(X, wall.b);
	const double near = options.near_limit;
	if (ca.y() < near && cb.y() < near)
	{
		r.reason = "behind the camera";
		return r;
	}
	bool aClipped = false, bClipped = false;
	auto clip = [&](Eigen::Vector2d& p, const Eigen::Vector2d& q, bool& clipped) {
		if (p.y() >= near) return;
		p = q + (p - q) * (q.y() - near) / (q.y() - p.y());
		clipped = true;
	};
	clip(ca, cb, aClipped);
	clip(cb, ca, bClipped);

	// Eqs. (3)-(6): the ends' columns and their sigmas from Sigma_X.
	auto endColumn = [&](const Eigen::Vector2d& pw, const Eigen::Vector2d& c, double& u, double& sigma) {
		Eigen::Matrix<double, 2, 3> Jc;
		head.toCamera(X, pw, &Jc);
		Eigen::Matrix2d Jp;
		u = head.project(c, &Jp).x();
		const Eigen::RowVector3d Ju = Jp.row(0) * Jc;
		sigma = std::sqrt(Ju * SigmaX * Ju.transpose() + s2img);
	};
	endColumn(head.toWorld(X, ca), ca, r.uA, r.sigmaUA);
	endColumn(head.toWorld(X, cb), cb, r.uB, r.sigmaUB);
	const double W = head.width;
	r.aInView = !aClipped && r.uA - k * r.sigmaUA >= 0 && r.uA + k * r.sigmaUA <= W - 1;
	r.bInView = !bClipped && r.uB - k * r.sigmaUB >= 0 && r.uB + k * r.sigmaUB <= W - 1;
	const double lo = std::min(r.uA - k * r.sigmaUA, r.uB - k * r.sigmaUB);
	const double hi = std::max(r.uA + k * r.sigmaUA, r.uB + k * r.sigmaUB);
	r.uMin = std::max(0, static_cast<int>(std::floor(lo)));
	r.uMax = std::min(head.width - 1, static_cast<int>(std::ceil(hi)));
	if (r.uMax - r.uMin < 3)
	{
		r.reason = "outside the image";
		return r;
	}

	// The plane frame: origin at end a, e along the wall, n across it.
	r.fit.origin = ca;
	r.fit.e = (cb - ca).normalized();
	r.fit.n = Eigen::Vector2d(-r.fit.e.y(), r.fit.e.x());

	r.mask = cv::Mat::zeros(disparity.size(), CV_8U);
	const double s2nu = 2 * s2img;	// eq. (7)
	std::vector<double> ws, ss, vars;
	std::vector<char> inVisibleColumn;  // and above the camera: the wall observation's pixels
	// Occlusion by nearer walls, kept only where it holds across the
	// column's 3-sigma window (the nearest depth's maximum over it).
	std::vector<double> hidden;
	if (nearest && static_cast<int>(nearest->size()) == disparity.cols)
	{
		const int w = static_cast<int>(std::ceil(k * std::max(r.sigmaUA, r.sigmaUB)));
		hidden.assign(nearest->size(), 0);
		for (int u = r.uMin; u <= r.uMax; u++)  // the columns searched below
		{
			double m = 0;
			for (int j = std::max(0, u - w); j <= std::min(disparity.cols - 1, u + w); j++)
				m = std::max(m, (*nearest)[static_cast<size_t>(j)]);
			hidden[static_cast<size_t>(u)] = m;
		}
	}
	size_t occludedColumns = 0;
	for (int u = r.uMin; u <= r.uMax; u++)
	{
		// The ray of column u meets the predicted wall.
		Eigen::Vector2d c;
		if (!head.columnRayMeets(u, ca, cb - ca, c)) continue;
		if (c.y() < near) continue;
		if (!hidden.empty() && c.y() > hidden[static_cast<size_t>(u)] * (1 + kOcclusionMargin) + kOcclusionMargin)
		{
			occludedColumns++;
			continue;
		}
		const double t = (c - ca).dot(cb - ca) / (cb - ca).squaredNorm();
		const bool visible = nearest && static_cast<int>(nearest->size()) == disparity.cols && t >= 0 && t <= 1 &&
			c.y() <= (*nearest)[static_cast<size_t>(u)] + kVisibleTolerance;
		if (visible)
		{
			r.visibleColumns++;
			if (r.visibleUMin < 0) r.visibleUMin = u;
			r.visibleUMax = u;
			// Rows of the band just above the camera where this wall shows
			// at this depth, if it is that tall.
			r.bandRows += std::min(head.cy, kCoverageBand * head.fy / c.y());
			r.viewAngle += std::asin(std::min(1.0, std::abs(c.normalized().x() * r.fit.e.y() - c.normalized().y() * r.fit.e.x())));
		}
		double sigmaD = 0;
		const double dPred = predictedDisparity(head, X, SigmaX, c, s2nu, sigmaD);
		for (int v = 0; v < disparity.rows; v++)
		{
			const float d = disparity.at<float>(v, u);
			if (d <= 0 || std::abs(d - dPred) > k * sigmaD) continue;
			const Eigen::Vector2d p = head.triangulate(u, u - d);
			const double z = head.heightAt(v, p.y());
			if (z < options.min_height || z > options.max_height) continue;
			r.mask.at<uchar>(v, u) = 255;
			const Eigen::Vector2d sw_ = r.fit.toPlane(p);
			// dc/dd = -c/d (c scales with 1/d along the ray), taken at the
			// predicted point: weights from the measured disparity would
			// favour pixels whose noise brought them nearer.
			const double dn = r.fit.n.dot(-c / dPred);
			const double var = dn * dn * s2nu;
			// Above the camera only vertical surfaces are seen (to the
			// ceiling, left out by max_height): a surface lower than the
			// camera shows its top beneath the horizon, at depths inside
			// the band (a table 0.75 m high seen from 0.75 m away: its top
			// fills 130 rows, its face 7, and the fit lands 4 cm behind it).
			const bool observed = visible && z > head.camZ;
			if (observed) r.visiblePixels++;
			if (observed && z <= head.camZ + kCoverageBand) r.bandPixels++;
			inVisibleColumn.push_back(observed ? 1 : 0);
			ss.push_back(sw_.x());
			ws.push_back(sw_.y());
			vars.push_back(var);
			r.pixels++;
		}
	}
	if (r.visibleColumns > 0) r.viewAngle /= static_cast<double>(r.visibleColumns);
	if (r.pixels < options.min_pixels)
	{
		r.reason = "too few disparity pixels on it (" + std::to_string(r.pixels) + ")";
		if (occludedColumns > 0) r.reason += ", " + std::to_string(occludedColumns) + " columns hidden by nearer walls";
		return r;
	}
	// Eq. (11), weighted least squares of w = a + b s over every pixel or
	// over the wall observation's (visibleOnly); the covariance scaled by
	// the residuals' chi2 per degree of freedom (at least 1) and by the
	// block's pixels, which one SAD window makes dependent. Returns the
	// RMS residual.
	const auto fitLine = [&](bool visibleOnly, Eigen::Vector2d& line, Eigen::Matrix2d& cov) {
		Eigen::Matrix2d N = Eigen::Matrix2d::Zero();
		Eigen::Vector2d rhs = Eigen::Vector2d::Zero();
		size_t n = 0;
		for (size_t i = 0; i < ws.size(); i++)
		{
			if (visibleOnly && !inVisibleColumn[i]) continue;
			const double wgt = 1.0 / vars[i];
			N(0, 0) += wgt;
			N(0, 1) += wgt * ss[i];
			N(1, 1) += wgt * ss[i] * ss[i];
			rhs += wgt * Eigen::Vector2d(ws[i], ws[i] * ss[i]);
			n++;
		}
		N(1, 0) = N(0, 1);
		const Eigen::Matrix2d Ninv = N.inverse();
		line = Ninv * rhs;
		double chi2 = 0, sum2 = 0;
		for (size_t i = 0; i < ws.size(); i++)
		{
			if (visibleOnly && !inVisibleColumn[i]) continue;
			const double res = ws[i] - line.x() - line.y() * ss[i];
			chi2 += res * res / vars[i];
			sum2 += res * res;
		}
		const double dof = static_cast<double>(n) - 2;
		cov = Ninv * std::max(1.0, chi2 / dof) * static_cast<double>(options.block_size * options.block_size);
		return std::sqrt(sum2 / static_cast<double>(n));
	};
	r.rms = fitLine(false, r.fit.line, r.fit.lineCovariance);
	r.visibleFitted = r.visiblePixels >= options.min_pixels;
	if (r.visibleFitted) fitLine(true, r.visibleLine, r.visibleLineCovariance);

	// The pixels are the wall's only if the fitted line is where the map
	// puts the wall, within the robot's uncertainty (featloc's check: the
	// disparity band of a small wall also takes in a neighbour seen at
	// the same depth). The map's line in this frame is (0, 0); its
	// covariance from Sigma_X by central differences.
	const auto mapLine = [&](const Eigen::Vector3d& Xp) {
		const Eigen::Vector2d pa = r.fit.toPlane(head.toCamera(Xp, wall.a)),
							  pb = r.fit.toPlane(head.toCamera(Xp, wall.b));
		const double slope = (pb.y() - pa.y()) / (pb.x() - pa.x());
		return Eigen::Vector2d(pa.y() - slope * pa.x(), slope);
	};
	Eigen::Matrix<double, 2, 3> Jl;
	for (int i = 0; i < 3; i++)
	{
		Eigen::Vector3d dx = Eigen::Vector3d::Zero();
		dx(i) = 1e-6;
		Jl.col(i) = (mapLine(X + dx) - mapLine(X - dx)) / 2e-6;
	}
	const Eigen::Matrix2d S = Jl * SigmaX * Jl.transpose() + r.fit.lineCovariance;
	r.mapDistance2 = r.fit.line.dot(S.ldlt().solve(r.fit.line));
	if (r.mapDistance2 > kChi2TwoDof3Sigma)
	{
		char why[120];
		std::snprintf(why, sizeof(why), "its pixels fit a line %.2f m / %.1f deg from the map's wall (chi2 %.0f)",
			r.fit.line.x(), std::atan(r.fit.line.y()) * 180 / M_PI, r.mapDistance2);
		r.reason = why;
		return r;
	}
	r.fitted = true;
	return r;
}
std::vector<double> PlanarRegionExtractor::nearestWallDepth(
	const std::vector<MapWall>& walls, const StereoHead& head, const Eigen::Vector3d& X) const
{
	std::vector<double> depth(static_cast<size_t>(head.width), std::numeric_limits<double>::infinity());
	for (const auto& w : walls)
	{
		const Eigen::Vector2d ca = head.toCamera(X, w.a), cb = head.toCamera(X, w.b);
		if (ca.y() < options.near_limit && cb.y() < options.near_limit) continue;
		for (int u = 0; u < head.width; u++)
		{
			Eigen::Vector2d c;
			if (!head.columnRayMeets(u, ca, cb - ca, c) || c.y() < options.near_limit) continue;
			// On the wall: between its ends.
			const double t = (c - ca).dot(cb - ca) / (cb - ca).squaredNorm();
			if (t < 0 || t > 1) continue;
			auto& d = depth[static_cast<size_t>(u)];
			d = std::min(d, c.y());
		}
	}
	return depth;
}
}  // namespace featloc
