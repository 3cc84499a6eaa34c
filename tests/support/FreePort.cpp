#include "FreePort.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace featloc::test
{
unsigned short freePort()
{
	const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
	sockaddr_in a{};
	a.sin_family = AF_INET;
	a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
	a.sin_port = 0;
	socklen_t len = sizeof(a);
	::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof(a));
	::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len);
	::close(fd);
	return ntohs(a.sin_port);
}
}  // namespace featloc::test
