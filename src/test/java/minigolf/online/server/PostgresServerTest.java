package minigolf.online.server;

import static org.junit.jupiter.api.Assumptions.assumeTrue;

import org.junit.jupiter.api.Test;

/** The server on a real PostgreSQL (CI's .ci/online.sh starts one): a room survives a restart as on SQLite. */
class PostgresServerTest {
    @Test
    void aRoomSurvivesARestartOnPostgresql() throws Exception {
        String url = System.getenv("MINIGOLF_TEST_POSTGRES_URL");
        assumeTrue(url != null && !url.isBlank(), "MINIGOLF_TEST_POSTGRES_URL is not set (CI's .ci/online.sh sets it)");
        DroppedPlayerTest.restartRestoresTheRoom(url, 1);
    }
}
