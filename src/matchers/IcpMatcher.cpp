#include "featloc/matchers/IcpMatcher.h"

#include <mrpt/maps/CSimplePointsMap.h>

#include <sstream>

#include "featloc/config/ConfigValues.h"

namespace featloc
{
IMPLEMENTS_MRPT_OBJECT(IcpMatcher, ScanMatcher, featloc)

namespace
{
/** Builds a planar point map, skipping points closer than `minDist` to the
 * previously kept one (the same decimation as MRPT's
 * minDistBetweenLaserPoints). */
void toPointsMap(
	const ScanPoints& pts, double minDist, mrpt::maps::CSimplePointsMap& map)
{
	map.clear();
	map.reserve(pts.size());
	const double minDist2 = minDist * minDist;
	double lastX = 0, lastY = 0;
	bool first = true;
	for (const auto& p : pts.points)
	{
		if (!first && minDist2 > 0)
		{
			const double dx = p.x - lastX, dy = p.y - lastY;
			if (dx * dx + dy * dy < minDist2) continue;
		}
		map.insertPoint(
			static_cast<float>(p.x), static_cast<float>(p.y), 0.0f);
		lastX = p.x;
		lastY = p.y;
		first = false;
	}
}
}  // namespace

void IcpMatcher::Parameters::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	readEnum(c, s, "algorithm", algorithm);
	readEnum(c, s, "covariance_method", covarianceMethod);
	read(c, s, "maxIterations", maxIterations);
	read(c, s, "minAbsStep_trans", minAbsStep_trans);
	readDegrees(c, s, "minAbsStep_rot_DEG", minAbsStep_rot);
	read(c, s, "thresholdDist", thresholdDist);
	readDegrees(c, s, "thresholdAng_DEG", thresholdAng);
	read(c, s, "ALFA", ALFA);
	read(c, s, "smallestThresholdDist", smallestThresholdDist);
	read(c, s, "onlyUniqueRobust", onlyUniqueRobust);
	read(c, s, "corresponding_points_decimation", corresponding_points_decimation);
	read(c, s, "covariance_varPoints", covariance_varPoints);
	read(c, s, "use_kernel", use_kernel);
	read(c, s, "kernel_rho", kernel_rho);
	read(c, s, "Axy_aprox_derivatives", Axy_aprox_derivatives);
	read(c, s, "LM_initial_lambda", LM_initial_lambda);
	read(c, s, "minDistBetweenPoints", minDistBetweenPoints);
	read(c, s, "minGoodness", minGoodness);

	require(maxIterations > 0, c, s, "maxIterations", "> 0");
	require(thresholdDist > 0, c, s, "thresholdDist", "> 0");
	require(ALFA > 0 && ALFA < 1, c, s, "ALFA", "in (0, 1)");
	require(
		smallestThresholdDist > 0 && smallestThresholdDist <= thresholdDist, c,
		s, "smallestThresholdDist", "in (0, thresholdDist]");
	require(
		corresponding_points_decimation >= 1, c, s,
		"corresponding_points_decimation", ">= 1");
	require(covariance_varPoints > 0, c, s, "covariance_varPoints", "> 0");
	require(minDistBetweenPoints >= 0, c, s, "minDistBetweenPoints", ">= 0");
	require(
		minGoodness >= 0 && minGoodness <= 1, c, s, "minGoodness",
		"in [0, 1]");
}

