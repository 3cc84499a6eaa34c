#include "featloc/sim/StereoRenderer.h"

#include <Eigen/Dense>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

#include "featloc/core/ConfigError.h"
#include "featloc/sim/SurfaceMaterial.h"

namespace featloc
{
namespace
{
/** Bilinear, wrapping lookup in one mip level of a material. Coordinates
 * are shifted by a large multiple of the tile before truncating to an
 * integer, so that truncation is floor() without a libm call (this is
 * the renderer's innermost loop). */
struct Sampler
{
	static constexpr double kShift = 1 << 22;  //!< [texels] a multiple of every level size
	const float* texels = nullptr;
	int size = 1, mask = 0;
	double invTexel = 1;
	// Set by setU(): the texel column left of u and the weight to the next.
	int x0 = 0;
	float ax = 0;

	Sampler() = default;
	Sampler(const SurfaceMaterial& m, double footprint)
	{
		const int li = m.levelFor(footprint);
		const auto& l = m.level(li);
		texels = l.texels.data();
		size = l.size;
		mask = size - 1;
		invTexel = 1.0 / (m.texelSize() * static_cast<double>(1 << li));
	}
	void setU(double u)
	{
		const double x = u * invTexel - 0.5 + kShift;
		const auto xi = static_cast<int64_t>(x);
		ax = static_cast<float>(x - static_cast<double>(xi));
		x0 = static_cast<int>(xi & mask);
	}
	/** Bilinear between texel columns c0, c0 + 1 and rows r0, r0 + 1
	 * (wrapped). Column-major tiles: down an image column v varies, so the
	 * texels read are contiguous. */
	float bilinear(int c0, float wc, int r0, float wr) const
	{
		const int r1 = (r0 + 1) & mask;
		const float* col0 = texels + c0 * size;
		const float* col1 = texels + ((c0 + 1) & mask) * size;
		const float a = col0[r0] + wc * (col1[r0] - col0[r0]);
		const float b = col0[r1] + wc * (col1[r1] - col0[r1]);
		return a + wr * (b - a);
	}
	float atV(double v) const
	{
		const double y = v * invTexel - 0.5 + kShift;
		const auto yi = static_cast<int64_t>(y);
		return bilinear(
			x0, ax, static_cast<int>(yi & mask), static_cast<float>(y - static_cast<double>(yi)));
	}
	float at(double u, double v)
	{
		setU(u);
		return atV(v);
	}
	/** Texel coordinates of a surface point (already shifted): a row pass
	 * steps them by a constant per pixel. */
	double texelU(double u) const { return u * invTexel - 0.5 + kShift; }
	/** Lookup at fixed-point texel coordinates (16 fractional bits): the
	 * row pass steps them with integer additions. */
	float atFixed(int64_t x, int64_t y) const
	{
		return bilinear(
			static_cast<int>((x >> 16) & mask), static_cast<float>(x & 0xffff) * (1.0f / 65536),
			static_cast<int>((y >> 16) & mask), static_cast<float>(y & 0xffff) * (1.0f / 65536));
	}
};

/** Something one 2-D ray meets: a vertical face (constant depth along the
 * column) or the top of a solid between two faces (depth per row). */
struct Span
{
	bool cap = false;
	double tNear = 0, tFar = 0;	 //!< [m] depth along the level optical axis
	double rowA = 0, rowB = 0;	//!< rows covered (real-valued, A <= B)
	double u = 0;  //!< [m] face: texture coordinate along the surface
	double footprint = 0;  //!< [m] face: one pixel on the surface
	double top = 0;	 //!< [m] cap height
	int segment = -1;  //!< face or cap of a wall segment (else a circle)
	const SurfaceMaterial* material = nullptr;
};

/** Standard normal quantiles at (i + 0.5) / 65536: a 16-bit uniform
 * draw looked up here is a Gaussian draw (tails cut at 4.3 sigma), about
 * ten times cheaper than cv::RNG's normal generator. */
const std::vector<float>& normalQuantiles()
{
	static const std::vector<float> table = [] {
		std::vector<float> q(65536);
		for (size_t i = 0; i < q.size(); i++)
		{
			const double p = (static_cast<double>(i) + 0.5) / 65536.0;
			double lo = -10, hi = 10;  // bisection on the CDF
			for (int k = 0; k < 60; k++)
			{
				const double mid = 0.5 * (lo + hi);
				(0.5 * std::erfc(-mid / std::sqrt(2.0)) < p ? lo : hi) = mid;
			}
			q[i] = static_cast<float>(0.5 * (lo + hi));
		}
		return q;
	}();
	return table;
}

/** [m] what one pixel covers on a face seen at depth t, fx pixels per
 * unit, hit at incidence cosine cosInc: the geometric mean of its extent
 * across (t / fx) and along the surface (stretched by 1 / cosInc, at most
 * 8 times), so that grazing faces blur along but not across. */
double faceFootprint(double t, double fx, double cosInc)
{
	const double across = t / fx;
	return std::sqrt(across * std::min(across / std::max(cosInc, 1e-3), 8 * across));
}

std::shared_ptr<const SurfaceMaterial> materialOf(
	const std::string& texture, const std::string& object, const char* key)
{
	auto m = SurfaceMaterial::byName(texture);
	if (!m)
	{
		std::string known;
		for (const auto& n : SurfaceMaterial::names()) known += (known.empty() ? "" : ", ") + n;
		throw ConfigError(
			"[" + object + "] " + key + " = " + texture +
			": not a material the stereo camera can render; known: " + known);
	}
	return m;
}

/** Heading of a camera's optical axis projected on the floor. */
double headingOf(const mrpt::poses::CPose3D& camera)
{
	const auto R = camera.getRotationMatrix();
	return std::atan2(R(1, 2), R(0, 2));
}

/** Real camera axes expressed in the level camera's axes. */
Eigen::Matrix3d levelFromCamera(const mrpt::poses::CPose3D& camera)
{
	const double psi = headingOf(camera);
	Eigen::Matrix3d levelAxes;	// columns: level x, y, z in the world
	levelAxes << std::sin(psi), 0, std::cos(psi), -std::cos(psi), 0, std::sin(psi), 0, -1, 0;
	return levelAxes.transpose() * camera.getRotationMatrix().asEigen();
}
}  // namespace

StereoRenderer::StereoRenderer(const SimWorld& world, const StereoCameraOptions& camera)
	: m_world(world), m_cam(camera)
{
	for (const auto& s : world.segments())
	{
		m_segmentMaterials.push_back(materialOf(s.texture, s.object, "texture"));
		std::vector<std::shared_ptr<const SurfaceMaterial>> patches;
		for (const auto& p : s.patches)
			patches.push_back(materialOf(p.texture, s.object, "posters/patches/doors"));
		m_patchMaterials.push_back(std::move(patches));
	}
	for (const auto& c : world.circles()) materialOf(c.texture, c.object, "texture");
	for (const auto& a : world.agents()) materialOf(a.params().texture, a.params().name, "texture");
	m_floor = SurfaceMaterial::byName("floor");
	m_ceiling = SurfaceMaterial::byName("ceiling");

	// The level camera's canvas: where the real image's pixels come from.
	const double fx = m_cam.fx, fy = m_cam.fy;
	const int W = static_cast<int>(m_cam.width), H = static_cast<int>(m_cam.height);
	const Eigen::Matrix3d Rrel = levelFromCamera(m_cam.leftCameraOnRobot());
	m_warp = m_cam.hasDistortion() || !Rrel.isIdentity(1e-12);
	if (!m_warp)
	{
		m_cxLevel = m_cam.cx;
		m_cyLevel = m_cam.cy;
		m_wLevel = W;
		m_hLevel = H;
		return;
	}
	// Normalised rays of the real pixels: through the lens (distorted
	// pixels) and ideal (the rectified image the ground truth refers to).
	std::vector<cv::Point2f> pixels;
	pixels.reserve(static_cast<size_t>(W * H));
	for (int v = 0; v < H; v++)
		for (int u = 0; u < W; u++) pixels.emplace_back(static_cast<float>(u), static_cast<float>(v));
	const cv::Matx33d K(fx, 0, m_cam.cx, 0, fy, m_cam.cy, 0, 0, 1);
	std::vector<cv::Point2f> lensRays;
	cv::undistortPoints(
		pixels, lensRays, K, cv::Mat(m_cam.distortion), cv::noArray(), cv::noArray(),
		cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 50, 1e-9));
	auto toLevel = [&](double xn, double yn, double& x, double& y, double& invZ) {
		const Eigen::Vector3d d = Rrel * Eigen::Vector3d(xn, yn, 1);
		invZ = 1.0 / d.z();
		x = fx * d.x() / d.z();
		y = fy * d.y() / d.z();
	};
	double minX = 1e300, minY = 1e300, maxX = -1e300, maxY = -1e300;
	std::vector<double> lx(pixels.size()), ly(pixels.size()), ix(pixels.size()), iy(pixels.size()),
		iz(pixels.size());
	for (size_t i = 0; i < pixels.size(); i++)
	{
		double unused = 0;
		toLevel(lensRays[i].x, lensRays[i].y, lx[i], ly[i], unused);
		toLevel((pixels[i].x - m_cam.cx) / fx, (pixels[i].y - m_cam.cy) / fy, ix[i], iy[i], iz[i]);
		for (double x : {lx[i], ix[i]}) minX = std::min(minX, x), maxX = std::max(maxX, x);
		for (double y : {ly[i], iy[i]}) minY = std::min(minY, y), maxY = std::max(maxY, y);
	}
	// Two pixels of margin for the bilinear lookups.
	m_cxLevel = -minX + 2;
	m_cyLevel = -minY + 2;
	m_wLevel = static_cast<int>(std::ceil(maxX - minX)) + 5;
	m_hLevel = static_cast<int>(std::ceil(maxY - minY)) + 5;
	if (m_wLevel > 6 * W || m_hLevel > 6 * H)
		throw ConfigError(
			"[StereoCamera] pose/distortion: the image sees too wide a field through this "
			"lens and rotation to render (check the distortion coefficients)");
	m_mapX.create(H, W, CV_32F);
	m_mapY.create(H, W, CV_32F);
	m_idealX.create(H, W, CV_32F);
	m_idealY.create(H, W, CV_32F);
	m_idealDepthScale.create(H, W, CV_32F);
	for (int v = 0, i = 0; v < H; v++)
		for (int u = 0; u < W; u++, i++)
		{
			const auto k = static_cast<size_t>(i);
			m_mapX.at<float>(v, u) = static_cast<float>(lx[k] + m_cxLevel);
			m_mapY.at<float>(v, u) = static_cast<float>(ly[k] + m_cyLevel);
			m_idealX.at<float>(v, u) = static_cast<float>(ix[k] + m_cxLevel);
			m_idealY.at<float>(v, u) = static_cast<float>(iy[k] + m_cyLevel);
			m_idealDepthScale.at<float>(v, u) = static_cast<float>(iz[k]);
		}
}

