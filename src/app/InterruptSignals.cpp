#include "featloc/app/InterruptSignals.h"

#include <csignal>

namespace featloc
{
namespace
{
std::atomic<bool> g_stop{false};
struct sigaction g_oldInt, g_oldTerm;

void onSignal(int sig)
{
	if (g_stop.load())
	{
		// Second signal: the user insists; die as the signal says.
		std::signal(sig, SIG_DFL);
		std::raise(sig);
		return;
	}
	g_stop.store(true);
}
}  // namespace

InterruptSignals::InterruptSignals()
{
	g_stop.store(false);
	struct sigaction sa = {};
	sa.sa_handler = onSignal;
	sigemptyset(&sa.sa_mask);
	sigaction(SIGINT, &sa, &g_oldInt);
	sigaction(SIGTERM, &sa, &g_oldTerm);
}

InterruptSignals::~InterruptSignals()
{
	sigaction(SIGINT, &g_oldInt, nullptr);
	sigaction(SIGTERM, &g_oldTerm, nullptr);
}

const std::atomic<bool>& InterruptSignals::flag() const { return g_stop; }
}  // namespace featloc
