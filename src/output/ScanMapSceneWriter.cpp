#include "featloc/output/ScanMapSceneWriter.h"
#include "featloc/core/WholeFile.h"

#include <mrpt/opengl/CEllipsoid2D.h>
#include <mrpt/opengl/CGridPlaneXY.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CPointCloud.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/stock_objects.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "featloc/output/ThreeSigmaEllipse.h"
#include "featloc/scan/ScanPoints.h"

namespace featloc
{
namespace
{
// 0.03 m up: above the scans and the path.
std::shared_ptr<mrpt::opengl::CEllipsoid2D> ellipse(
	const Eigen::Vector2d& mean, const Eigen::Matrix2d& cov)
{
	return threeSigmaEllipse(
		mean.x(), mean.y(), cov(0, 0), 0.5 * (cov(0, 1) + cov(1, 0)), cov(1, 1), 0.03);
}
}  // namespace

ScanMapSceneWriter::ScanMapSceneWriter(std::string path, unsigned int scanDecimation,
	double pointResolution, unsigned int ellipseEvery, std::vector<mrpt::math::TPoint2D> map)
	: m_path(std::move(path)),
	  m_decimation(std::max(1u, scanDecimation)),
	  m_pointResolution(pointResolution),
	  m_ellipseEvery(ellipseEvery),
	  m_map(std::move(map))
{
}

void ScanMapSceneWriter::onStep(const StepRecord& r)
{
	const mrpt::poses::CPose2D robot = r.pose.mean;
	m_path3d.push_back(mrpt::poses::CPose3D(robot).asTPose());
	if (r.landmarks) m_landmarks = *r.landmarks;
	if (m_ellipseEvery > 0 && r.step.index % m_ellipseEvery == 0)
	{
		Eigen::Matrix2d c;
		c << r.pose.cov(0, 0), r.pose.cov(0, 1), r.pose.cov(1, 0), r.pose.cov(1, 1);
		m_robotEllipses.emplace_back(Eigen::Vector2d(robot.x(), robot.y()), c);
	}
	if (!r.step.scan || r.step.scanIndex % m_decimation != 0) return;
	// Points in the sensor frame -> robot frame (sensorPose) -> world.
	const mrpt::poses::CPose2D sensor =
		robot + mrpt::poses::CPose2D(r.step.scan->sensorPose);
	const double c = std::cos(sensor.phi()), s = std::sin(sensor.phi());
	for (const auto& p : ScanPoints::fromScan(*r.step.scan).points)
	{
		const double x = sensor.x() + c * p.x - s * p.y, y = sensor.y() + s * p.x + c * p.y;
		if (m_pointResolution > 0)
		{
			// A robot that comes back sees the same walls again: one point
			// per cell is what a picture of them needs.
			const auto cx = static_cast<uint32_t>(static_cast<int32_t>(std::floor(x / m_pointResolution)));
			const auto cy = static_cast<uint32_t>(static_cast<int32_t>(std::floor(y / m_pointResolution)));
			if (!m_cells.insert((uint64_t(cx) << 32) | cy).second) continue;
		}
		m_x.push_back(static_cast<float>(x));
		m_y.push_back(static_cast<float>(y));
		m_z.push_back(0.0f);
	}
}

void ScanMapSceneWriter::finish(const RunStats&)
{
	mrpt::opengl::COpenGLScene scene;

	float minX = -5, maxX = 5, minY = -5, maxY = 5;
	for (size_t i = 0; i < m_x.size(); i++)
	{
		minX = std::min(minX, m_x[i]);
		maxX = std::max(maxX, m_x[i]);
		minY = std::min(minY, m_y[i]);
		maxY = std::max(maxY, m_y[i]);
	}
	auto grid = mrpt::opengl::CGridPlaneXY::Create(
		std::floor(minX), std::ceil(maxX), std::floor(minY), std::ceil(maxY),
		-0.01, 1.0);
	grid->setColor(0.7f, 0.7f, 0.7f, 0.5f);
	scene.insert(grid);

	auto cloud = mrpt::opengl::CPointCloud::Create();
	// Not setAllPointsFast(): in MRPT 2.5.8 it takes the points mutex and
	// then calls clear(), which takes it again (std::system_error EDEADLK).
	cloud->setAllPoints(m_x, m_y, m_z);
	cloud->setColor(0.1f, 0.1f, 0.1f);
	cloud->setPointSize(2.0f);
	scene.insert(cloud);
	if (!m_map.empty())
	{
		std::vector<float> mx, my, mz;
		for (const auto& p : m_map)
		{
			mx.push_back(static_cast<float>(p.x));
			my.push_back(static_cast<float>(p.y));
			mz.push_back(-0.005f);	// under the scans
		}
		auto map = mrpt::opengl::CPointCloud::Create();
		map->setAllPoints(mx, my, mz);
		map->setColor(0.65f, 0.65f, 0.65f);
		map->setPointSize(2.0f);
		map->setName("map");
		scene.insert(map);
	}

	auto path = mrpt::opengl::CSetOfLines::Create();
	path->setColor(0.0f, 0.3f, 1.0f);
	path->setLineWidth(2.0f);
	for (size_t i = 1; i < m_path3d.size(); i++)
		path->appendLine(
			m_path3d[i - 1].x, m_path3d[i - 1].y, 0.02, m_path3d[i].x,
			m_path3d[i].y, 0.02);
	scene.insert(path);

	for (const auto& [mean, cov] : m_robotEllipses)
	{
		auto e = ellipse(mean, cov);
		e->setColor(0.0f, 0.3f, 1.0f, 0.8f);
		scene.insert(e);
	}
	if (!m_landmarks.empty())
	{
		auto points = mrpt::opengl::CPointCloud::Create();
		points->setColor(0.9f, 0.1f, 0.1f);
		points->setPointSize(6.0f);
		// Vertical-line landmarks (Moon et al.) as their segments, from
		// l_low to l_high above their foot.
		auto vertical = mrpt::opengl::CSetOfLines::Create();
		vertical->setColor(0.1f, 0.7f, 0.1f);
		vertical->setLineWidth(3.0f);
		for (const auto& l : m_landmarks)
		{
			if (l.vertical)
				vertical->appendLine(l.mean.x(), l.mean.y(), l.lLow, l.mean.x(), l.mean.y(), l.lHigh);
			points->insertPoint(
				static_cast<float>(l.mean.x()), static_cast<float>(l.mean.y()), 0.03f);
			auto e = ellipse(l.mean, l.covariance);
			e->setColor(0.9f, 0.1f, 0.1f, 0.8f);
			scene.insert(e);
		}
		scene.insert(points);
		if (vertical->size() > 0) scene.insert(vertical);
	}

	if (!m_path3d.empty())
	{
		auto robot = mrpt::opengl::stock_objects::CornerXYZSimple(0.5f, 2.0f);
		robot->setPose(mrpt::poses::CPose3D(m_path3d.back()));
		scene.insert(robot);
	}
	writeWholeFile(m_path, [&](const std::string& file) {
		if (!scene.saveToFile(file)) throw std::runtime_error("cannot write '" + m_path + "'");
	});
}
}  // namespace featloc