StereoRenderer::~StereoRenderer() = default;

mrpt::poses::CPose3D StereoRenderer::leftCameraPose(const mrpt::poses::CPose2D& robot) const
{
	return mrpt::poses::CPose3D(robot) + m_cam.leftCameraOnRobot();
}

void StereoRenderer::renderLevel(
	const mrpt::poses::CPose3D& cameraPose, double t, cv::Mat& intensity, cv::Mat& depth) const
{
	const double psi = headingOf(cameraPose);
	const double ox = cameraPose.x(), oy = cameraPose.y(), oz = cameraPose.z();
	const double fwdX = std::cos(psi), fwdY = std::sin(psi);
	const double rightX = std::sin(psi), rightY = -std::cos(psi);
	const double fx = m_cam.fx, fy = m_cam.fy, ceilingZ = m_cam.ceiling_height;
	const int W = m_wLevel, H = m_hLevel;

	std::vector<CircleShape> circles;
	m_world.cameraCirclesAt(t, circles);
	std::vector<const SurfaceMaterial*> circleMaterials;
	std::vector<std::shared_ptr<const SurfaceMaterial>> keepAlive;
	for (const auto& c : circles)
	{
		keepAlive.push_back(SurfaceMaterial::byName(c.texture));
		circleMaterials.push_back(keepAlive.back().get());
	}

	// The floor and the ceiling, one sample per pixel, row by row: along a
	// row of a level camera their depth is constant and the surface point
	// moves linearly, so texel coordinates are stepped, not recomputed.
	// Walls are drawn over them below.
	cv::Mat& background = m_ws.background;
	background.create(H, W, CV_32F);
	std::vector<double> rowDepth(static_cast<size_t>(H));
	for (int r = 0; r < H; r++)
	{
		const double yn = (r - m_cyLevel) / fy;
		const bool floor = yn > 0;
		const double h = floor ? oz : ceilingZ - oz;
		const double d = std::min(std::abs(yn) > 1e-9 ? h / std::abs(yn) : 1e4, 1e4);
		rowDepth[static_cast<size_t>(r)] = d;
		// Grazing view: one pixel spans d/f across and d^2/(f h) along.
		const double across = d / fy, along = across * d / std::max(h, 1e-3);
		const Sampler smp(floor ? *m_floor : *m_ceiling, std::sqrt(across * std::min(along, 8 * across)));
		const double xn0 = (0 - m_cxLevel) / fx;
		auto fixed = [](double texel) { return static_cast<int64_t>(std::llround(texel * 65536.0)); };
		int64_t X = fixed(smp.texelU(ox + d * (fwdX + xn0 * rightX)));
		int64_t Y = fixed(smp.texelU(oy + d * (fwdY + xn0 * rightY)));
		const int64_t stepX = fixed(d / fx * rightX * smp.invTexel);
		const int64_t stepY = fixed(d / fx * rightY * smp.invTexel);
		float* out = background.ptr<float>(r);
		for (int u = 0; u < W; u++, X += stepX, Y += stepY) out[u] = smp.atFixed(X, Y);
	}
	cv::Mat& backgroundT = m_ws.backgroundT;
	cv::transpose(background, backgroundT);

	// Columns are rendered transposed (one image column per matrix row:
	// contiguous writes). castRay fills one column for a ray through
	// horizontal pixel position uPix and returns a signature of what it
	// met (objects, and which patches cover the hit points).
	std::vector<Span> spans;
	std::vector<std::pair<double, int>> solidHits;	// (depth, segment)
	std::vector<char> filled(static_cast<size_t>(H));
	const auto& segs = m_world.segments();

	auto castRay = [&](double uPix, const float* bg, float* I, float* D) -> uint64_t {
		const double xn = (uPix - m_cxLevel) / fx;
		const double dx = fwdX + xn * rightX, dy = fwdY + xn * rightY;
		const double dirNorm = std::hypot(dx, dy);
		spans.clear();
		solidHits.clear();
		auto faceRows = [&](Span& s, double bottom, double top) {
			s.rowA = m_cyLevel + fy * (oz - top) / s.tNear;
			s.rowB = m_cyLevel + fy * (oz - bottom) / s.tNear;
		};
		// The top at height `top` seen between entry tNear and exit tFar.
		auto addCap = [&](double top, double tNear, double tFar, const SurfaceMaterial* m) {
			Span s;
			s.cap = true;
			s.tNear = tNear;
			s.tFar = tFar;
			s.top = top;
			s.material = m;
			s.rowA = m_cyLevel + fy * (oz - top) / tFar;
			s.rowB = m_cyLevel + fy * (oz - top) / tNear;
			spans.push_back(s);
		};
		for (size_t i = 0; i < segs.size(); i++)
		{
			const auto& sg = segs[i];
			const double ex = sg.b.x - sg.a.x, ey = sg.b.y - sg.a.y;
			const double den = dx * ey - dy * ex;
			if (std::abs(den) < 1e-12) continue;
			const double wx = sg.a.x - ox, wy = sg.a.y - oy;
			const double tHit = (wx * ey - wy * ex) / den;
			const double lambda = (wx * dy - wy * dx) / den;
			if (tHit <= 1e-4 || lambda < 0 || lambda > 1) continue;
			const double len = std::hypot(ex, ey);
			Span s;
			s.tNear = s.tFar = tHit;
			s.segment = static_cast<int>(i);
			s.u = sg.sStart + lambda * len;
			s.footprint = faceFootprint(tHit, fx, std::abs(den) / (dirNorm * len));
			s.material = m_segmentMaterials[i].get();
			faceRows(s, sg.bottom, sg.top);
			spans.push_back(s);
			if (sg.solid) solidHits.emplace_back(tHit, static_cast<int>(i));
		}
		// Tops of solid obstacles below the camera: between the ray's entry
		// into the outline and its exit.
		if (!solidHits.empty())
		{
			std::sort(solidHits.begin(), solidHits.end());
			for (size_t a = 0; a < solidHits.size(); a++)
			{
				const auto& sa = segs[static_cast<size_t>(solidHits[a].second)];
				if (sa.top >= oz) continue;
				for (size_t b = a + 1; b < solidHits.size(); b++)
				{
					const auto& sb = segs[static_cast<size_t>(solidHits[b].second)];
					if (sb.object != sa.object) continue;
					addCap(
						sa.top, solidHits[a].first, solidHits[b].first,
						m_segmentMaterials[static_cast<size_t>(solidHits[a].second)].get());
					a = b;	// the exit is not an entry
					break;
				}
			}
		}
		for (size_t i = 0; i < circles.size(); i++)
		{
			const auto& c = circles[i];
			const double px = ox - c.centre.x, py = oy - c.centre.y;
			const double A = dx * dx + dy * dy, B = dx * px + dy * py,
						 C = px * px + py * py - c.radius * c.radius;
			const double disc = B * B - A * C;
			if (C <= 0 || disc <= 0) continue;
			const double sq = std::sqrt(disc);
			const double t1 = (-B - sq) / A, t2 = (-B + sq) / A;
			if (t1 <= 1e-4) continue;
			const double hx = ox + t1 * dx - c.centre.x, hy = oy + t1 * dy - c.centre.y;
			Span s;
			s.tNear = s.tFar = t1;
			s.u = std::atan2(hy, hx) * c.radius;
			s.footprint = faceFootprint(t1, fx, std::abs(hx * dx + hy * dy) / (c.radius * dirNorm));
			s.material = circleMaterials[i];
			faceRows(s, c.bottom, c.top);
			spans.push_back(s);
			if (c.top < oz) addCap(c.top, t1, t2, circleMaterials[i]);
		}
		std::sort(spans.begin(), spans.end(), [](const Span& a, const Span& b) {
			return a.tNear < b.tNear;
		});

		uint64_t signature = 1469598103934665603ull;
		auto mix = [&signature](uint64_t v) { signature = (signature ^ v) * 1099511628211ull; };
		std::fill(filled.begin(), filled.end(), 0);
		for (const Span& s : spans)
		{
			const int r0 = std::max(0, static_cast<int>(std::ceil(s.rowA)));
			const int r1 = std::min(H - 1, static_cast<int>(std::floor(s.rowB)));
			if (r0 > r1) continue;
			if (s.cap)
			{
				for (int r = r0; r <= r1; r++)
				{
					if (filled[static_cast<size_t>(r)]) continue;
					const double yn = (r - m_cyLevel) / fy;
					if (yn <= 0) continue;
					const double tc = (oz - s.top) / yn;
					Sampler smp(*s.material, tc / fy);
					I[r] = smp.at(ox + tc * dx, oy + tc * dy);
					D[r] = static_cast<float>(tc);
					filled[static_cast<size_t>(r)] = 1;
				}
				continue;
			}
			// A face: the base material, or the last patch covering (s, z).
			Sampler base(*s.material, s.footprint);
			base.setU(s.u);
			struct PatchHere
			{
				double z0, z1;
				Sampler smp;
			};
			PatchHere here[8];
			int nHere = 0;
			mix(static_cast<uint64_t>(s.segment + 2) * 2 + (s.material != nullptr));
			mix(reinterpret_cast<uintptr_t>(s.material));
			if (s.segment >= 0)
			{
				const auto& patches = segs[static_cast<size_t>(s.segment)].patches;
				const auto& mats = m_patchMaterials[static_cast<size_t>(s.segment)];
				for (size_t p = patches.size(); p-- > 0 && nHere < 8;)
					if (s.u >= patches[p].s0 && s.u < patches[p].s1)
					{
						mix(p + 7);
						here[nHere] = {patches[p].z0, patches[p].z1, Sampler(*mats[p], s.footprint)};
						here[nHere++].smp.setU(s.u);
					}
			}
			const float depthF = static_cast<float>(s.tNear);
			for (int r = r0; r <= r1; r++)
			{
				if (filled[static_cast<size_t>(r)]) continue;
				const double z = oz - s.tNear * (r - m_cyLevel) / fy;
				const Sampler* smp = &base;
				for (int p = 0; p < nHere; p++)
					if (z >= here[p].z0 && z < here[p].z1)
					{
						smp = &here[p].smp;
						break;
					}
				I[r] = smp->atV(z);
				D[r] = depthF;
				filled[static_cast<size_t>(r)] = 1;
			}
		}
		for (int r = 0; r < H; r++)
		{
			if (filled[static_cast<size_t>(r)]) continue;
			I[r] = bg[r];
			D[r] = static_cast<float>(rowDepth[static_cast<size_t>(r)]);
		}
		return signature;
	};

	// One ray per pixel centre; then every column whose neighbour met
	// something else (an object's end, a patch's side, a person's
	// silhouette) is rendered again as the mean of 4 rays across the pixel,
	// which places those vertical edges to 1/4 pixel. A pixel whose rays
	// hit surfaces at different depths has no single depth (0 there).
	cv::Mat& colI = m_ws.colI;
	cv::Mat& colD = m_ws.colD;
	colI.create(W, H, CV_32F);
	colD.create(W, H, CV_32F);
	std::vector<uint64_t> signature(static_cast<size_t>(W));
	for (int u = 0; u < W; u++)
		signature[static_cast<size_t>(u)] =
			castRay(u, backgroundT.ptr<float>(u), colI.ptr<float>(u), colD.ptr<float>(u));
	constexpr int kRays = 4;
	std::vector<float> rayI(static_cast<size_t>(H)), rayD(static_cast<size_t>(H)),
		lo(static_cast<size_t>(H)), hi(static_cast<size_t>(H));
	for (int u = 0; u < W; u++)
	{
		const auto sig = signature[static_cast<size_t>(u)];
		const bool edge = (u > 0 && signature[static_cast<size_t>(u - 1)] != sig) ||
			(u + 1 < W && signature[static_cast<size_t>(u + 1)] != sig);
		if (!edge) continue;
		float* I = colI.ptr<float>(u);
		float* D = colD.ptr<float>(u);
		std::fill(I, I + H, 0.0f);
		std::fill(lo.begin(), lo.end(), 1e30f);
		std::fill(hi.begin(), hi.end(), 0.0f);
		for (int k = 0; k < kRays; k++)
		{
			castRay(u - 0.5 + (k + 0.5) / kRays, backgroundT.ptr<float>(u), rayI.data(), rayD.data());
			for (int r = 0; r < H; r++)
			{
				I[r] += rayI[static_cast<size_t>(r)] * (1.0f / kRays);
				lo[static_cast<size_t>(r)] = std::min(lo[static_cast<size_t>(r)], rayD[static_cast<size_t>(r)]);
				hi[static_cast<size_t>(r)] = std::max(hi[static_cast<size_t>(r)], rayD[static_cast<size_t>(r)]);
			}
		}
		for (int r = 0; r < H; r++)
		{
			const float l = lo[static_cast<size_t>(r)], h = hi[static_cast<size_t>(r)];
			D[r] = h - l <= 0.01f * h ? 0.5f * (l + h) : 0.0f;
		}
	}

	cv::transpose(colI, intensity);
	cv::transpose(colD, depth);
}

