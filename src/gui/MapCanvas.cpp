#include "featloc/gui/MapCanvas.h"

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/opengl/CEllipsoid2D.h>
#include <mrpt/opengl/CPointCloud.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_set>

#include "featloc/output/ThreeSigmaEllipse.h"
#include "featloc/scan/ScanPoints.h"

namespace featloc
{
namespace
{
template <typename T>
void colour(T& obj, const unsigned char (&rgb)[3])
{
	obj.setColor_u8(rgb[0], rgb[1], rgb[2]);
}

// (CPointCloud::setAllPointsFast() locks its mutex twice in MRPT 2.5.8:
// "resource deadlock avoided".)
mrpt::opengl::CPointCloud::Ptr cloud(
	const std::vector<mrpt::math::TPoint3Df>& pts, const unsigned char (&rgb)[3], float size)
{
	auto c = mrpt::opengl::CPointCloud::Create();
	c->resize(pts.size());
	for (size_t i = 0; i < pts.size(); i++) c->setPoint_fast(i, pts[i].x, pts[i].y, pts[i].z);
	colour(*c, rgb);
	c->setPointSize(size);
	return c;
}

// The map's scans are drawn one point per cell: a robot sees the same
// walls again and again, so a long log's millions of points shrink to what
// the walls are. Cells of 2, 4, 8 and 16 cm; each redraw uses the finest
// whose cells are at least kPixelsPerCell pixels (OnPreRender), so the
// points drawn follow the walls' extent, not the number of scans.
constexpr double kMapCellSize = 0.02;  // [m]
constexpr float kPixelsPerCell = 2;

std::vector<mrpt::math::TPoint3Df> onePerCell(
	const std::vector<mrpt::math::TPoint3Df>& pts, double cell)
{
	std::unordered_set<uint64_t> seen;
	seen.reserve(pts.size() / 4);
	std::vector<mrpt::math::TPoint3Df> out;
	for (const auto& p : pts)
	{
		const auto ix = static_cast<int32_t>(std::floor(p.x / cell));
		const auto iy = static_cast<int32_t>(std::floor(p.y / cell));
		const uint64_t key = (static_cast<uint64_t>(static_cast<uint32_t>(ix)) << 32) |
			static_cast<uint32_t>(iy);
		if (seen.insert(key).second) out.push_back(p);
	}
	return out;
}

// Heights above the scans (z = 0) that keep what matters on top (the
// camera looks down; equal depths would hide the later object).
constexpr double kGroundTruthZ = 0.015, kTrajectoryZ = 0.02;

mrpt::opengl::CSetOfLines::Ptr polyline(const std::vector<mrpt::math::TPose2D>& poses,
	const unsigned char (&rgb)[3], float width, double z)
{
	auto lines = mrpt::opengl::CSetOfLines::Create();
	for (size_t i = 1; i < poses.size(); i++)
		lines->appendLine(poses[i - 1].x, poses[i - 1].y, z, poses[i].x, poses[i].y, z);
	colour(*lines, rgb);
	lines->setLineWidth(width);
	lines->enableAntiAliasing(false);  // exact colours, for the eye and the tests
	return lines;
}

mrpt::opengl::CEllipsoid2D::Ptr ellipse(
	double x, double y, double cxx, double cxy, double cyy, const unsigned char (&rgb)[3])
{
	auto e = threeSigmaEllipse(x, y, cxx, cxy, cyy, 0.025);
	colour(*e, rgb);
	e->setLineWidth(2);
	return e;
}
}  // namespace

MapCanvas::MapCanvas(wxWindow* parent) : CWxGLCanvasBase(parent)
{
	// A map is looked at from above: dragging pans instead of orbiting.
	Unbind(wxEVT_MOTION, &CWxGLCanvasBase::OnMouseMove, static_cast<CWxGLCanvasBase*>(this));
	Bind(wxEVT_MOTION, &MapCanvas::onMouseMove, this);
	setCameraProjective(false);
	setElevationDegrees(90);
	setAzimuthDegrees(-90);
	setMinimumZoom(0.05f);
	setMaximumZoom(1e5f);
}

void MapCanvas::onMouseMove(wxMouseEvent& event)
{
	const int x = event.GetX(), y = event.GetY();
	updateLastPos(x, y);
	if (event.LeftIsDown() || event.RightIsDown())
	{
		CamaraParams params = cameraParams();
		updatePan(params, x, y);
		setMousePos(x, y);
		setCameraParams(params);
		Refresh(false);
	}
}

void MapCanvas::OnPreRender()
{
	if (m_levels.empty()) return;
	int w = 0, h = 0;
	GetClientSize(&w, &h);
	// MRPT's orthographic view spans zoom/2 over the window's smaller side.
	const double metresPerPixel = 0.5 * getZoomDistance() / std::max(1, std::min(w, h));
	// The finest level whose cells are at least kPixelsPerCell pixels (its
	// points are drawn that big): finer ones would only put more points in
	// the same pixels, at a cost that grows with the log's length.
	size_t use = 0;
	while (use + 1 < m_levels.size() && m_levels[use].first < kPixelsPerCell * metresPerPixel)
		use++;
	for (size_t i = 0; i < m_levels.size(); i++)
		if (m_levels[i].second->isVisible() != (i == use))  // a change costs an upload
			m_levels[i].second->setVisibility(i == use);
}

void MapCanvas::placeScan(
	size_t step, float z, std::vector<mrpt::math::TPoint3Df>& points) const
{
	const auto& s = m_results->steps[step];
	if (!s.scan) return;
	const mrpt::poses::CPose3D robot(mrpt::poses::CPose2D(s.pose));
	const mrpt::poses::CPose3D sensor = robot + s.scan->sensorPose;
	for (const ScanPoint& p : ScanPoints::fromScan(*s.scan).points)
	{
		double x, y, unusedZ;
		sensor.composePoint(p.x, p.y, 0, x, y, unusedZ);
		points.emplace_back(static_cast<float>(x), static_cast<float>(y), z);
	}
}

void MapCanvas::setResults(const RunResults& results)
{
	m_results = &results;
	auto scene = getOpenGLSceneRef();
	scene->clear();
	scene->getViewport()->setCustomBackgroundColor({1.f, 1.f, 1.f});

	std::vector<mrpt::math::TPoint3Df> all;
	for (size_t i = 0; i < results.steps.size(); i++) placeScan(i, 0.f, all);
	m_levels.clear();
	for (double cell = kMapCellSize; cell <= 8 * kMapCellSize; cell *= 2)
	{
		m_levels.emplace_back(cell, cloud(onePerCell(all, cell), kScans, kPixelsPerCell));
		scene->insert(m_levels.back().second);
	}

	// A known map (localization in a map), under the scans.
	if (!results.mapCells.empty())
	{
		std::vector<mrpt::math::TPoint3Df> cells;
		for (const auto& c : results.mapCells)
			cells.emplace_back(static_cast<float>(c.x), static_cast<float>(c.y), -0.005f);
		scene->insert(cloud(cells, kKnownMap, kPixelsPerCell));
	}

	std::vector<mrpt::math::TPose2D> est, gt;
	for (const auto& s : results.steps) est.push_back(s.pose);
	if (results.groundTruth)
		for (const auto& p : results.groundTruth->poses)
			gt.push_back((mrpt::poses::CPose2D(results.groundTruthToEstimate) + mrpt::poses::CPose2D(p.pose)).asTPose());
	// The robot's 3-sigma ellipse along the path, about 100 of them (the
	// current step's is drawn stronger by setStep).
	const size_t every = std::max<size_t>(1, results.steps.size() / 100);
	for (size_t i = 0; i < results.steps.size(); i += every)
	{
		const auto& st = results.steps[i];
		if (st.cov(0, 0) <= 0 || st.cov(1, 1) <= 0) continue;
		scene->insert(ellipse(st.pose.x, st.pose.y, st.cov(0, 0), st.cov(0, 1), st.cov(1, 1),
			kPathEllipses));
	}
	scene->insert(polyline(gt, kGroundTruth, 2.f, kGroundTruthZ));
	scene->insert(polyline(est, kTrajectory, 2.f, kTrajectoryZ));
	// Landmarks: a cross 0.2 m wide (seen at any zoom) and the 3-sigma
	// ellipse (often smaller than a pixel on a whole-map view).
	auto crosses = mrpt::opengl::CSetOfLines::Create();
	for (const auto& l : results.landmarks)
	{
		scene->insert(ellipse(l.x, l.y, l.cxx, l.cxy, l.cyy, kLandmarks));
		crosses->appendLine(l.x - 0.1, l.y, 0.02, l.x + 0.1, l.y, 0.02);
		crosses->appendLine(l.x, l.y - 0.1, 0.02, l.x, l.y + 0.1, 0.02);
	}
	colour(*crosses, kLandmarks);
	crosses->enableAntiAliasing(false);
	scene->insert(crosses);

	m_robot = mrpt::opengl::CSetOfLines::Create();
	m_robot->setLineWidth(2.f);
	m_robot->setColor_u8(0, 0, 0);
	m_robotEllipse = ellipse(0, 0, 1e-6, 0, 1e-6, {240, 140, 0});
	scene->insert(m_robotEllipse);
	scene->insert(m_robot);

	// What fitAll shows: the paths whole, and the scans without the 1% of
	// their points furthest out on each side (stray long ranges).
	std::vector<double> xs, ys;
	const size_t step = std::max<size_t>(1, all.size() / 20000);
	for (size_t k = 0; k < all.size(); k += step) xs.push_back(all[k].x), ys.push_back(all[k].y);
	auto range = [](std::vector<double>& v, double& lo, double& hi) {
		lo = 1e300, hi = -1e300;
		if (v.empty()) return;
		std::sort(v.begin(), v.end());
		lo = v[v.size() / 100];
		hi = v[v.size() - 1 - v.size() / 100];
	};
	range(xs, m_minX, m_maxX);
	range(ys, m_minY, m_maxY);
	for (const auto* path : {&est, &gt})
		for (const auto& p : *path)
		{
			m_minX = std::min(m_minX, p.x), m_maxX = std::max(m_maxX, p.x);
			m_minY = std::min(m_minY, p.y), m_maxY = std::max(m_maxY, p.y);
		}
	fitAll();
	setStep(0);
}

void MapCanvas::setStep(size_t i)
{
	if (!m_results || i >= m_results->steps.size()) return;
	const auto& s = m_results->steps[i];
	// Above the other scans (z), so that the depth test keeps them on top.
	std::vector<mrpt::math::TPoint3Df> current, reference;
	placeScan(i, 0.01f, current);
	if (s.reference >= 0) placeScan(static_cast<size_t>(s.reference), 0.005f, reference);
	// New clouds rather than changed ones: MRPT 2.5.8 does not redraw a
	// CPointCloud whose points change after it was inserted.
	auto scene = getOpenGLSceneRef();
	scene->removeObject(m_current);
	scene->removeObject(m_reference);
	m_current = cloud(current, kCurrentScan, 3.f);
	m_reference = cloud(reference, kReferenceScan, 3.f);
	scene->insert(m_reference);
	scene->insert(m_current);
	// The robot: a triangle pointing along its heading, 0.3 m long.
	const mrpt::poses::CPose2D p(s.pose);
	const double tri[3][2] = {{0.3, 0}, {-0.1, 0.1}, {-0.1, -0.1}};
	m_robot->clear();
	for (int k = 0; k < 3; k++)
	{
		double ax, ay, bx, by;
		p.composePoint(tri[k][0], tri[k][1], ax, ay);
		p.composePoint(tri[(k + 1) % 3][0], tri[(k + 1) % 3][1], bx, by);
		m_robot->appendLine(ax, ay, 0.03, bx, by, 0.03);
	}
	mrpt::math::CMatrixDouble22 c = s.cov.blockCopy<2, 2>(0, 0);
	if (c(0, 0) <= 0 || c(1, 1) <= 0) c(0, 0) = c(1, 1) = 1e-10;
	m_robotEllipse->setCovMatrixAndMean(c, mrpt::math::CVectorFixedDouble<2>({p.x(), p.y()}));
	Refresh(false);
}

void MapCanvas::fitAll()
{
	int w = 0, h = 0;
	GetClientSize(&w, &h);
	const double ratio = h > 0 ? static_cast<double>(w) / h : 1.0;
	const double hx = 0.55 * std::max(m_maxX - m_minX, 1.0);
	const double hy = 0.55 * std::max(m_maxY - m_minY, 1.0);
	// MRPT's orthographic camera shows a half-height of zoom/4 (half-width
	// when the window is taller than wide), TRenderMatrices.
	const double zoom = 4 * (ratio >= 1 ? std::max(hy, hx / ratio) : std::max(hx, hy * ratio));
	setCameraPointing(static_cast<float>(0.5 * (m_minX + m_maxX)),
		static_cast<float>(0.5 * (m_minY + m_maxY)), 0.f);
	setZoomDistance(static_cast<float>(zoom));
	Refresh(false);
}
}  // namespace featloc
