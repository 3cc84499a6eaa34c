#include "MatcherTestHelpers.h"

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/serialization/CArchive.h>

#include "featloc/matchers/ScanMatcherFactory.h"
#include "featloc/registerClasses.h"

namespace featloc::test
{
ScanMatcher::Ptr configuredMatcher(const std::string& cls, const std::string& overrides)
{
	registerClasses();
	auto m = ScanMatcherFactory::create(cls);
	mrpt::config::CConfigFileMemory cfg;
	cfg.setContent("[S]\n" + overrides + "\n");
	m->loadParams(cfg, "S");
	return m;
}

mrpt::obs::CObservation2DRangeScan::Ptr withRangeNoise(
	mrpt::obs::CObservation2DRangeScan::Ptr s, mrpt::random::CRandomGenerator& rng, double sigma)
{
	for (size_t i = 0; i < s->getScanSize(); i++)
		if (s->getScanRangeValidity(i))
			s->setScanRange(
				i, s->getScanRange(i) + static_cast<float>(sigma * rng.drawGaussian1D_normalized()));
	return s;
}

void readScanPair(const std::string& file, mrpt::obs::CObservation2DRangeScan& reference,
	mrpt::obs::CObservation2DRangeScan& current)
{
	mrpt::io::CFileGZInputStream in(std::string(FEATLOC_SOURCE_DIR) + "/tests/data/" + file);
	auto ar = mrpt::serialization::archiveFrom(in);
	ar >> reference >> current;
}

mrpt::poses::CPosePDFGaussian guessFromMatchTable(
	const mrpt::poses::CPose2D& mean, const std::array<double, 6>& g)
{
	mrpt::math::CMatrixDouble33 P;
	P(0, 0) = g[0];
	P(0, 1) = P(1, 0) = g[1];
	P(0, 2) = P(2, 0) = g[2];
	P(1, 1) = g[3];
	P(1, 2) = P(2, 1) = g[4];
	P(2, 2) = g[5];
	return mrpt::poses::CPosePDFGaussian(mean, P);
}
}  // namespace featloc::test
