package minigolf;
import org.junit.jupiter.api.Test;
import static org.junit.jupiter.api.Assertions.*;
class SmokeTest { @Test void one(){ assertEquals(2, 1+1); } }