void StereoRenderer::toCamera(
	const cv::Mat& levelIntensity, const cv::Mat& levelDepth, cv::Mat* intensity,
	cv::Mat* idealDepth) const
{
	if (!m_warp)
	{
		if (intensity) *intensity = levelIntensity;
		if (idealDepth) *idealDepth = levelDepth;
		return;
	}
	if (intensity)
		cv::remap(levelIntensity, *intensity, m_mapX, m_mapY, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
	if (idealDepth)
	{
		cv::remap(levelDepth, *idealDepth, m_idealX, m_idealY, cv::INTER_NEAREST, cv::BORDER_REPLICATE);
		// Depth along the real optical axis (Z_real = Z_level / d_z).
		cv::multiply(*idealDepth, m_idealDepthScale, *idealDepth);
	}
}

void StereoRenderer::renderIdeal(
	const mrpt::poses::CPose3D& leftCamera, double t, cv::Mat& left, cv::Mat& right,
	cv::Mat& leftDepth, cv::Mat& rightDepth) const
{
	const mrpt::poses::CPose3D rightCamera =
		leftCamera + mrpt::poses::CPose3D(m_cam.baseline, 0, 0, 0, 0, 0);
	if (!m_warp)
	{
		renderLevel(leftCamera, t, left, leftDepth);
		renderLevel(rightCamera, t, right, rightDepth);
		return;
	}
	cv::Mat &li = m_ws.levelI[0], &ld = m_ws.levelD[0], &ri = m_ws.levelI[1], &rd = m_ws.levelD[1];
	renderLevel(leftCamera, t, li, ld);
	renderLevel(rightCamera, t, ri, rd);
	toCamera(li, ld, &left, &leftDepth);
	toCamera(ri, rd, &right, &rightDepth);
}

void StereoRenderer::render(
	const mrpt::poses::CPose2D& robot, double t, cv::RNG& rng, StereoFrame& f) const
{
	f.leftCamera = leftCameraPose(robot);
	cv::Mat &left = m_ws.ideal[0], &right = m_ws.ideal[1];
	renderIdeal(f.leftCamera, t, left, right, f.depth, f.rightDepth);
	f.disparity.create(f.depth.size(), CV_32F);
	const double fb = m_cam.fx * m_cam.baseline;
	for (int v = 0; v < f.depth.rows; v++)
	{
		const float* z = f.depth.ptr<float>(v);
		float* d = f.disparity.ptr<float>(v);
		for (int u = 0; u < f.depth.cols; u++)
			d[u] = z[u] > 0 ? static_cast<float>(fb / z[u]) : 0.0f;
	}
	const std::vector<float>& quantile = normalQuantiles();
	for (auto [img, out] : {std::pair{&left, &f.left}, std::pair{&right, &f.right}})
	{
		cv::Mat x = *img;
		if (m_cam.blur_sigma > 0)
			cv::GaussianBlur(x, x, cv::Size(0, 0), m_cam.blur_sigma, m_cam.blur_sigma, cv::BORDER_REPLICATE);
		const float gain = static_cast<float>(1 + m_cam.gain_change * rng.gaussian(1.0));
		const float sigma = static_cast<float>(m_cam.noise_sigma);
		out->create(x.size(), CV_8U);	// reused when the size matches
		// x * gain + N(0, sigma^2), rounded and saturated to 8 bits; two
		// 16-bit draws per 32-bit random number.
		for (int v = 0; v < x.rows; v++)
		{
			const float* in = x.ptr<float>(v);
			uchar* o = out->ptr<uchar>(v);
			for (int u = 0; u < x.cols; u += 2)
			{
				const unsigned bits = rng.next();
				o[u] = cv::saturate_cast<uchar>(in[u] * gain + sigma * quantile[bits & 0xffff]);
				if (u + 1 < x.cols)
					o[u + 1] = cv::saturate_cast<uchar>(in[u + 1] * gain + sigma * quantile[bits >> 16]);
			}
		}
	}
}
}  // namespace featloc