void IcpMatcher::Parameters::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	writeEnum(c, s, "algorithm", algorithm,
		"icpClassic | icpLevenbergMarquardt");
	writeEnum(c, s, "covariance_method", covarianceMethod,
		"icpCovFiniteDifferences | icpCovLinealMSE");
	write(c, s, "maxIterations", maxIterations,
		"iterations per threshold level");
	write(c, s, "minAbsStep_trans", minAbsStep_trans,
		"[m] stop when the translation step is below this");
	writeDegrees(c, s, "minAbsStep_rot_DEG", minAbsStep_rot,
		"[deg] stop when the rotation step is below this");
	write(c, s, "thresholdDist", thresholdDist,
		"[m] initial maximum distance of a point pair");
	writeDegrees(c, s, "thresholdAng_DEG", thresholdAng,
		"[deg] pairing distance grows by range*tan(this)");
	write(c, s, "ALFA", ALFA,
		"thresholds shrink by this factor at each convergence");
	write(c, s, "smallestThresholdDist", smallestThresholdDist,
		"[m] finest pairing distance (ICP stops there)");
	write(c, s, "onlyUniqueRobust", onlyUniqueRobust,
		"keep one pairing per reference point");
	write(c, s, "corresponding_points_decimation",
		corresponding_points_decimation,
		"pair only every N-th current point (1 = all)");
	write(c, s, "covariance_varPoints", covariance_varPoints,
		"[m^2] point noise variance scaling the covariance");
	write(c, s, "use_kernel", use_kernel, "Cauchy kernel in the covariance");
	write(c, s, "kernel_rho", kernel_rho, "[m] Cauchy kernel width");
	write(c, s, "Axy_aprox_derivatives", Axy_aprox_derivatives,
		"[m] LM only: step for numerical Jacobians");
	write(c, s, "LM_initial_lambda", LM_initial_lambda,
		"LM only: initial damping");
	write(c, s, "minDistBetweenPoints", minDistBetweenPoints,
		"[m] drop points closer than this to the previous one (0 = keep all)");
	write(c, s, "minGoodness", minGoodness,
		"match fails below this fraction of paired points [0-1]");
}

mrpt::slam::CICP::TConfigParams IcpMatcher::Parameters::toCICP() const
{
	mrpt::slam::CICP::TConfigParams o;
	o.ICP_algorithm = algorithm;
	o.ICP_covariance_method = covarianceMethod;
	o.maxIterations = maxIterations;
	o.minAbsStep_trans = minAbsStep_trans;
	o.minAbsStep_rot = minAbsStep_rot;
	o.thresholdDist = thresholdDist;
	o.thresholdAng = thresholdAng;
	o.ALFA = ALFA;
	o.smallestThresholdDist = smallestThresholdDist;
	o.onlyUniqueRobust = onlyUniqueRobust;
	o.corresponding_points_decimation = corresponding_points_decimation;
	o.covariance_varPoints = covariance_varPoints;
	o.use_kernel = use_kernel;
	o.kernel_rho = kernel_rho;
	o.Axy_aprox_derivatives = Axy_aprox_derivatives;
	o.LM_initial_lambda = LM_initial_lambda;
	o.doRANSAC = false;	 // keeps the output a single Gaussian
	o.skip_cov_calculation = false;
	return o;
}

void IcpMatcher::loadOwnParams(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section)
{
	params.loadFromConfigFile(cfg, section);
}

void IcpMatcher::saveOwnParams(
	mrpt::config::CConfigFileBase& cfg, const std::string& section) const
{
	params.saveToConfigFile(cfg, section);
}

void IcpMatcher::matchPoints(
	const ScanPoints& reference, const ScanPoints& current,
	const mrpt::poses::CPosePDFGaussian& initialGuess, MatchResult& result)
{
	mrpt::maps::CSimplePointsMap refMap, curMap;
	toPointsMap(reference, params.minDistBetweenPoints, refMap);
	toPointsMap(current, params.minDistBetweenPoints, curMap);

	mrpt::slam::CICP icp(params.toCICP());
	mrpt::slam::CICP::TReturnInfo info;
	const auto pdf = icp.AlignPDF(&refMap, &curMap, initialGuess, info);
	result.estimate.copyFrom(*pdf);
	result.iterations = info.nIterations;
	result.goodness = info.goodness;
	if (info.goodness < params.minGoodness)
	{
		std::ostringstream ss;
		ss << "only " << static_cast<int>(info.goodness * 100 + 0.5)
		   << "% of the points paired (minGoodness "
		   << static_cast<int>(params.minGoodness * 100 + 0.5) << "%)";
		result.success = false;
		result.failureReason = ss.str();
	}
	else
	{
		result.success = true;
	}
}

}  // namespace featloc
