#include "featloc/sim/LoopbackTcpServer.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <stdexcept>

namespace featloc
{
LoopbackTcpServer::LoopbackTcpServer(unsigned short port)
{
	m_fd = ::socket(AF_INET, SOCK_STREAM, 0);
	const int one = 1;
	::setsockopt(m_fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof(one));
	sockaddr_in a{};
	a.sin_family = AF_INET;
	a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
	a.sin_port = htons(port);
	if (m_fd < 0 || ::bind(m_fd, reinterpret_cast<sockaddr*>(&a), sizeof(a)) != 0 ||
		::listen(m_fd, 8) != 0)
	{
		const std::string why = std::strerror(errno);
		if (m_fd >= 0) ::close(m_fd);
		throw std::runtime_error(
			"cannot listen on 127.0.0.1:" + std::to_string(port) + ": " + why);
	}
}

LoopbackTcpServer::~LoopbackTcpServer() { ::close(m_fd); }

int LoopbackTcpServer::accept(int timeoutMs) const
{
	pollfd p{m_fd, POLLIN, 0};
	if (::poll(&p, 1, timeoutMs) <= 0) return -1;
	const int fd = ::accept(m_fd, nullptr, nullptr);
	if (fd < 0) return -1;
	const int one = 1;
	::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof(one));
	return fd;
}

bool LoopbackTcpServer::sendAll(int fd, const std::string& bytes, int timeoutMs)
{
	const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeoutMs);
	size_t done = 0;
	while (done < bytes.size())
	{
		const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
			deadline - std::chrono::steady_clock::now())
							  .count();
		pollfd p{fd, POLLOUT, 0};
		if (left <= 0 || ::poll(&p, 1, static_cast<int>(left)) <= 0) return false;
		if (p.revents & (POLLERR | POLLHUP | POLLNVAL)) return false;
		const ssize_t n = ::send(fd, bytes.data() + done, bytes.size() - done, MSG_NOSIGNAL);
		if (n < 0 && errno != EAGAIN && errno != EINTR) return false;
		if (n > 0) done += static_cast<size_t>(n);
	}
	return true;
}

long LoopbackTcpServer::receive(int fd, char* buffer, size_t size)
{
	const ssize_t n = ::recv(fd, buffer, size, MSG_DONTWAIT);
	if (n > 0) return n;
	if (n == 0) return -1;	// orderly close
	return (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) ? 0 : -1;
}

void LoopbackTcpServer::close(int fd)
{
	if (fd >= 0) ::close(fd);
}
}  // namespace featloc
