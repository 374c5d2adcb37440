package minigolf.online;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;

/** Every client message round-trips, and every way a field can be wrong is refused with its code and field. */
class ClientMessagesTest {
    @Test
    void everyMessageReadsBackAsWritten() throws ProtocolException {
        List<ClientMessage> all = List.of(
                new ClientMessage.Create("Ann", "meadowbrook-9", 4, List.of("planner", "straight"), false, 7),
                new ClientMessage.Join("ABCD2345", "Bob"),
                new ClientMessage.Resume("ABCD2345", "abcdefghijklmnopqrstu_"),
                new ClientMessage.Shot(12, 1.25, -0.5, 35, 2.5),
                new ClientMessage.Chat("nice shot"),
                new ClientMessage.Leave(), new ClientMessage.Ping(), new ClientMessage.Sync());
        for (ClientMessage m : all) assertEquals(m, ClientMessages.parse(ClientMessages.write(m)));
    }

    @Test
    void optionalFieldsTakeTheirDefaults() throws ProtocolException {
        ClientMessage.Create c = (ClientMessage.Create) ClientMessages.parse(
                "{\"type\":\"create\",\"protocol\":1,\"name\":\" Ann \",\"course\":\"lake\",\"seats\":2}");
        assertEquals(new ClientMessage.Create("Ann", "lake", 2, List.of(), true, 10), c);
        assertEquals(new ClientMessage.Shot(3, 1, 2, 0, 0), ClientMessages.parse("{\"type\":\"shot\",\"seq\":3,\"velocity\":[1,2]}"));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
            "not json|bad-message|not valid JSON",
            "[1,2]|bad-message|one JSON object",
            "{\"seq\":1}|bad-field|type: is missing",
            "{\"type\":\"dance\"}|bad-message|unknown message type \"dance\"",
            "{\"type\":\"ping\",\"x\":1}|bad-field|\"x\": unknown field",
            "{\"type\":\"ping\",\"type\":\"ping\"}|bad-message|Duplicate field",
            "{\"type\":\"join\",\"protocol\":2,\"room\":\"ABCD2345\",\"name\":\"A\"}|version|speaks protocol 1, the client 2",
            "{\"type\":\"join\",\"protocol\":1,\"room\":\"abcd2345\",\"name\":\"A\"}|bad-field|room: must be a room code",
            "{\"type\":\"join\",\"protocol\":1,\"room\":\"ABCD2345\",\"name\":\"   \"}|bad-field|name: is empty",
            "{\"type\":\"join\",\"protocol\":1,\"room\":\"ABCD2345\",\"name\":\"A\\u0007\"}|bad-field|name: must not hold control",
            "{\"type\":\"join\",\"protocol\":1,\"room\":\"ABCD2345\",\"name\":\"0123456789012345678901234\"}|bad-field|name: is longer than 24",
            "{\"type\":\"join\",\"protocol\":1,\"room\":\"ABCD2345\",\"name\":7}|bad-field|name: must be a string",
            "{\"type\":\"resume\",\"protocol\":1,\"room\":\"ABCD2345\",\"token\":\"short\"}|bad-field|token: must be a seat token",
            "{\"type\":\"create\",\"protocol\":1,\"name\":\"A\",\"course\":\"../etc/passwd\",\"seats\":2}|bad-field|course: must be a course",
            "{\"type\":\"create\",\"protocol\":1,\"name\":\"A\",\"course\":\"lake\",\"seats\":5}|bad-field|seats: must be 1 to 4",
            "{\"type\":\"create\",\"protocol\":1,\"name\":\"A\",\"course\":\"lake\",\"seats\":2.5}|bad-field|seats: must be a whole number",
            "{\"type\":\"create\",\"protocol\":1,\"name\":\"A\",\"course\":\"lake\",\"seats\":2,\"bots\":[\"a\",\"b\"]}|bad-field|bots: must be a list of at most",
            "{\"type\":\"create\",\"protocol\":1,\"name\":\"A\",\"course\":\"lake\",\"seats\":2,\"strokeLimit\":0}|bad-field|strokeLimit: must be 1 to 99",
            "{\"type\":\"shot\",\"seq\":-1,\"velocity\":[1,0]}|bad-field|seq: must be 0 to",
            "{\"type\":\"shot\",\"seq\":0,\"velocity\":[1]}|bad-field|velocity: must be an array of 2",
            "{\"type\":\"shot\",\"seq\":0,\"velocity\":[1,\"x\"]}|bad-field|velocity[1]: must be a finite number",
            "{\"type\":\"shot\",\"seq\":0,\"velocity\":[1e999,0]}|bad-field|velocity[0]: must be a finite number",
            "{\"type\":\"shot\",\"seq\":0,\"velocity\":[1,0],\"loft\":61}|bad-field|loft: must be 0.0 to 60.0",
            "{\"type\":\"shot\",\"seq\":0,\"velocity\":[1,0],\"wait\":-0.5}|bad-field|wait: must be 0.0 to 30.0",
            "{\"type\":\"shot\",\"seq\":0,\"velocity\":[1,0],\"wait\":NaN}|bad-message|not valid JSON",
            "{\"type\":\"chat\",\"text\":\"  \"}|bad-field|text: is empty",
    })
    void aBadMessageIsRefusedNamingItsField(String text, String code, String message) {
        ProtocolException e = assertThrows(ProtocolException.class, () -> ClientMessages.parse(text));
        assertEquals(code, e.code(), e.getMessage());
        assertTrue(e.getMessage().contains(message), e.getMessage());
    }

    @Test
    void oversizedAndDeeplyNestedMessagesAreRefused() {
        String big = "{\"type\":\"chat\",\"text\":\"" + "x".repeat(Protocol.MAX_MESSAGE_BYTES) + "\"}";
        assertEquals("too-large", assertThrows(ProtocolException.class, () -> ClientMessages.parse(big)).code());
        // 2,000 characters of 3-byte UTF-8 exceed the byte limit though the text is short.
        String wide = "{\"type\":\"chat\",\"text\":\"" + "\u20ac".repeat(1400) + "\"}";
        assertEquals("too-large", assertThrows(ProtocolException.class, () -> ClientMessages.parse(wide)).code());
        String deep = "{\"type\":\"ping\",\"x\":" + "[".repeat(1000) + "]".repeat(1000) + "}";
        assertEquals("bad-message", assertThrows(ProtocolException.class, () -> ClientMessages.parse(deep)).code());
        String longChat = "{\"type\":\"chat\",\"text\":\"" + "y".repeat(Protocol.MAX_CHAT_CHARS + 1) + "\"}";
        assertTrue(assertThrows(ProtocolException.class, () -> ClientMessages.parse(longChat)).getMessage()
                .contains("longer than 200"));
    }
}
