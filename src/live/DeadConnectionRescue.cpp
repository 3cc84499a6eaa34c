#include "featloc/live/DeadConnectionRescue.h"

#include <dirent.h>
#include <fcntl.h>
#include <linux/tcp.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <vector>

namespace featloc
{
namespace
{
constexpr int kTcpStateClose = 7;  // TCP_CLOSE in the kernel's tcp_states.h

bool deadConnection(int fd)
{
	struct stat st;
	if (::fstat(fd, &st) != 0 || !S_ISSOCK(st.st_mode)) return false;
	tcp_info info{};
	socklen_t len = sizeof(info);
	if (::getsockopt(fd, IPPROTO_TCP, TCP_INFO, &info, &len) != 0) return false;  // not TCP
	// A socket not yet connected is in CLOSE too, but has sent nothing.
	return info.tcpi_state == kTcpStateClose && info.tcpi_segs_out > 0;
}
}  // namespace

size_t DeadConnectionRescue::rescueAll()
{
	static std::mutex mutex;
	static std::vector<int> keptOpen;  // the pairs' other ends, see the header
	std::lock_guard<std::mutex> lock(mutex);
	std::vector<int> dead;
	if (DIR* dir = ::opendir("/proc/self/fd"))
	{
		while (const dirent* e = ::readdir(dir))
		{
			char* end = nullptr;
			const long fd = std::strtol(e->d_name, &end, 10);
			if (end != e->d_name && *end == '\0' && fd > 2 && fd != ::dirfd(dir) &&
				std::find(keptOpen.begin(), keptOpen.end(), fd) == keptOpen.end() &&
				deadConnection(static_cast<int>(fd)))
				dead.push_back(static_cast<int>(fd));
		}
		::closedir(dir);
	}
	size_t rescued = 0;
	for (int fd : dead)
	{
		int pair[2];
		if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, pair) != 0) break;
		::shutdown(pair[1], SHUT_WR);  // reads on pair[0] see end-of-file
		// The dead socket itself stays open under another number: an epoll
		// set the stuck write waits on (MRPT 2.5.8 waits with epoll) keeps
		// reporting it ready, so the write loop goes round once more and
		// now sends to the pair.
		const int old = ::fcntl(fd, F_DUPFD_CLOEXEC, 3);
		if (old >= 0 && ::dup2(pair[0], fd) >= 0)
		{
			rescued++;
			keptOpen.push_back(pair[1]);
			keptOpen.push_back(old);
		}
		else
		{
			::close(pair[1]);
			if (old >= 0) ::close(old);
		}
		::close(pair[0]);
	}
	return rescued;
}
}  // namespace featloc
