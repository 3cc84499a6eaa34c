#include "featloc/ekf/LandmarkObservation.h"

#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/poses/CPose2D.h>

#include <Eigen/Dense>
#include <cmath>

namespace featloc
{
std::vector<LandmarkObservation> LandmarkObservation::fromBearingRange(
	const mrpt::obs::CObservationBearingRange& obs)
{
	std::vector<LandmarkObservation> out;
	const mrpt::poses::CPose2D sensor(obs.sensorLocationOnRobot);
	const double cs = std::cos(sensor.phi()), ss = std::sin(sensor.phi());
	Eigen::Matrix2d Rs;
	Rs << cs, -ss, ss, cs;
	for (const auto& m : obs.sensedData)
	{
		const double r = m.range, b = m.yaw, c = std::cos(b), s = std::sin(b);
		Eigen::Matrix2d polar;	// covariance of (range, bearing)
		if (obs.validCovariances)
			polar << m.covariance(0, 0), m.covariance(0, 1), m.covariance(1, 0), m.covariance(1, 1);
		else
			polar << obs.sensor_std_range * obs.sensor_std_range, 0, 0,
				obs.sensor_std_yaw * obs.sensor_std_yaw;
		// (x, y) = r (cos b, sin b): d(x, y)/d(r, b).
		Eigen::Matrix2d J;
		J << c, -r * s, s, r * c;
		LandmarkObservation o;
		o.position = Eigen::Vector2d(sensor.x(), sensor.y()) + Rs * Eigen::Vector2d(r * c, r * s);
		o.covariance = Rs * J * polar * J.transpose() * Rs.transpose();
		o.id = m.landmarkID >= 0 ? m.landmarkID : -1;
		out.push_back(o);
	}
	return out;
}
}  // namespace featloc
