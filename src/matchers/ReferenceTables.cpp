#include "featloc/matchers/ReferenceTables.h"

namespace featloc
{
namespace
{
bool sameWindow(const CorrelationTables::Window& a, const CorrelationTables::Window& b)
{
	return a.centre.x() == b.centre.x() && a.centre.y() == b.centre.y() &&
		a.centre.phi() == b.centre.phi() && a.nx == b.nx && a.ny == b.ny && a.nYaw == b.nYaw &&
		a.yawStep == b.yawStep;
}
}  // namespace

bool ReferenceTables::builtFor(
	const ScanPoints& reference, int top, const BuildOptions& options) const
{
	return m_top >= 0 && m_top == top && m_options == options && m_reference.samePointsAs(reference);
}

void ReferenceTables::setBuiltFor(
	const ScanPoints& reference, int top, const BuildOptions& options)
{
	m_reference = reference;
	m_top = top;
	m_options = options;
	m_hasSearch = false;
}

const std::vector<CorrelationTables::Candidate>* ReferenceTables::lastSearch(
	const std::vector<double>& px, const std::vector<double>& py,
	const CorrelationTables::Window& w, double keepRatio) const
{
	if (!m_hasSearch || keepRatio != m_keepRatio || !sameWindow(w, m_window) || px != m_px ||
		py != m_py)
		return nullptr;
	return &m_found;
}

void ReferenceTables::rememberSearch(const std::vector<double>& px,
	const std::vector<double>& py, const CorrelationTables::Window& w, double keepRatio,
	const std::vector<CorrelationTables::Candidate>& found)
{
	m_px = px;
	m_py = py;
	m_window = w;
	m_keepRatio = keepRatio;
	m_found = found;
	m_hasSearch = true;
}
}  // namespace featloc
