#include "MatcherTestHelpers.h"

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include "featloc/matchers/ScanMatcherFactory.h"
#include "featloc/math/CovarianceFromUpperTriangle.h"
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
	// Either format: two observations (rawlog format #2), or rawlog-edit
	// --cut of a format #1 log, whose scans sit in sensory frames between
	// action collections.
	std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> scans;
	while (scans.size() < 2)
	{
		const auto obj = ar.ReadObject();
		if (auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obj))
			scans.push_back(scan);
		else if (auto frame = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj))
			if (auto inFrame = frame->getObservationByClass<mrpt::obs::CObservation2DRangeScan>())
				scans.push_back(inFrame);
	}
	reference = *scans[0];
	current = *scans[1];
}

mrpt::poses::CPosePDFGaussian guessFromMatchTable(
	const mrpt::poses::CPose2D& mean, const std::array<double, 6>& g)
{
	return mrpt::poses::CPosePDFGaussian(mean, covarianceFromUpperTriangle(g.data()));
}
}  // namespace featloc::test
